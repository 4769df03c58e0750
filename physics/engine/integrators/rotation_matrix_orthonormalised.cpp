#include "physics/engine/integrators/rotation_matrix_orthonormalised.h"

#include "physics/engine/quantities.h"

#include "physics/engine/integrators/rotation_matrix.h"

#include <Eigen/SVD>

namespace rbw {

Mat3 nearestRotation(const Mat3& M)
{
    // M = U S V^T  ->  Q = U V^T; if det Q = -1, flip the column of the smallest
    // singular value so that Q is a rotation (Higham 1986).
    const Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat3 U = svd.matrixU();
    const Mat3 V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0.0) {
        U.col(2) = -U.col(2);
    }
    return U * V.transpose();
}

} // namespace rbw
