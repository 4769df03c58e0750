// reference_simulator.cpp: a rigid-body simulator written the way a careful student
// writes the TUM course algorithm, speaking the workbook's simulator protocol
// (docs/simulator-protocol.md). Standalone C++17: no project code, no Eigen.
//
// What it computes (docs/references.md §1-§3):
//   the explicit Euler step of "Simulation Algorithm 3D" (x with the old v, r with the
//   old omega, Iinv_W = R I0inv R^T from the new r), the template's box-box test
//   checkCollisionSAT, and the impulse J = -(1 + c) v_rel.n / (...) for every
//   colliding pair i < j after the step. No gravity, no damping, no friction.
// Each mistake model of the checker (`--mistake ID`, repeatable) changes one formula
// the way a student who makes that mistake would; README.md lists them with their
// equations. `--float` computes everything in float, as the template does.
//
// Glossary
//   x_W, v_W          centre of mass and its velocity, world frame             [m], [m/s]
//   r_WB              orientation, quaternion (w, x, y, z), body -> world        [-]
//   R_WB              rotation matrix R(r_WB)                                  [-]
//   L_W, omega_W      angular momentum and angular velocity, world frame       [kg m^2/s], [rad/s]
//   I0_B, I0inv_B     body-frame inertia of the box (diagonal) and its inverse [kg m^2], [1/(kg m^2)]
//   Iinv_W            the stored world-frame inverse inertia                   [1/(kg m^2)]
//   F_W, q_W          force and torque accumulated for the next step           [N], [N m]
//   h                 time step                                                [s]
//   c                 coefficient of restitution                               [-]
//   p_W, n_W          contact point and unit normal from B to A                [m], [-]
//   x_a, x_b          lever arms p - x_A and p - x_B                           [m]
//
// reference_simulator.py is the same program in Python; the two give the same
// numbers because every expression is evaluated in the same order (keep it so).
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace rbwref {

// ---------------------------------------------------------------------------------
// Small linear algebra
// ---------------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------------
// The mistake models (the checker's contract; README.md has the equations)
// ---------------------------------------------------------------------------------

struct MistakeDef {
    const char* id;
    const char* scope;   // "both", "sim" or "hand" (hand: the protocol cannot show it)
};

// Every id of the contract, in its order. Only "sim" and "both" ones are accepted.
inline const MistakeDef kMistakeDefs[] = {
    {"velocity-before-position", "both"},
    {"omega-before-orientation", "both"},
    {"transposed-inertia", "both"},
    {"body-inverse-inertia", "both"},
    {"inertia-not-inverted", "both"},
    {"torque-reversed", "both"},
    {"lever-arm-from-origin", "both"},
    {"missing-time-step", "both"},
    {"quaternion-missing-half", "both"},
    {"quaternion-not-normalised", "both"},
    {"half-extents-for-size", "both"},
    {"point-velocity-without-rotation", "hand"},
    {"relative-velocity-reversed", "both"},
    {"impulse-linear-only", "both"},
    {"impulse-without-one-plus", "both"},
    {"inertia-from-old-orientation", "both"},
    {"inertia-half-extents-without-third", "both"},
    {"inertia-axes-swapped", "both"},
    {"inertia-not-updated", "sim"},
    {"inertia-accumulated-rotation", "sim"},
    {"quaternion-right-multiplied", "both"},
    {"omega-accumulated", "both"},
    {"forces-not-cleared", "sim"},
    {"gravity-always-on", "sim"},
    {"orientation-zero-quaternion", "sim"},
    {"quaternion-without-half-angle", "hand"},
    {"angle-in-degrees", "hand"},
    {"point-velocity-lever-arm-from-origin", "hand"},
    {"point-velocity-cross-reversed", "hand"},
    {"restitution-one-minus", "both"},
    {"no-separating-check", "both"},
    {"impulse-body-inverse-inertia", "both"},
    {"impulse-lever-arm-from-origin", "both"},
    {"impulse-denominator-missing-cross", "both"},
};

struct Mistakes {
    bool velocityBeforePosition = false, omegaBeforeOrientation = false, transposedInertia = false,
         bodyInverseInertia = false, inertiaNotInverted = false, torqueReversed = false,
         leverArmFromOrigin = false, missingTimeStep = false, quaternionMissingHalf = false,
         quaternionNotNormalised = false, halfExtentsForSize = false, relativeVelocityReversed = false,
         impulseLinearOnly = false, impulseWithoutOnePlus = false, inertiaFromOldOrientation = false,
         inertiaHalfExtentsWithoutThird = false, inertiaAxesSwapped = false, inertiaNotUpdated = false,
         inertiaAccumulatedRotation = false, quaternionRightMultiplied = false, omegaAccumulated = false,
         forcesNotCleared = false, gravityAlwaysOn = false, orientationZeroQuaternion = false,
         restitutionOneMinus = false, noSeparatingCheck = false, impulseBodyInverseInertia = false,
         impulseLeverArmFromOrigin = false, impulseDenominatorMissingCross = false;

    // Switches the model `id` on; false if `id` is not a sim/both model.
    bool enable(const std::string& id)
    {
        struct Entry { const char* id; bool Mistakes::*flag; };
        static const Entry entries[] = {
            {"velocity-before-position", &Mistakes::velocityBeforePosition},
            {"omega-before-orientation", &Mistakes::omegaBeforeOrientation},
            {"transposed-inertia", &Mistakes::transposedInertia},
            {"body-inverse-inertia", &Mistakes::bodyInverseInertia},
            {"inertia-not-inverted", &Mistakes::inertiaNotInverted},
            {"torque-reversed", &Mistakes::torqueReversed},
            {"lever-arm-from-origin", &Mistakes::leverArmFromOrigin},
            {"missing-time-step", &Mistakes::missingTimeStep},
            {"quaternion-missing-half", &Mistakes::quaternionMissingHalf},
            {"quaternion-not-normalised", &Mistakes::quaternionNotNormalised},
            {"half-extents-for-size", &Mistakes::halfExtentsForSize},
            {"relative-velocity-reversed", &Mistakes::relativeVelocityReversed},
            {"impulse-linear-only", &Mistakes::impulseLinearOnly},
            {"impulse-without-one-plus", &Mistakes::impulseWithoutOnePlus},
            {"inertia-from-old-orientation", &Mistakes::inertiaFromOldOrientation},
            {"inertia-half-extents-without-third", &Mistakes::inertiaHalfExtentsWithoutThird},
            {"inertia-axes-swapped", &Mistakes::inertiaAxesSwapped},
            {"inertia-not-updated", &Mistakes::inertiaNotUpdated},
            {"inertia-accumulated-rotation", &Mistakes::inertiaAccumulatedRotation},
            {"quaternion-right-multiplied", &Mistakes::quaternionRightMultiplied},
            {"omega-accumulated", &Mistakes::omegaAccumulated},
            {"forces-not-cleared", &Mistakes::forcesNotCleared},
            {"gravity-always-on", &Mistakes::gravityAlwaysOn},
            {"orientation-zero-quaternion", &Mistakes::orientationZeroQuaternion},
            {"restitution-one-minus", &Mistakes::restitutionOneMinus},
            {"no-separating-check", &Mistakes::noSeparatingCheck},
            {"impulse-body-inverse-inertia", &Mistakes::impulseBodyInverseInertia},
            {"impulse-lever-arm-from-origin", &Mistakes::impulseLeverArmFromOrigin},
            {"impulse-denominator-missing-cross", &Mistakes::impulseDenominatorMissingCross},
        };
        for (const Entry& e : entries) {
            if (id == e.id) {
                this->*e.flag = true;
                return true;
            }
        }
        return false;
    }
};

// ---------------------------------------------------------------------------------
// The template's box-box test (checkCollisionSAT), docs/references.md §2
// ---------------------------------------------------------------------------------

template <typename Real>
struct Contact {
    Vec3<Real> p_W;   // the one contact point
    Vec3<Real> n_W;   // unit normal from B to A (the direction of the impulse on A)
    Real depth = 0;   // the smallest overlap (not used by the impulse)
    int axis = -1;    // winning axis: 0-2 faces of A, 3-5 faces of B, 6 + 3i + j edges a_i x b_j
};

template <typename Real>
struct Box {
    Vec3<Real> c_W;      // centre
    Mat3<Real> R_WB;     // columns: the body axes in the world
    Vec3<Real> h;        // half extents
};

// The 8 corners in the template's order: corner k has sign -/+ along body x, y, z
// by bits 0, 1, 2 of k.  corner_k = c + sum_j s_j(k) h_j R.col(j)
template <typename Real> void boxCorners(const Box<Real>& box, Vec3<Real> corners_W[8])
{
    const Real h[3] = {box.h.x, box.h.y, box.h.z};
    for (int k = 0; k < 8; ++k) {
        Vec3<Real> corner_W = box.c_W;
        for (int j = 0; j < 3; ++j) {
            const Real s = ((k >> j) & 1) ? Real(1) : Real(-1);
            corner_W = corner_W + box.R_WB.col(j) * (s * h[j]);
        }
        corners_W[k] = corner_W;
    }
}

// [min, max] of corner . axis over the 8 corners (template project()).
template <typename Real> void project(const Vec3<Real> corners_W[8], const Vec3<Real>& axis_W, Real& lo, Real& hi)
{
    lo = hi = dot(corners_W[0], axis_W);
    for (int k = 1; k < 8; ++k) {
        const Real p = dot(corners_W[k], axis_W);
        if (p < lo) {
            lo = p;
        } else if (p > hi) {
            hi = p;
        }
    }
}

// The first corner with the smallest corner . dir (template handleVertexToface()).
template <typename Real> Vec3<Real> cornerMinimising(const Vec3<Real> corners_W[8], const Vec3<Real>& dir_W)
{
    Real best = std::numeric_limits<Real>::infinity();
    Vec3<Real> bestCorner_W = corners_W[0];
    for (int k = 0; k < 8; ++k) {
        const Real value = dot(corners_W[k], dir_W);
        if (value < best) {
            best = value;
            bestCorner_W = corners_W[k];
        }
    }
    return bestCorner_W;
}

// Closest points of the lines pOne + mua dOne and pTwo + mub dTwo (template contactPoint()):
//   denom = |dOne|^2 |dTwo|^2 - (dOne.dTwo)^2; parallel (|denom| < 1e-4) or a parameter
//   outside [-size, size]: pOne if useOne else pTwo; otherwise the midpoint of the two
//   closest points.
template <typename Real>
Vec3<Real> edgeContactPoint(const Vec3<Real>& pOne, const Vec3<Real>& dOne, Real oneSize, const Vec3<Real>& pTwo,
                            const Vec3<Real>& dTwo, Real twoSize, bool useOne)
{
    const Real smOne = dot(dOne, dOne);
    const Real smTwo = dot(dTwo, dTwo);
    const Real dpOneTwo = dot(dTwo, dOne);
    const Vec3<Real> toSt = pOne - pTwo;
    const Real dpStaOne = dot(dOne, toSt);
    const Real dpStaTwo = dot(dTwo, toSt);
    const Real denom = smOne * smTwo - dpOneTwo * dpOneTwo;
    if (std::abs(denom) < Real(1e-4)) return useOne ? pOne : pTwo;
    const Real mua = (dpOneTwo * dpStaTwo - smTwo * dpStaOne) / denom;
    const Real mub = (smOne * dpStaTwo - dpOneTwo * dpStaOne) / denom;
    if (mua > oneSize || mua < -oneSize || mub > twoSize || mub < -twoSize) return useOne ? pOne : pTwo;
    const Vec3<Real> cOne = pOne + dOne * mua;
    const Vec3<Real> cTwo = pTwo + dTwo * mub;
    return cOne * Real(0.5) + cTwo * Real(0.5);
}

// A's contact with B; false when an axis separates them.
template <typename Real> bool collideBoxes(const Box<Real>& A, const Box<Real>& B, Contact<Real>& contact)
{
    // An edge pair whose |a_i x b_j| is at most this is parallel and gives no axis.
    const Real parallelSine = sizeof(Real) == sizeof(float) ? Real(1e-6) : Real(1e-9);
    Vec3<Real> a_W[3], b_W[3];
    for (int k = 0; k < 3; ++k) {
        a_W[k] = A.R_WB.col(k) / norm(A.R_WB.col(k));
        b_W[k] = B.R_WB.col(k) / norm(B.R_WB.col(k));
    }
    Vec3<Real> cornersA_W[8], cornersB_W[8];
    boxCorners(A, cornersA_W);
    boxCorners(B, cornersB_W);
    const Vec3<Real> toCenter_W = B.c_W - A.c_W;

    Real smallOverlap = std::numeric_limits<Real>::infinity();
    int bestAxis = -1;
    Vec3<Real> bestAxis_W;
    bool bestSingleAxis = false;   // a face of B was the running minimum at some point
    // overlap = min(maxA, maxB) - max(minA, minB); separated iff minA > maxB or minB > maxA.
    // Strict < keeps the earlier axis on a tie.
    auto testAxis = [&](const Vec3<Real>& axis_W, int number) -> bool {
        Real minA, maxA, minB, maxB;
        project(cornersA_W, axis_W, minA, maxA);
        project(cornersB_W, axis_W, minB, maxB);
        if (minA > maxB || minB > maxA) return false;
        const Real o = std::min(maxA, maxB) - std::max(minA, minB);
        if (o < smallOverlap) {
            smallOverlap = o;
            bestAxis = number;
            bestAxis_W = axis_W;
            if (number >= 3 && number < 6) bestSingleAxis = true;
        }
        return true;
    };
    for (int k = 0; k < 3; ++k)
        if (!testAxis(a_W[k], k)) return false;
    for (int k = 0; k < 3; ++k)
        if (!testAxis(b_W[k], 3 + k)) return false;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const Vec3<Real> cross_W = cross(a_W[i], b_W[j]);
            const Real length = norm(cross_W);
            if (!(length > parallelSine)) continue;
            if (!testAxis(cross_W / length, 6 + 3 * i + j)) return false;
        }
    }
    if (bestAxis < 0) return false;   // only with non-finite input

    // Orient the axis along toCenter; n = -axis points from B to A.
    Vec3<Real> axis_W = bestAxis_W;
    if (dot(axis_W, toCenter_W) <= 0) axis_W = axis_W * Real(-1);
    contact.axis = bestAxis;
    contact.depth = smallOverlap;
    contact.n_W = axis_W * Real(-1);
    if (bestAxis < 3) {
        // A face of A: B's corner with the smallest corner . toCenter.
        contact.p_W = cornerMinimising(cornersB_W, toCenter_W);
    } else if (bestAxis < 6) {
        // A face of B: A's corner with the smallest corner . (-toCenter).
        contact.p_W = cornerMinimising(cornersA_W, toCenter_W * Real(-1));
    } else {
        // Edge pair (i, j): A's edge along a_i furthest along the axis, B's edge along
        // b_j furthest against it (through their midpoints), then their closest points.
        const int i = (bestAxis - 6) / 3;
        const int j = (bestAxis - 6) % 3;
        const Real hA[3] = {A.h.x, A.h.y, A.h.z};
        const Real hB[3] = {B.h.x, B.h.y, B.h.z};
        Vec3<Real> pOne_W = A.c_W;
        Vec3<Real> pTwo_W = B.c_W;
        for (int k = 0; k < 3; ++k) {
            if (k != i) {
                const Real sA = dot(a_W[k], axis_W) < 0 ? Real(-1) : Real(1);
                pOne_W = pOne_W + A.R_WB.col(k) * (sA * hA[k]);
            }
            if (k != j) {
                const Real sB = dot(b_W[k], axis_W) > 0 ? Real(-1) : Real(1);
                pTwo_W = pTwo_W + B.R_WB.col(k) * (sB * hB[k]);
            }
        }
        // The template passes the full edge lengths as the parameter ranges.
        contact.p_W = edgeContactPoint(pOne_W, a_W[i], 2 * hA[i], pTwo_W, b_W[j], 2 * hB[j], bestSingleAxis);
    }
    return true;
}

