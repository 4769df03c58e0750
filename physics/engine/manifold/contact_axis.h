// One constraint axis at a contact point: the one place the effective-mass formula is
// written (Jolt's AxisConstraintPart; Box2D v3 b2PrepareContactsTask's kNormal and
// kTangent; Catto, GDC 2005). Every row of the manifold model's solvers (the normal
// and friction rows of the sequential impulses and of the soft step, the normal rows'
// coupling, and the position fix's normal) builds its numbers here.
//
// For an axis d (a unit vector: n, t1 or t2) at lever arms r_A, r_B, an impulse lambda d
// on A (and -lambda d on B) changes the relative velocity along another axis e at the
// same or another point of the same two bodies by K_ed lambda, with
//   K_ed = 1/M_A + 1/M_B (e . d) + (r_A,e x e) . I_A^-1 (r_A,d x d) + (r_B,e x e) . I_B^-1 (r_B,d x d)
// and along d itself by
//   K = 1/M_A + 1/M_B + (r_A x d) . I_A^-1 (r_A x d) + (r_B x d) . I_B^-1 (r_B x d),
// the inverse of the effective mass m = 1/K: the impulse that changes v_d by dv is m dv.
//
// Glossary
//   rAxd_W, rBxd_W       the angular parts r_A x d, r_B x d                        [m]
//   IArAxd_W, IBrBxd_W   the angular responses I_A^-1 (r_A x d), I_B^-1 (r_B x d)   [1/(kg m)]
//   invMAB               1/M_A + 1/M_B (0 for a fixed body or a plane)             [1/kg]
#pragma once

#include "physics/engine/math_types.h"

namespace rbw {

struct ContactAxis {
    Vec3 rAxd_W;
    Vec3 rBxd_W;
    Vec3 IArAxd_W;
    Vec3 IBrBxd_W;

    ContactAxis() = default;
    // The axis d at lever arms r_A, r_B of bodies with inverse inertias I_A^-1, I_B^-1
    // (zero for a body the contacts do not turn).
    ContactAxis(const Vec3& r_A_W, const Vec3& r_B_W, const Vec3& d_W, const Mat3& IinvA_W, const Mat3& IinvB_W)
        : rAxd_W(r_A_W.cross(d_W))
        , rBxd_W(r_B_W.cross(d_W))
        , IArAxd_W(IinvA_W * rAxd_W)
        , IBrBxd_W(IinvB_W * rBxd_W)
    {
    }

    // K_ed = linear + (r_A,e x e) . I_A^-1 (r_A,d x d) + (r_B,e x e) . I_B^-1 (r_B,d x d),
    // this axis e, `d` the other; linear = 1/M_A + 1/M_B when e = d or both are the
    // normal n, 0 for two perpendicular axes.
    double coupling(double linear, const ContactAxis& d) const
    {
        return linear + rAxd_W.dot(d.IArAxd_W) + rBxd_W.dot(d.IBrBxd_W);
    }
    // The angular part of the coupling of two perpendicular axes (t1 . t2 = 0):
    // (r_A x e) . I_A^-1 (r_A x d) + (r_B x e) . I_B^-1 (r_B x d)
    double angularCoupling(const ContactAxis& d) const { return rAxd_W.dot(d.IArAxd_W) + rBxd_W.dot(d.IBrBxd_W); }
    // K = 1/M_A + 1/M_B + (r_A x d) . I_A^-1 (r_A x d) + (r_B x d) . I_B^-1 (r_B x d)
    double inverseMass(double invMAB) const { return coupling(invMAB, *this); }
    // m = 1/K, or 0 for a row nothing can move (K = 0)
    double mass(double invMAB) const { return effectiveMass(inverseMass(invMAB)); }

    static double effectiveMass(double K) { return K > 0.0 ? 1.0 / K : 0.0; }
};

} // namespace rbw
