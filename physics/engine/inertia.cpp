#include "physics/engine/inertia.h"

#include <cassert>

namespace rbw {

Mat3 boxInertiaBody(const Vec3& size, double mass)
{
    const double a2 = size.x() * size.x();
    const double b2 = size.y() * size.y();
    const double c2 = size.z() * size.z();
    // I0 = M/12 * diag(b^2 + c^2, a^2 + c^2, a^2 + b^2)
    Mat3 I0_B = Mat3::Zero();
    I0_B(0, 0) = mass / 12.0 * (b2 + c2);
    I0_B(1, 1) = mass / 12.0 * (a2 + c2);
    I0_B(2, 2) = mass / 12.0 * (a2 + b2);
    return I0_B;
}

Mat3 inverseInertiaWorld(const Mat3& R_WB, const Mat3& I0inv_B, InertiaConvention convention)
{
    assert(I0inv_B.isDiagonal() && "body inertia must be given in its principal frame");
    if (convention == InertiaConvention::CourseTemplate) {
        // Iinv_W = R^T I0^-1 R  (TUM template reference solution, docs/references.md §1)
        return R_WB.transpose() * I0inv_B.diagonal().asDiagonal() * R_WB;
    }
    // Iinv_W = R I0^-1 R^T  (TUM slides "Simulation Algorithm 3D", step 6).
    // I0 is diagonal in the principal body frame, so the product runs on its diagonal.
    return R_WB * I0inv_B.diagonal().asDiagonal() * R_WB.transpose();
}

} // namespace rbw
