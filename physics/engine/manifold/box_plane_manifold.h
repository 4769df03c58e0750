// Box-plane manifolds (the manifold model): every corner of the box on, below or within
// the speculative margin above a fixed plane is a point of one manifold, kept together
// and solved together (Catto GDC 2005; Ericson, "Real-Time Collision Detection", 5.2.3).
//
// Glossary
//   corner_W    a box corner, world frame (contact.h's order, bit j = sign along axis j) [m]
//   s           signed distance of the corner from the plane, n . (corner - point)     [m]
//   pA_A        the corner in the box frame                                            [m]
//   pB_B        its projection on the plane, world frame: corner - s n                 [m]
//
// The box is A, the plane B, n the plane normal (from B to A). Feature id: the corner
// index 0-7, so a box that keeps resting on the same face keeps its points' ids.
#pragma once

#include "physics/engine/collision/contact.h"
#include "physics/engine/manifold/manifold.h"

namespace rbw {

// Fills m's points (up to 8) with the corners with s <= margin, plus reference, normal
// and tangents; returns false when no corner is that close. m.a, m.plane, mu and c are
// the caller's.
bool collideBoxPlaneManifold(const BoxPose& box, const PlaneDef& plane, double margin, Manifold& m);

} // namespace rbw