// ---------------------------------------------------------------------------------
// The simulator
// ---------------------------------------------------------------------------------

template <typename Real>
struct Body {
    Real M = 1;                 // mass
    Vec3<Real> size;            // full edge lengths a, b, c
    Vec3<Real> I0_B;            // diagonal of the body inertia
    Vec3<Real> I0inv_B;         // diagonal of its inverse
    Vec3<Real> x_W, v_W;
    Quat<Real> r_WB;
    Vec3<Real> L_W, omega_W;
    Mat3<Real> Iinv_W;          // stored world inverse inertia
    Vec3<Real> F_W, q_W;        // loads for the next step
    bool stepped = false;       // inertia-not-updated: the tensor is fixed at the first step
};

template <typename Real>
class ReferenceSimulator {
public:
    ReferenceSimulator(const Mistakes& mistakes, Real restitution, bool trace)
        : mistakes_(mistakes), c_(restitution), trace_(trace) {}

    int bodyCount() const { return static_cast<int>(bodies_.size()); }

    // reset: a new scene without bodies.
    void reset() { bodies_.clear(); }

    // add_body: x = position, v = 0, r = 1, L = omega = 0, loads 0, Iinv_W = I0inv (R = E).
    void addBody(const Vec3<Real>& x_W, const Vec3<Real>& size, Real M)
    {
        Body<Real> b;
        b.M = M;
        b.size = size;
        // I0 = M/12 diag(b^2 + c^2, a^2 + c^2, a^2 + b^2)
        Real a = size.x, bb = size.y, c = size.z;
        if (mistakes_.halfExtentsForSize || mistakes_.inertiaHalfExtentsWithoutThird) {
            // half extents a' = a/2 ... used as if they were the edge lengths
            a = a / 2;
            bb = bb / 2;
            c = c / 2;
        }
        const Real factor = mistakes_.inertiaHalfExtentsWithoutThird ? M : M / 12;
        b.I0_B = {factor * (bb * bb + c * c), factor * (a * a + c * c), factor * (a * a + bb * bb)};
        if (mistakes_.inertiaAxesSwapped) {
            // y and z moments exchanged: M/12 diag(b^2 + c^2, a^2 + b^2, a^2 + c^2)
            b.I0_B = {b.I0_B.x, b.I0_B.z, b.I0_B.y};
        }
        b.I0inv_B = {1 / b.I0_B.x, 1 / b.I0_B.y, 1 / b.I0_B.z};
        b.x_W = x_W;
        if (mistakes_.orientationZeroQuaternion) b.r_WB = {0, 0, 0, 0};
        b.Iinv_W = diag(b.I0inv_B);
        bodies_.push_back(b);
    }

