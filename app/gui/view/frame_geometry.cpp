#include "app/gui/view/frame_geometry.h"

#include "app/gui/view/plane_patch.h"

#include <algorithm>

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

} // namespace

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
    double sum = 0.0;
    int count = 0;
    for (const ViewSnapshot::Body& body : snap.bodies) {
        if (!body.finite) continue;
        sum += body.size.maxCoeff();
        ++count;
    }
    return count > 0 ? sum / count : 1.0;
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
    // from the centre to a little beyond each face.
    for (int b = 0; b < static_cast<int>(snap.bodies.size()); ++b) {
        const ViewSnapshot::Body& body = snap.bodies[b];
        if (!body.finite) continue;
        Rgba colour = bodyColour(b, body.fixed);
        if (b == options.highlightBody) colour = lighter(colour, 0.35f);
        appendBox(g.lit, body.x_W, body.R_WB, body.size, colour);
        appendBoxEdges(g.lines, body.x_W, body.R_WB, body.size, kEdge);
        const double poke = 0.3 * body.size.maxCoeff();
        const Rgba axisColour[3] = {kAxisX, kAxisY, kAxisZ};
        for (int j = 0; j < 3; ++j) {
            appendLine(g.lines, body.x_W, body.x_W + (0.5 * body.size[j] + poke) * body.R_WB.col(j), axisColour[j]);
        }
    }

    // Motion trails of the centres of mass.
    if (options.trails) {
        for (int b = 0; b < static_cast<int>(trails.size()) && b < static_cast<int>(snap.bodies.size()); ++b) {
            const Rgba colour = lighter(bodyColour(b, snap.bodies[b].fixed), 0.25f);
            for (size_t k = 1; k < trails[b].size(); ++k) appendLine(g.lines, trails[b][k - 1], trails[b][k], colour);
        }
    }

    const double shaft = 0.022 * ref;

    // Forces: f_i from p_i, and M g from x; one scale for both (they share the unit N).
    for (const ViewSnapshot::Force& f : snap.forces) {
        s.maxForce = std::max(s.maxForce, f.f_W.norm());
        (f.kind == ViewSnapshot::ForceKind::Gravity ? s.hasGravity : s.hasApplied) = true;
    }
    const double forceScale = arrowScale(s.maxForce, ref);
    for (const ViewSnapshot::Force& f : snap.forces) {
        appendArrow(g.overlay, f.origin_W, forceScale * f.f_W, shaft,
                    f.kind == ViewSnapshot::ForceKind::Gravity ? kGravity : kForce);
    }

    // Probes: the point and its velocity v_p.
    for (const ViewSnapshot::Probe& p : snap.probes) {
        s.maxVelocity = std::max(s.maxVelocity, p.v_W.norm());
        s.hasProbes = true;
    }
    const double velocityScale = arrowScale(s.maxVelocity, ref);
    for (const ViewSnapshot::Probe& p : snap.probes) {
        appendBall(g.overlay, p.p_W, 0.05 * ref, kProbe);
        appendArrow(g.overlay, p.p_W, velocityScale * p.v_W, shaft, kProbe);
    }

    // Contacts: the point, the unit normal n (drawn at half the reference length)
    // and the impulse J n on A.
    for (const ViewSnapshot::Contact& c : snap.contacts) {
        s.maxImpulse = std::max(s.maxImpulse, c.impulse_W.norm());
        s.hasContacts = true;
    }
    const double impulseScale = arrowScale(s.maxImpulse, ref);
    for (const ViewSnapshot::Contact& c : snap.contacts) {
        appendBall(g.overlay, c.p_W, 0.055 * ref, kContact);
        appendArrow(g.overlay, c.p_W, 0.5 * ref * c.n_W.normalized(), 0.8 * shaft, kContact);
        appendArrow(g.overlay, c.p_W, impulseScale * c.impulse_W, 1.2 * shaft, kImpulse);
    }

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
