// An orbit camera for the 3D view: it looks at a target point from a distance, at a
// yaw angle about the world's y axis (up) and a pitch angle above the horizon.
//
// Glossary
//   target_W   the point the camera orbits and looks at             [m]
//   eye_W      camera position, target_W + distance * back(yaw, pitch) [m]
//   yaw        angle about +y, 0 looks from +z towards -z            [deg]
//   pitch      elevation above the x-z plane, |pitch| <= 90          [deg]
//   fovY       vertical field of view                                [deg]
//   ndc        normalised device coordinates, x right, y up, in [-1, 1]
//
// Column vectors, OpenGL conventions: clip = P V p, the camera looks along -z in
// its own frame. Plain Eigen (double) so that picking and projection are exact; the
// renderer converts to float only for the GPU.
#pragma once

#include "physics/engine/math_types.h"

#include <Eigen/Core>

namespace rbw {

// A ray p(t) = origin_W + t dir_W, t >= 0, dir_W unit.
struct Ray {
    Vec3 origin_W = Vec3::Zero();
    Vec3 dir_W = -Vec3::UnitZ();
};

// The standard views (keys 1-3). The world's up is +y (gravity (0, -g, 0)); each
// view is named after where the eye is and what the screen's right and up are:
//   Front  seen from +z, looking along -z: +x right, +y up (lesson 7's "seen from +z")
//   Top    seen from +y, looking along -y: +x right, -z up
//   Side   seen from +x, looking along -x: -z right, +y up
enum class StandardView { Front, Top, Side };

class OrbitCamera {
public:
    using Mat4 = Eigen::Matrix4d;

    // Where resetView() goes: slightly above the scene, looking down at it.
    static constexpr double kDefaultYawDeg = 35.0;
    static constexpr double kDefaultPitchDeg = 22.0;
    static constexpr double kFovYDeg = 40.0;

    Vec3 target() const { return target_W_; }
    double distance() const { return distance_; }
    double yawDeg() const { return yawDeg_; }
    double pitchDeg() const { return pitchDeg_; }
    double fovYDeg() const { return kFovYDeg; }

    void setTarget(const Vec3& target_W) { target_W_ = target_W; }
    void setDistance(double d);
    void setAngles(double yawDeg, double pitchDeg);

    Vec3 eye() const;
    Vec3 forward() const;   // unit, from the eye towards the target
    Vec3 right() const;     // unit, screen right
    Vec3 up() const;        // unit, screen up

    Mat4 viewMatrix() const;                        // V: world -> camera
    Mat4 projectionMatrix(double aspect) const;     // P: perspective, aspect = width/height

    // Sets the angles of a standard view; keeps the target and distance.
    void setStandardView(StandardView v);

    // Mouse gestures, in widget pixels.
    void orbit(double dxPx, double dyPx);
    void pan(double dxPx, double dyPx, double viewportHeightPx);
    void zoom(double wheelSteps);   // > 0 moves closer

    // Puts the target at centre_W and backs off until a sphere of this radius fits
    // the view in both directions. Keeps the angles.
    void frame(const Vec3& centre_W, double radius, double aspect);

    // The ray from the eye through a point given in ndc.
    Ray rayThroughNdc(double ndcX, double ndcY, double aspect) const;

private:
    Vec3 target_W_ = Vec3::Zero();
    double distance_ = 6.0;
    double yawDeg_ = kDefaultYawDeg;
    double pitchDeg_ = kDefaultPitchDeg;
};

} // namespace rbw