    // set_orientation: r = q / |q|; Iinv_W and omega are not touched.
    void setOrientation(int i, const Quat<Real>& q)
    {
        const Real n = norm(q);
        bodies_[i].r_WB = {q.w / n, q.x / n, q.y / n, q.z / n};
    }

    void setVelocity(int i, const Vec3<Real>& v_W) { bodies_[i].v_W = v_W; }

    // apply_force: F += f; q += (p - x) x f, with x the body's position now.
    void applyForce(int i, const Vec3<Real>& p_W, const Vec3<Real>& f_W)
    {
        Body<Real>& b = bodies_[i];
        b.F_W = b.F_W + f_W;
        Vec3<Real> q_W;
        if (mistakes_.leverArmFromOrigin && mistakes_.torqueReversed) {
            q_W = cross(f_W, p_W);                   // both: q = f x p
        } else if (mistakes_.leverArmFromOrigin) {
            q_W = cross(p_W, f_W);                   // q = p x f
        } else if (mistakes_.torqueReversed) {
            q_W = cross(f_W, p_W - b.x_W);           // q = f x (p - x)
        } else {
            q_W = cross(p_W - b.x_W, f_W);           // q = (p - x) x f
        }
        b.q_W = b.q_W + q_W;
    }

    void step(Real h)
    {
        for (Body<Real>& b : bodies_) integrate(b, h);
        for (int i = 0; i < bodyCount(); ++i)
            for (int j = i + 1; j < bodyCount(); ++j) collide(i, j);
    }

