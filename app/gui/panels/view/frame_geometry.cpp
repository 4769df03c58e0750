#include "app/gui/panels/view/frame_geometry.h"

#include "app/gui/panels/view/plane_patch.h"

#include <algorithm>
#include <cmath>

namespace rbw::view {

namespace {

Rgba lighter(Rgba c, float t)
{
    return Rgba{c.r + (1.f - c.r) * t, c.g + (1.f - c.g) * t, c.b + (1.f - c.b) * t, c.a};
}

void appendPlane(std::vector<PlaneVertex>& out, const std::vector<Vec3>& polygon, const ViewSnapshot::Plane& plane,
                 float alpha)
{
    Vec3 u_W;
    Vec3 v_W;
    planeAxes(plane.n_W.normalized(), u_W, v_W);
    auto vertex = [&](const Vec3& p) {
        // (u, v): coordinates in the plane, measured from the plane's point.
        const Vec3 d = p - plane.point_W;
        return PlaneVertex{{float(p.x()), float(p.y()), float(p.z())},
                           {float(d.dot(u_W)), float(d.dot(v_W))},
                           {kPlane.r, kPlane.g, kPlane.b, alpha}};
    };
    // A convex polygon as a triangle fan.
    for (size_t k = 1; k + 1 < polygon.size(); ++k) {
        out.push_back(vertex(polygon[0]));
        out.push_back(vertex(polygon[k]));
        out.push_back(vertex(polygon[k + 1]));
    }
}

const char* const kAxisNames[3] = {"x", "y", "z"};

// The world axes at the origin (opaque, depth-tested: a box hides the part inside
// it) and a light grid at y = y0 below the bodies, spanning the scene box and the origin.
void appendWorldReference(FrameGeometry& g, const ViewSnapshot& snap, const FrameOptions& options, double ref)
{
    WorldReference& w = g.world;
    w.shown = true;
    w.axisLength = kWorldAxisLength * ref;
    const Rgba axisColour[3] = {kAxisX, kAxisY, kAxisZ};
    for (int j = 0; j < 3; ++j) {
        const Vec3 e = Vec3::Unit(j);
        appendArrow(g.lit, Vec3::Zero(), w.axisLength * e, 0.018 * ref, axisColour[j]);
        g.labels.push_back(SceneLabel{SceneLabel::Kind::WorldAxis, -1, j, (w.axisLength + 0.12 * ref) * e, kAxisNames[j]});
    }

    Bounds area;
    area.add(Vec3::Zero());
    area.add(bodyBounds(snap));
    area.add(options.sceneBox);
    w.spacing = niceGridSpacing(std::max(area.max_W.x() - area.min_W.x(), area.max_W.z() - area.min_W.z()));
    const Bounds bodies = bodyBounds(snap);
    // The first grid line at or below the lowest body point; the 1e-9 keeps a box
    // whose bottom is on a grid line up to round-off (cos 90° = 6e-17) on that line.
    w.y0 = (bodies.valid() && bodies.min_W.y() < 0.0) ? std::floor(bodies.min_W.y() / w.spacing + 1e-9) * w.spacing : 0.0;
    // Whole cells, one spare cell on each side.
    const double x0 = (std::floor(area.min_W.x() / w.spacing) - 1.0) * w.spacing;
    const double x1 = (std::ceil(area.max_W.x() / w.spacing) + 1.0) * w.spacing;
    const double z0 = (std::floor(area.min_W.z() / w.spacing) - 1.0) * w.spacing;
    const double z1 = (std::ceil(area.max_W.z() / w.spacing) + 1.0) * w.spacing;
    w.min_W = Vec3(x0, w.y0, z0);
    w.max_W = Vec3(x1, w.y0, z1);
    const int nx = static_cast<int>(std::lround((x1 - x0) / w.spacing));
    const int nz = static_cast<int>(std::lround((z1 - z0) / w.spacing));
    if (nx > 400 || nz > 400) return;   // a scene box gone huge (a blow-up): no grid
    for (int i = 0; i <= nx; ++i) {
        const double x = x0 + i * w.spacing;
        appendLine(g.lines, Vec3(x, w.y0, z0), Vec3(x, w.y0, z1), kGrid);
    }
    for (int k = 0; k <= nz; ++k) {
        const double z = z0 + k * w.spacing;
        appendLine(g.lines, Vec3(x0, w.y0, z), Vec3(x1, w.y0, z), kGrid);
    }
    w.lineCount = nx + nz + 2;
}

} // namespace

double niceGridSpacing(double extent)
{
    if (!std::isfinite(extent) || extent <= 0.0) return 1.0;
    const double target = std::max(extent / 10.0, 1e-3);
    const double decade = std::pow(10.0, std::floor(std::log10(target)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (m * decade >= target) return m * decade;
    }
    return 10.0 * decade;
}

Bounds bodyBounds(const ViewSnapshot& snap)
{
    Bounds b;
    for (const ViewSnapshot::Body& body : snap.bodies) {
        if (!body.finite) continue;
        // Half extent of an oriented box along world axis i: sum_j |R_ij| h_j.
        const Vec3 e_W = body.R_WB.cwiseAbs() * (0.5 * body.size);
        b.add(body.x_W - e_W);
        b.add(body.x_W + e_W);
    }
    return b;
}

double referenceLength(const ViewSnapshot& snap)
{
    // The smallest box's longest edge: the longest arrow of a kind is no longer than the
    // smallest box, so no box is dwarfed by its arrows (lesson 7's 1 × 2 × 1 boxes
    // beside the 6 m cuboids had gravity arrows longer than themselves with the mean).
    double smallest = 0.0;
    for (const ViewSnapshot::Body& body : snap.bodies) {
        if (!body.finite) continue;
        const double edge = body.size.maxCoeff();
        if (smallest == 0.0 || edge < smallest) smallest = edge;
    }
    return smallest > 0.0 ? smallest : 1.0;
}

FrameGeometry buildFrameGeometry(const ViewSnapshot& snap, const std::vector<std::vector<Vec3>>& trails,
                                 const FrameOptions& options)
{
    FrameGeometry g;
    const double ref = referenceLength(snap);
    ArrowScales& s = g.scales;
    s.refLength = ref;
    g.lit.reserve(snap.bodies.size() * 36);
    g.lines.reserve(snap.bodies.size() * 30);

    // Bodies: shaded box, dark outline, and the body axes x (red), y (green), z (blue)
    // as thin arrows from the centre to well beyond each face. They are overlay
    // geometry, so the part inside the box shows through it (the x-ray pass).
    const bool labelBodies = static_cast<int>(snap.bodies.size()) <= kMaxLabelledBodies;
    for (int b = 0; b < static_cast<int>(snap.bodies.size()); ++b) {
        const ViewSnapshot::Body& body = snap.bodies[b];
        if (!body.finite) continue;
        Rgba colour = bodyColour(b, body.fixed, body.name);
        if (b == options.highlightBody) colour = lighter(colour, 0.35f);
        appendBox(g.lit, body.x_W, body.R_WB, body.size, colour);
        appendBoxEdges(g.lines, body.x_W, body.R_WB, body.size, kEdge);
        const double poke = kBodyAxisPoke * body.size.maxCoeff();
        const Rgba axisColour[3] = {kAxisX, kAxisY, kAxisZ};
        for (int j = 0; j < 3; ++j) {
            const Vec3 tip_W = body.x_W + (0.5 * body.size[j] + poke) * body.R_WB.col(j);
            appendArrow(g.overlay, body.x_W, tip_W - body.x_W, 0.012 * ref, axisColour[j]);
            if (labelBodies) {
                g.labels.push_back(SceneLabel{SceneLabel::Kind::BodyAxis, b, j,
                                              tip_W + 0.08 * body.size.maxCoeff() * body.R_WB.col(j),
                                              std::string(kAxisNames[j]) + "_B"});
            }
        }
    }
    // The world reference locates bodies; a scene without bodies stays blank.
    if (options.worldReference && !snap.bodies.empty()) appendWorldReference(g, snap, options, ref);

    // Motion trails of the centres of mass.
    if (options.trails) {
        for (int b = 0; b < static_cast<int>(trails.size()) && b < static_cast<int>(snap.bodies.size()); ++b) {
            const Rgba colour = lighter(bodyColour(b, snap.bodies[b].fixed, snap.bodies[b].name), 0.25f);
            for (size_t k = 1; k < trails[b].size(); ++k) appendLine(g.lines, trails[b][k - 1], trails[b][k], colour);
        }
    }

    const double shaft = 0.022 * ref;
    // Arrows drawn translucent go last, so what lies inside them is already drawn.
    std::vector<LitVertex> translucent;
    auto arrow = [&](std::vector<LitVertex>& out, ArrowKind kind, int body, int index, const Vec3& from,
                     const Vec3& to, const Vec3& value, double radius, Rgba colour) {
        if (!isFinite(from) || !isFinite(to) || (to - from).norm() <= 0.0) return;
        appendArrow(out, from, to - from, radius, colour);
        g.arrows.push_back(ArrowRecord{kind, body, index, from, to, value});
    };

    // Forces: f_i from p_i, and M g ending at x; one scale for both (they share the
    // unit N). Gravity ends at x so that it never lies on the contact arrows below a
    // body; a force of the step just taken that does not act again is faded.
    for (const ViewSnapshot::Force& f : snap.forces) {
        s.maxForce = std::max(s.maxForce, f.f_W.norm());
        if (f.kind == ViewSnapshot::ForceKind::Gravity) {
            s.hasGravity = true;
        } else {
            (f.upcoming ? s.hasApplied : s.hasAppliedDone) = true;
        }
    }
    const double forceScale = arrowScale(s.maxForce, ref);
    for (const ViewSnapshot::Force& f : snap.forces) {
        const Vec3 d = forceScale * f.f_W;
        if (f.kind == ViewSnapshot::ForceKind::Gravity) {
            arrow(g.overlay, ArrowKind::Gravity, f.body, f.index, f.origin_W - d, f.origin_W, f.f_W, shaft, kGravity);
        } else if (f.upcoming) {
            arrow(g.overlay, ArrowKind::Force, f.body, f.index, f.origin_W, f.origin_W + d, f.f_W, shaft, kForce);
        } else {
            arrow(translucent, ArrowKind::ForceDone, f.body, f.index, f.origin_W, f.origin_W + d, f.f_W, shaft,
                  kForceDone);
        }
    }

    // Torques (couples q_j): at the centre of mass x, with their own scale (N m).
    for (const ViewSnapshot::Torque& t : snap.torques) {
        if (t.q_W.norm() <= 0.0 || t.body < 0 || t.body >= static_cast<int>(snap.bodies.size())) continue;
        s.maxTorque = std::max(s.maxTorque, t.q_W.norm());
        s.hasTorque = true;
    }
    const double torqueScale = arrowScale(s.maxTorque, ref);
    for (const ViewSnapshot::Torque& t : snap.torques) {
        if (t.body < 0 || t.body >= static_cast<int>(snap.bodies.size())) continue;
        const Vec3& x_W = snap.bodies[t.body].x_W;
        arrow(g.overlay, ArrowKind::Torque, t.body, t.index, x_W, x_W + torqueScale * t.q_W, t.q_W, 1.2 * shaft, kTorque);
    }

    // Probes: the point and its velocity v_p.
    for (const ViewSnapshot::Probe& p : snap.probes) {
        s.maxVelocity = std::max(s.maxVelocity, p.v_W.norm());
        s.hasProbes = true;
    }
    const double velocityScale = arrowScale(s.maxVelocity, ref);
    for (const ViewSnapshot::Probe& p : snap.probes) {
        appendBall(g.overlay, p.p_W, 0.05 * ref, kProbe);
        arrow(g.overlay, ArrowKind::ProbeVelocity, p.body, p.index, p.p_W, p.p_W + velocityScale * p.v_W, p.v_W, shaft,
              kProbe);
    }

    // Contacts: the point; the unit normal n from p into A (half the reference
    // length, thin); the impulses on A ending at p, so they lie on the other side
    // of p and never on the normal: J n, the friction impulse J_t t and their sum.
    for (const ViewSnapshot::Contact& c : snap.contacts) {
        s.maxImpulse = std::max({s.maxImpulse, c.impulse_W.norm(), c.friction_W.norm(), c.total_W.norm()});
        s.hasContacts = true;
        s.hasFriction = s.hasFriction || c.friction_W.norm() > 0.0;
    }
    const double impulseScale = arrowScale(s.maxImpulse, ref);
    for (const ViewSnapshot::Contact& c : snap.contacts) {
        appendBall(g.overlay, c.p_W, 0.055 * ref, kContact);
        const Vec3 n = c.n_W.normalized();
        arrow(g.overlay, ArrowKind::Normal, c.bodyA, c.index, c.p_W, c.p_W + 0.5 * ref * n, n, 0.6 * shaft, kContact);
        arrow(g.overlay, ArrowKind::NormalImpulse, c.bodyA, c.index, c.p_W - impulseScale * c.impulse_W, c.p_W,
              c.impulse_W, 1.1 * shaft, kImpulse);
        if (c.friction_W.norm() > 0.0) {
            arrow(g.overlay, ArrowKind::FrictionImpulse, c.bodyA, c.index, c.p_W - impulseScale * c.friction_W, c.p_W,
                  c.friction_W, 0.9 * shaft, kFriction);
            arrow(translucent, ArrowKind::TotalImpulse, c.bodyA, c.index, c.p_W - impulseScale * c.total_W, c.p_W,
                  c.total_W, 1.6 * shaft, kTotalImpulse);
        }
    }

    // The state: v, ω and L at each movable body's centre, each kind with its own scale.
    auto shown = [](const Vec3& v) { return v.norm() > kNegligibleMagnitude; };
    for (const ViewSnapshot::Body& body : snap.bodies) {
        if (!body.finite || body.fixed) continue;
        if (shown(body.v_W)) s.maxBodyVelocity = std::max(s.maxBodyVelocity, body.v_W.norm());
        if (shown(body.omega_W)) s.maxOmega = std::max(s.maxOmega, body.omega_W.norm());
        if (shown(body.L_W)) s.maxL = std::max(s.maxL, body.L_W.norm());
    }
    const double vScale = arrowScale(s.maxBodyVelocity, ref);
    const double omegaScale = arrowScale(s.maxOmega, ref);
    const double lScale = arrowScale(s.maxL, ref);
    for (int b = 0; b < static_cast<int>(snap.bodies.size()); ++b) {
        const ViewSnapshot::Body& body = snap.bodies[b];
        if (!body.finite || body.fixed) continue;
        if (options.velocity && shown(body.v_W)) {
            s.hasVelocity = true;
            arrow(g.overlay, ArrowKind::Velocity, b, -1, body.x_W, body.x_W + vScale * body.v_W, body.v_W, shaft,
                  kVelocity);
        }
        if (options.angularVelocity && shown(body.omega_W)) {
            s.hasOmega = true;
            arrow(g.overlay, ArrowKind::AngularVelocity, b, -1, body.x_W, body.x_W + omegaScale * body.omega_W,
                  body.omega_W, 0.8 * shaft, kOmega);
        }
        if (options.angularMomentum && shown(body.L_W)) {
            s.hasL = true;
            arrow(translucent, ArrowKind::AngularMomentum, b, -1, body.x_W, body.x_W + lScale * body.L_W, body.L_W,
                  1.9 * shaft, kAngularMomentum);
        }
    }
    g.overlay.insert(g.overlay.end(), translucent.begin(), translucent.end());

    // The drag spring: a line from the picked point to the target, with both ends marked.
    if (snap.spring) {
        s.hasSpring = true;
        appendLine(g.lines, snap.spring->from_W, snap.spring->to_W, kSpring);
        appendBall(g.overlay, snap.spring->from_W, 0.03 * ref, kSpring);
        appendBall(g.overlay, snap.spring->to_W, 0.04 * ref, kSpring);
    }

    // Planes, farthest first so that blending composes them back to front.
    struct Patch {
        int plane;
        std::vector<Vec3> polygon;
        double distance;
    };
    std::vector<Patch> patches;
    if (options.sceneBox.valid()) {
        for (int i = 0; i < static_cast<int>(snap.planes.size()); ++i) {
            std::vector<Vec3> polygon = planePatch(snap.planes, i, options.sceneBox.min_W, options.sceneBox.max_W);
            if (polygon.empty()) continue;
            Vec3 centroid_W = Vec3::Zero();
            for (const Vec3& p : polygon) centroid_W += p;
            centroid_W /= double(polygon.size());
            patches.push_back(Patch{i, std::move(polygon), (centroid_W - options.eye_W).norm()});
        }
    }
    std::sort(patches.begin(), patches.end(), [](const Patch& a, const Patch& b) { return a.distance > b.distance; });
    for (const Patch& p : patches) {
        const ViewSnapshot::Plane& plane = snap.planes[p.plane];
        // Seen from behind (the eye outside a wall), a plane barely shows, so walls
        // never hide the scene.
        const bool front = plane.n_W.dot(options.eye_W - plane.point_W) > 0.0;
        appendPlane(g.planes, p.polygon, plane, front ? kPlane.a : kPlaneAlphaBehind);
    }
    return g;
}

} // namespace rbw::view
