// reference_simulator.h: the rigid bodies and the step of the reference simulator
// (reference_simulator.cpp speaks the protocol around it; template_stub/ calls it as the
// template's class would). A careful student's TUM course algorithm (docs/references.md
// §1-§3): the explicit Euler step of "Simulation Algorithm 3D" (x with the old v, r with
// the old omega, Iinv_W = R I0inv R^T from the new r), the template's box-box test
// (box_box_sat.h), and the impulse J = -(1 + c) v_rel.n / (...) for every colliding pair
// i < j after the step. No gravity, no damping, no friction. Each switched-on mistake
// (mistakes.h) changes one formula the way a student who makes that mistake would.
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
// reference_simulator.py is the same program in Python; keep every expression in the
// same order, so the two give the same numbers.
#pragma once

#include "box_box_sat.h"
#include "mistakes.h"
#include "vec_math.h"

#include <cstdio>
#include <vector>

namespace rbwref {

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