    // x, v, omega, r of body i: 13 numbers.
    std::vector<Real> state(int i) const
    {
        const Body<Real>& b = bodies_[i];
        return {b.x_W.x, b.x_W.y, b.x_W.z, b.v_W.x, b.v_W.y, b.v_W.z, b.omega_W.x, b.omega_W.y, b.omega_W.z,
                b.r_WB.w, b.r_WB.x, b.r_WB.y, b.r_WB.z};
    }

private:
    // The world inverse inertia for orientation r: R I0inv R^T, or the mistake's form.
    Mat3<Real> worldInverseInertia(const Body<Real>& b, const Quat<Real>& r) const
    {
        // inertia-not-inverted: I0 where I0inv belongs
        const Mat3<Real> D = diag(mistakes_.inertiaNotInverted ? b.I0_B : b.I0inv_B);
        // body-inverse-inertia: no rotation at all
        if (mistakes_.bodyInverseInertia) return D;
        return rotated(D, rotationMatrix(r));
    }

    // R D R^T, or R^T D R under transposed-inertia.
    Mat3<Real> rotated(const Mat3<Real>& D, const Mat3<Real>& R) const
    {
        if (mistakes_.transposedInertia) return (transpose(R) * D) * R;
        return (R * D) * transpose(R);
    }

