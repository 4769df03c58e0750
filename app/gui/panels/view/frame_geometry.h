// Turns a snapshot (plus the motion trails the view keeps) into the vertex arrays of
// one frame: lit triangles (boxes, arrows, balls), lines (edges, body axes, trails,
// the spring) and plane patches. Plain CPU code, so it can be tested without GL.
//
// Arrow lengths: each kind has its own display scale, chosen so that the longest
// arrow of that kind is drawn one reference length long, where the reference length
// is the mean of the bodies' longest edges (arrowScale in view_style.h). The legend
// prints the magnitude that this length stands for.
#pragma once

#include "app/gui/panels/view/mesh_primitives.h"
#include "app/gui/panels/view/view_snapshot.h"

#include <limits>
#include <string>
#include <vector>

namespace rbw::view {

struct Bounds {
    Vec3 min_W = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 max_W = Vec3::Constant(-std::numeric_limits<double>::infinity());

    bool valid() const { return (min_W.array() <= max_W.array()).all(); }
    void add(const Vec3& p_W)
    {
        if (!isFinite(p_W)) return;
        min_W = min_W.cwiseMin(p_W);
        max_W = max_W.cwiseMax(p_W);
    }
    void add(const Bounds& b)
    {
        if (b.valid()) {
            add(b.min_W);
            add(b.max_W);
        }
    }
};

// The world AABB of all finite bodies' corners (planes are infinite and ignored).
Bounds bodyBounds(const ViewSnapshot& snap);

// The smallest finite body's longest edge; 1 m when there are none.
double referenceLength(const ViewSnapshot& snap);

struct FrameOptions {
    Vec3 eye_W = Vec3(0, 0, 10);   // decides which side of a plane faces the camera
    Bounds sceneBox;               // where plane patches end
    bool trails = true;
    int highlightBody = -1;        // the grabbed body, drawn lighter
    // The state arrows at each movable body's centre (View menu toggles).
    bool velocity = false;         // v
    bool angularVelocity = false;  // ω
    bool angularMomentum = false;  // L (drawn translucent and wider, so ω shows inside it)
    bool worldReference = true;    // the world axes at the origin and the ground grid (scenes with bodies)
};

// A text the view writes next to a point of the scene (an axis tip).
struct SceneLabel {
    enum class Kind { WorldAxis, BodyAxis };
    Kind kind = Kind::WorldAxis;
    int body = -1;        // the body of a body axis
    int axis = 0;         // 0, 1, 2: x, y, z
    Vec3 at_W = Vec3::Zero();
    std::string text;     // UTF-8
};

// The world reference: axes x, y, z from the origin and a square grid in a
// horizontal plane y = y0 (the world's up is +y), under the bodies.
struct WorldReference {
    bool shown = false;
    double axisLength = 0.0;   // m
    double spacing = 0.0;      // m between grid lines (1, 2 or 5 times a power of ten)
    double y0 = 0.0;           // m: 0, or lower when a body reaches below y = 0
    Vec3 min_W = Vec3::Zero();   // the grid's corners (min_W.y() = max_W.y() = y0)
    Vec3 max_W = Vec3::Zero();
    int lineCount = 0;
};

// The body axes are drawn as thin arrows this far beyond each face, as a fraction
// of the body's longest edge, and the world axes this many reference lengths long.
inline constexpr double kBodyAxisPoke = 0.35;
inline constexpr double kWorldAxisLength = 1.5;
// Body axes are labelled x_B, y_B, z_B when a scene has at most this many bodies.
inline constexpr int kMaxLabelledBodies = 4;

// Every arrow of a frame, for the legend and the tests: what it shows and where it
// is drawn from and to (the head at `to_W`).
enum class ArrowKind {
    Force,            // f_i at p_i, acting in the next step
    ForceDone,        // f_i of the step just taken that does not act again (faded)
    Gravity,          // M g, drawn ending at x
    Torque,           // a couple q_j of the step just taken, at x
    ProbeVelocity,    // v_p at the probe point
    Normal,           // the unit normal n, from p into A
    NormalImpulse,    // J n on A, ending at p
    FrictionImpulse,  // J_t t on A, ending at p
    TotalImpulse,     // J n + J_t t on A, ending at p
    Velocity,         // v at x
    AngularVelocity,  // ω at x
    AngularMomentum,  // L at x
};
struct ArrowRecord {
    ArrowKind kind;
    int body = -1;      // the body it belongs to (A for a contact)
    int index = -1;     // force, probe or contact number
    Vec3 from_W = Vec3::Zero();
    Vec3 to_W = Vec3::Zero();
    Vec3 value = Vec3::Zero();   // the vector it shows, in its unit (unscaled)
};

// What each kind of arrow's full reference length stands for (0: none drawn).
struct ArrowScales {
    double refLength = 1.0;       // m on screen
    double maxForce = 0.0;        // N   (applied forces and gravity share one scale)
    double maxTorque = 0.0;       // N m (couples q_j)
    double maxVelocity = 0.0;     // m/s (probe velocities)
    double maxImpulse = 0.0;      // N s (J n, J_t t and their sum share one scale)
    double maxBodyVelocity = 0.0;   // m/s (v at x)
    double maxOmega = 0.0;          // rad/s
    double maxL = 0.0;              // N m s
    bool hasGravity = false;
    bool hasApplied = false;
    bool hasAppliedDone = false;
    bool hasTorque = false;
    bool hasProbes = false;
    bool hasContacts = false;
    bool hasFriction = false;
    bool hasSpring = false;
    bool hasVelocity = false;
    bool hasOmega = false;
    bool hasL = false;
};

struct FrameGeometry {
    std::vector<LitVertex> lit;       // the boxes
    std::vector<LitVertex> overlay;   // arrows and markers: also shown, faintly, through boxes
    std::vector<LineVertex> lines;
    std::vector<PlaneVertex> planes;   // triangles, farthest plane first
    ArrowScales scales;
    std::vector<ArrowRecord> arrows;
    std::vector<SceneLabel> labels;   // axis names at the axis tips
    WorldReference world;
};

// A spacing of 1, 2 or 5 times a power of ten, near extent / 10 (at least 1 mm).
double niceGridSpacing(double extent);

FrameGeometry buildFrameGeometry(const ViewSnapshot& snap, const std::vector<std::vector<Vec3>>& trails,
                                 const FrameOptions& options);

} // namespace rbw::view
