// vec_math.h: the small linear algebra of the reference simulator (reference_simulator.h):
// Vec3, the quaternion (w, x, y, z), the 3x3 matrix and R(r). Templates over Real
// (double, or float for --float). Standalone C++17: no project code, no Eigen.
// reference_simulator.py has the same functions; keep every expression in its order.
#pragma once

#include <cmath>

namespace rbwref {

template <typename Real>
struct Vec3 {
    Real x = 0, y = 0, z = 0;
};

template <typename Real> Vec3<Real> operator+(const Vec3<Real>& a, const Vec3<Real>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <typename Real> Vec3<Real> operator-(const Vec3<Real>& a, const Vec3<Real>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <typename Real> Vec3<Real> operator*(const Vec3<Real>& a, Real s) { return {a.x * s, a.y * s, a.z * s}; }
template <typename Real> Vec3<Real> operator/(const Vec3<Real>& a, Real s) { return {a.x / s, a.y / s, a.z / s}; }
template <typename Real> Real dot(const Vec3<Real>& a, const Vec3<Real>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename Real> Vec3<Real> cross(const Vec3<Real>& a, const Vec3<Real>& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename Real> Real norm(const Vec3<Real>& a) { return std::sqrt(dot(a, a)); }

// Quaternion (w, x, y, z); (0, v) is the pure quaternion of a vector.
template <typename Real>
struct Quat {
    Real w = 1, x = 0, y = 0, z = 0;
};

// (w1, v1)(w2, v2) = (w1 w2 - v1.v2, w1 v2 + w2 v1 + v1 x v2)
template <typename Real> Quat<Real> operator*(const Quat<Real>& a, const Quat<Real>& b)
{
    const Vec3<Real> va{a.x, a.y, a.z};
    const Vec3<Real> vb{b.x, b.y, b.z};
    const Vec3<Real> v = (vb * a.w + va * b.w) + cross(va, vb);
    return {a.w * b.w - dot(va, vb), v.x, v.y, v.z};
}
template <typename Real> Quat<Real> operator+(const Quat<Real>& a, const Quat<Real>& b) { return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z}; }
template <typename Real> Quat<Real> operator*(const Quat<Real>& a, Real s) { return {a.w * s, a.x * s, a.y * s, a.z * s}; }
template <typename Real> Real norm(const Quat<Real>& a) { return std::sqrt(a.w * a.w + a.x * a.x + a.y * a.y + a.z * a.z); }

template <typename Real>
struct Mat3 {
    Real m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    Vec3<Real> col(int j) const { return {m[0][j], m[1][j], m[2][j]}; }
};

template <typename Real> Mat3<Real> diag(const Vec3<Real>& d)
{
    Mat3<Real> A;
    A.m[0][0] = d.x;
    A.m[1][1] = d.y;
    A.m[2][2] = d.z;
    return A;
}
template <typename Real> Mat3<Real> transpose(const Mat3<Real>& A)
{
    Mat3<Real> T;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) T.m[i][j] = A.m[j][i];
    return T;
}
template <typename Real> Mat3<Real> operator*(const Mat3<Real>& A, const Mat3<Real>& B)
{
    Mat3<Real> C;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) C.m[i][j] = A.m[i][0] * B.m[0][j] + A.m[i][1] * B.m[1][j] + A.m[i][2] * B.m[2][j];
    return C;
}
template <typename Real> Vec3<Real> operator*(const Mat3<Real>& A, const Vec3<Real>& v)
{
    return {A.m[0][0] * v.x + A.m[0][1] * v.y + A.m[0][2] * v.z,
            A.m[1][0] * v.x + A.m[1][1] * v.y + A.m[1][2] * v.z,
            A.m[2][0] * v.x + A.m[2][1] * v.y + A.m[2][2] * v.z};
}

// R(r): the standard formula for a unit quaternion, used unchanged for a non-unit one
// (as Eigen's toRotationMatrix does; it matters for quaternion-not-normalised).
template <typename Real> Mat3<Real> rotationMatrix(const Quat<Real>& r)
{
    const Real w = r.w, x = r.x, y = r.y, z = r.z;
    Mat3<Real> R;
    R.m[0][0] = 1 - 2 * (y * y + z * z);
    R.m[0][1] = 2 * (x * y - w * z);
    R.m[0][2] = 2 * (x * z + w * y);
    R.m[1][0] = 2 * (x * y + w * z);
    R.m[1][1] = 1 - 2 * (x * x + z * z);
    R.m[1][2] = 2 * (y * z - w * x);
    R.m[2][0] = 2 * (x * z - w * y);
    R.m[2][1] = 2 * (y * z + w * x);
    R.m[2][2] = 1 - 2 * (x * x + y * y);
    return R;
}

}   // namespace rbwref