    // One explicit Euler step of one body (docs/references.md §1).
    void integrate(Body<Real>& b, Real h)
    {
        const Quat<Real> r_n = b.r_WB;
        const Vec3<Real> omega_n = b.omega_W;
        // dt of the two load updates: h, or 1 under missing-time-step
        const Real loadDt = mistakes_.missingTimeStep ? Real(1) : h;
        // a = F/M (+ g under gravity-always-on, the template's y is up)
        Vec3<Real> a_W = b.F_W / b.M;
        if (mistakes_.gravityAlwaysOn) a_W = a_W + Vec3<Real>{0, Real(-9.81), 0};

        if (mistakes_.velocityBeforePosition) {
            // v <- v + h F/M, then x <- x + h v_{n+1}
            b.v_W = b.v_W + a_W * loadDt;
            b.x_W = b.x_W + b.v_W * h;
        } else {
            // 1. x <- x + h v (old v)
            b.x_W = b.x_W + b.v_W * h;
            // 2. v <- v + h F/M
            b.v_W = b.v_W + a_W * loadDt;
        }

        // 3. r <- r + (h/2) (0, omega) r with the old omega, then r <- r/|r|
        Vec3<Real> omegaForR_W = omega_n;
        if (mistakes_.omegaBeforeOrientation) {
            // omega' = R_n I0inv R_n^T L_{n+1}: L updated first, the inertia of the old r
            const Vec3<Real> L_next = b.L_W + b.q_W * loadDt;
            omegaForR_W = worldInverseInertia(b, r_n) * L_next;
        }
        const Quat<Real> omegaQ{0, omegaForR_W.x, omegaForR_W.y, omegaForR_W.z};
        // quaternion-right-multiplied: r (0, omega) instead of (0, omega) r
        const Quat<Real> rDot = mistakes_.quaternionRightMultiplied ? b.r_WB * omegaQ : omegaQ * b.r_WB;
        // quaternion-missing-half: h instead of h/2
        const Real rFactor = mistakes_.quaternionMissingHalf ? h : h / 2;
        b.r_WB = b.r_WB + rDot * rFactor;
        const Real rNorm = norm(b.r_WB);
        if (!mistakes_.quaternionNotNormalised && rNorm > 0) {
            b.r_WB = {b.r_WB.w / rNorm, b.r_WB.x / rNorm, b.r_WB.y / rNorm, b.r_WB.z / rNorm};
        }

        // 4. L <- L + h q
        b.L_W = b.L_W + b.q_W * loadDt;

        // 5. Iinv_W = R I0inv R^T with R = R(r_{n+1})
        if (mistakes_.inertiaNotUpdated) {
            // R_0 I0inv R_0^T from the orientation at the body's first step, never again
            if (!b.stepped) b.Iinv_W = worldInverseInertia(b, r_n);
        } else if (mistakes_.inertiaAccumulatedRotation) {
            // Iinv_W <- R Iinv_W R^T applied to the stored tensor
            b.Iinv_W = rotated(b.Iinv_W, rotationMatrix(b.r_WB));
        } else if (mistakes_.inertiaFromOldOrientation) {
            // R_n I0inv R_n^T: the orientation before this step's update
            b.Iinv_W = worldInverseInertia(b, r_n);
        } else {
            b.Iinv_W = worldInverseInertia(b, b.r_WB);
        }
        b.stepped = true;

        // 6. omega = Iinv_W L   (omega-accumulated: omega_{n+1} = omega_n + Iinv_W L)
        if (mistakes_.omegaAccumulated) {
            b.omega_W = omega_n + b.Iinv_W * b.L_W;
        } else {
            b.omega_W = b.Iinv_W * b.L_W;
        }

        // 7. the loads act for one step
        if (!mistakes_.forcesNotCleared) {
            b.F_W = {};
            b.q_W = {};
        }
    }

