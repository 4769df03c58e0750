// Fixed-size Eigen types used throughout physics/, and the one statement of the
// quaternion coefficient order.
//
// Glossary
//   Vec3, Mat3   3-vector and 3x3 matrix of doubles (column vectors, R acts as R*v).
//   Quat         unit quaternion r_WB that rotates body-frame vectors into the world.
//   skew(a)      the cross-product matrix [a]x, with [a]x * b = a x b.
//
// Quaternion coefficient order. Everywhere outside Eigen's memory layout, i.e. in
// scene files, JSON output, CSV, traces and docs, a quaternion is written
// [w, x, y, z] (scalar first). Eigen's Quaterniond(w, x, y, z) constructor takes the
// same order, but Quaterniond::coeffs() is stored x, y, z, w: never index coeffs();
// use toWxyz()/fromWxyz() below.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>

namespace rbw {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

inline Mat3 skew(const Vec3& a)
{
    Mat3 m;
    m << 0.0, -a.z(), a.y(),
         a.z(), 0.0, -a.x(),
         -a.y(), a.x(), 0.0;
    return m;
}

inline std::array<double, 4> toWxyz(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }
inline Quat fromWxyz(const std::array<double, 4>& c) { return Quat(c[0], c[1], c[2], c[3]); }

inline bool isFinite(const Vec3& a) { return a.allFinite(); }
inline bool isFinite(const Mat3& a) { return a.allFinite(); }
inline bool isFinite(const Quat& q) { return q.coeffs().allFinite(); }

} // namespace rbw
