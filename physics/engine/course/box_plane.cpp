// Box-plane contacts and their average; see box_plane.h for the rules and source.
//
// Glossary
//   corners_W   the box's 8 corners in the template's order (contact.h)          [m]
//   d           signed distance of a corner above the plane                      [m]
//   sum_W       running sum of the averaged contact points                       [m]
#include "physics/engine/course/box_plane.h"

#include <algorithm>
#include <array>
#include <cassert>

namespace rbw {

int collideBoxPlane(const BoxPose& box, const PlaneDef& plane, std::vector<ContactGeometry>& out)
{
    // Napier practical 6: transform the 8 corners to world space,
    //   corner_W = c_W + R_WB * (+-h_x, +-h_y, +-h_z).
    const std::array<Vec3, 8> corners_W = boxCorners(box);
    int appended = 0;
    for (const Vec3& corner_W : corners_W) {
        // Signed distance to the plane { p : n . (p - point) = 0 }:
        //   d = n . (corner - point); d <= 0 is on or below the plane (touching counts).
        const Vec3 fromPlane_W = corner_W - plane.point_W;
        const double d = plane.n_W.dot(fromPlane_W);
        if (d <= 0.0) {
            ContactGeometry contact;
            contact.p_W = corner_W;
            contact.where = std::source_location::current();
            // The plane is body B: n points from B (plane) to A (box) = the plane normal.
            contact.n_W = plane.n_W;
            // Penetration depth = -d >= 0 (written 0.0 - d so that d == 0 gives +0).
            contact.depth = 0.0 - d;
            contact.feature = ContactFeature::VertexPlane;
            contact.axis = -1;
            out.push_back(contact);
            ++appended;
        }
    }
    return appended;
}

ContactGeometry averageContact(const std::vector<ContactGeometry>& contacts, std::size_t first,
                               std::size_t count)
{
    assert(count >= 1 && first + count <= contacts.size());
    // Napier assessment: the contact point is the average of the colliding corners,
    //   p = (1/count) * sum_k p_k; the normal is the shared plane normal; the depth
    //   is the deepest corner's, max_k depth_k.
    Vec3 sum_W = Vec3::Zero();
    double maxDepth = contacts[first].depth;
    for (std::size_t k = first; k < first + count; ++k) {
        sum_W += contacts[k].p_W;
        maxDepth = std::max(maxDepth, contacts[k].depth);
    }
    ContactGeometry average;
    average.p_W = sum_W / static_cast<double>(count);
    average.where = std::source_location::current();
    average.n_W = contacts[first].n_W;
    average.depth = maxDepth;
    average.feature = ContactFeature::VertexPlane;
    average.axis = -1;
    return average;
}

} // namespace rbw