    // The impulse between bodies i (A) and j (B), docs/references.md §3.
    void collide(int i, int j)
    {
        Body<Real>& A = bodies_[i];
        Body<Real>& B = bodies_[j];
        const Box<Real> boxA{A.x_W, rotationMatrix(A.r_WB), A.size / Real(2)};
        const Box<Real> boxB{B.x_W, rotationMatrix(B.r_WB), B.size / Real(2)};
        Contact<Real> contact;
        if (!collideBoxes(boxA, boxB, contact)) return;
        const Vec3<Real>& p_W = contact.p_W;
        const Vec3<Real>& n_W = contact.n_W;

        // x_a = p - x_A, x_b = p - x_B   (impulse-lever-arm-from-origin: x_a = x_b = p)
        const Vec3<Real> x_a = mistakes_.impulseLeverArmFromOrigin ? p_W : p_W - A.x_W;
        const Vec3<Real> x_b = mistakes_.impulseLeverArmFromOrigin ? p_W : p_W - B.x_W;
        // v_rel = (v_A + omega_A x x_a) - (v_B + omega_B x x_b)
        const Vec3<Real> vA_p = A.v_W + cross(A.omega_W, x_a);
        const Vec3<Real> vB_p = B.v_W + cross(B.omega_W, x_b);
        const Vec3<Real> v_rel = mistakes_.relativeVelocityReversed ? vB_p - vA_p : vA_p - vB_p;
        const Real vn = dot(v_rel, n_W);
        const bool separating = vn > 0;
        if (trace_) traceContact(i, j, contact, vn, separating);
        // separating: no impulse
        if (separating && !mistakes_.noSeparatingCheck) return;

        // numerator -(1 + c) v_rel.n
        Real numerator = -(1 + c_) * vn;
        if (mistakes_.impulseWithoutOnePlus) numerator = -c_ * vn;
        if (mistakes_.restitutionOneMinus) numerator = -(1 - c_) * vn;

        // denominator 1/M_A + 1/M_B + [(IA (x_a x n)) x x_a + (IB (x_b x n)) x x_b].n
        const Mat3<Real> IA = mistakes_.impulseBodyInverseInertia ? diag(A.I0inv_B) : A.Iinv_W;
        const Mat3<Real> IB = mistakes_.impulseBodyInverseInertia ? diag(B.I0inv_B) : B.Iinv_W;
        const Real linear = 1 / A.M + 1 / B.M;
        Real denominator = linear + dot(cross(IA * cross(x_a, n_W), x_a) + cross(IB * cross(x_b, n_W), x_b), n_W);
        if (mistakes_.impulseLinearOnly) denominator = linear;
        if (mistakes_.impulseDenominatorMissingCross) {
            // (IA (x_a x n)).n + (IB (x_b x n)).n
            denominator = linear + (dot(IA * cross(x_a, n_W), n_W) + dot(IB * cross(x_b, n_W), n_W));
        }
        const Real J = numerator / denominator;
        if (trace_) std::fprintf(stderr, "  J = %.17g\n", double(J));

        // v_A += J n / M_A;  v_B -= J n / M_B;  L_A += x_a x J n;  L_B -= x_b x J n
        const Vec3<Real> Jn_W = n_W * J;
        A.v_W = A.v_W + Jn_W / A.M;
        B.v_W = B.v_W - Jn_W / B.M;
        A.L_W = A.L_W + cross(x_a, Jn_W);
        B.L_W = B.L_W - cross(x_b, Jn_W);
        // omega = Iinv_W L for both
        A.omega_W = A.Iinv_W * A.L_W;
        B.omega_W = B.Iinv_W * B.L_W;
    }

    static void traceContact(int i, int j, const Contact<Real>& k, Real vn, bool separating)
    {
        std::fprintf(stderr,
                     "contact %d %d: axis %d, p = (%.17g, %.17g, %.17g), n = (%.17g, %.17g, %.17g), "
                     "depth %.17g, v_rel.n = %.17g%s\n",
                     i, j, k.axis, double(k.p_W.x), double(k.p_W.y), double(k.p_W.z), double(k.n_W.x),
                     double(k.n_W.y), double(k.n_W.z), double(k.depth), double(vn),
                     separating ? " (separating)" : "");
    }

    Mistakes mistakes_;
    Real c_;
    bool trace_;
    std::vector<Body<Real>> bodies_;
};

}   // namespace rbwref

#ifndef RBW_REFERENCE_SIMULATOR_NO_MAIN

namespace {

using rbwref::kMistakeDefs;
using rbwref::Mistakes;

const char* const kProgram = "reference_simulator";

[[noreturn]] void die(const std::string& message)
{
    std::fprintf(stderr, "%s: %s\n", kProgram, message.c_str());
    std::exit(2);
}

std::string validMistakeIds()
{
    std::string ids;
    for (const auto& d : kMistakeDefs) {
        if (std::strcmp(d.scope, "hand") == 0) continue;
        if (!ids.empty()) ids += ", ";
        ids += d.id;
    }
    return ids;
}

void printHelp()
{
    std::printf(
        "Usage: %s [--mistake ID]... [--restitution C] [--float] [--trace] [--fail MODE]\n"
        "A rigid-body simulator that speaks the workbook's simulator protocol on stdin/stdout\n"
        "(docs/simulator-protocol.md): the TUM explicit Euler step, the template's box-box\n"
        "test and the impulse, with no gravity and no damping.\n\n"
        "Options:\n"
        "  --mistake ID      switch on a mistake model (repeatable); see README.md\n"
        "  --restitution C   coefficient of restitution, 0 <= C <= 1 (default 0.5)\n"
        "  --float           compute in float, as the course template does\n"
        "  --trace           describe every contact on stderr\n"
        "  --fail MODE       misbehave on purpose, to test a driver: nan (the second state\n"
        "                    answer is nan), exit (exit status 1 after the first step),\n"
        "                    hang (no answers after the first step), garbage (answers hello)\n"
        "  --help            this text\n\n"
        "Mistake ids:\n",
        kProgram);
    for (const auto& d : kMistakeDefs) {
        if (std::strcmp(d.scope, "hand") != 0) std::printf("  %s\n", d.id);
    }
    std::printf("\nExit status: 0 after quit or end of input, 2 bad options or a malformed command.\n");
}

enum class Fail { None, Nan, Exit, Hang, Garbage };

struct Options {
    Mistakes mistakes;
    double restitution = 0.5;
    bool useFloat = false;
    bool trace = false;
    Fail fail = Fail::None;
};

// A plain decimal number: [+-] digits [. digits] [e [+-] digits] (or .digits), finite.
bool parseNumber(const std::string& token, double& value)
{
    size_t k = 0;
    const size_t n = token.size();
    if (k < n && (token[k] == '+' || token[k] == '-')) ++k;
    size_t digits = 0;
    while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++digits;
    if (k < n && token[k] == '.') {
        ++k;
        while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++digits;
    }
    if (digits == 0) return false;
    if (k < n && (token[k] == 'e' || token[k] == 'E')) {
        ++k;
        if (k < n && (token[k] == '+' || token[k] == '-')) ++k;
        size_t expDigits = 0;
        while (k < n && std::isdigit(static_cast<unsigned char>(token[k]))) ++k, ++expDigits;
        if (expDigits == 0) return false;
    }
    if (k != n) return false;
    errno = 0;
    value = std::strtod(token.c_str(), nullptr);
    return std::isfinite(value) && errno != ERANGE;
}

Options parseOptions(int argc, char** argv)
{
    Options o;
    bool failSeen = false;
    for (int k = 1; k < argc; ++k) {
        std::string arg = argv[k];
        std::string value;
        bool hasValue = false;
        const size_t eq = arg.find('=');
        if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = arg.substr(eq + 1);
            arg = arg.substr(0, eq);
            hasValue = true;
        }
        const auto takeValue = [&]() {
            if (hasValue) return value;
            if (k + 1 >= argc) die(arg + " needs a value");
            return std::string(argv[++k]);
        };
        if (arg == "--help" || arg == "-h") {
            printHelp();
            std::exit(0);
        } else if (arg == "--mistake") {
            const std::string id = takeValue();
            if (!o.mistakes.enable(id)) {
                std::string why = "unknown mistake id '" + id + "'";
                for (const auto& d : kMistakeDefs) {
                    if (id == d.id) why = "'" + id + "' is a hand-calculation mistake; the protocol cannot show it";
                }
                die(why + ". Valid ids: " + validMistakeIds());
            }
        } else if (arg == "--restitution") {
            const std::string text = takeValue();
            if (!parseNumber(text, o.restitution) || o.restitution < 0 || o.restitution > 1) {
                die("--restitution needs a number from 0 to 1, got '" + text + "'");
            }
        } else if (arg == "--float" && !hasValue) {
            o.useFloat = true;
        } else if (arg == "--trace" && !hasValue) {
            o.trace = true;
        } else if (arg == "--fail") {
            const std::string mode = takeValue();
            if (failSeen) die("--fail given twice");
            failSeen = true;
            if (mode == "nan") o.fail = Fail::Nan;
            else if (mode == "exit") o.fail = Fail::Exit;
            else if (mode == "hang") o.fail = Fail::Hang;
            else if (mode == "garbage") o.fail = Fail::Garbage;
            else die("unknown --fail mode '" + mode + "' (valid: nan, exit, hang, garbage)");
        } else {
            die(std::string("unknown option '") + argv[k] + "' (try --help)");
        }
    }
    return o;
}

template <typename Real>
int run(const Options& options)
{
    using V = rbwref::Vec3<Real>;
    rbwref::ReferenceSimulator<Real> sim(options.mistakes, Real(options.restitution), options.trace);
    const char* const format = sizeof(Real) == sizeof(float) ? "%.9g" : "%.17g";
    int lineNo = 0;
    int stateAnswers = 0;
    bool stepped = false;
    std::string line;
    while (std::getline(std::cin, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream in(line);
        std::vector<std::string> tokens;
        for (std::string t; in >> t;) tokens.push_back(t);
        if (tokens.empty()) continue;   // blank lines are ignored
        const std::string& command = tokens[0];
        const std::string where = "line " + std::to_string(lineNo) + ": ";

        // The command's arguments: a body index and/or numbers.
        const auto expectCount = [&](size_t count, const char* usage) {
            if (tokens.size() - 1 != count) {
                die(where + command + " needs " + std::to_string(count) + " argument" + (count == 1 ? "" : "s") +
                    " (" + usage + "), got " + std::to_string(tokens.size() - 1));
            }
        };
        const auto number = [&](size_t k) -> Real {
            double value = 0;
            if (!parseNumber(tokens[k], value)) {
                die(where + command + ": '" + tokens[k] + "' is not a finite decimal number");
            }
            return Real(value);
        };
        const auto bodyIndex = [&](size_t k) -> int {
            const std::string& t = tokens[k];
            bool digits = !t.empty() && t.size() < 10;
            for (char ch : t) digits = digits && std::isdigit(static_cast<unsigned char>(ch));
            if (!digits) die(where + command + ": body index '" + t + "' is not a whole number >= 0");
            const int i = std::atoi(t.c_str());
            if (i >= sim.bodyCount()) {
                die(where + command + ": there is no body " + t + " (the scene has " +
                    std::to_string(sim.bodyCount()) + " bod" + (sim.bodyCount() == 1 ? "y" : "ies") + ")");
            }
            return i;
        };
        const auto vec = [&](size_t k) -> V { return V{number(k), number(k + 1), number(k + 2)}; };

        if (command == "reset") {
            expectCount(0, "");
            sim.reset();
        } else if (command == "add_body") {
            expectCount(7, "X Y Z SX SY SZ MASS");
            const V x_W = vec(1);
            const V size = vec(4);
            if (!(size.x > 0 && size.y > 0 && size.z > 0)) die(where + "add_body: the size must be positive");
            const std::string& m = tokens[7];
            bool whole = !m.empty() && m.size() < 10;
            for (size_t k = 0; k < m.size(); ++k)
                whole = whole && (std::isdigit(static_cast<unsigned char>(m[k])) || (k == 0 && m[k] == '+'));
            if (!whole || std::atoi(m.c_str()) <= 0) {
                die(where + "add_body: the mass '" + m + "' is not a whole number > 0 (the template takes an int)");
            }
            sim.addBody(x_W, size, Real(std::atoi(m.c_str())));
        } else if (command == "set_orientation") {
            expectCount(5, "I W X Y Z");
            const int i = bodyIndex(1);
            const rbwref::Quat<Real> q{number(2), number(3), number(4), number(5)};
            if (!(rbwref::norm(q) > 0)) die(where + "set_orientation: the quaternion is zero");
            sim.setOrientation(i, q);
        } else if (command == "set_velocity") {
            expectCount(4, "I VX VY VZ");
            const int i = bodyIndex(1);
            sim.setVelocity(i, vec(2));
        } else if (command == "apply_force") {
            expectCount(7, "I PX PY PZ FX FY FZ");
            const int i = bodyIndex(1);
            sim.applyForce(i, vec(2), vec(5));
        } else if (command == "step") {
            expectCount(1, "H");
            const Real h = number(1);
            if (!(h > 0)) die(where + "step: the time step must be > 0");
            sim.step(h);
            if (!stepped && options.fail == Fail::Exit) {
                std::fprintf(stderr, "%s: --fail exit: exiting with status 1 after the first step\n", kProgram);
                return 1;
            }
            if (!stepped && options.fail == Fail::Hang) {
                // Never answer again, and never exit: a driver must time out.
                for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
            }
            stepped = true;
        } else if (command == "state") {
            expectCount(1, "I");
            const int i = bodyIndex(1);
            ++stateAnswers;
            std::string answer;
            if (options.fail == Fail::Garbage) {
                answer = "hello";
            } else {
                const std::vector<Real> s = sim.state(i);
                for (size_t k = 0; k < s.size(); ++k) {
                    char buffer[64];
                    if (options.fail == Fail::Nan && stateAnswers == 2) {
                        std::snprintf(buffer, sizeof buffer, "nan");
                    } else {
                        std::snprintf(buffer, sizeof buffer, format, double(s[k]));
                    }
                    if (k > 0) answer += ' ';
                    answer += buffer;
                }
            }
            std::printf("%s\n", answer.c_str());
            std::fflush(stdout);
        } else if (command == "quit") {
            expectCount(0, "");
            return 0;
        } else {
            die(where + "unknown command '" + command +
                "' (valid: reset, add_body, set_orientation, set_velocity, apply_force, step, state, quit)");
        }
    }
    return 0;
}

}   // namespace

int main(int argc, char** argv)
{
    const Options options = parseOptions(argc, argv);
    return options.useFloat ? run<float>(options) : run<double>(options);
}

#endif   // RBW_REFERENCE_SIMULATOR_NO_MAIN
