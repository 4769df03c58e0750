#include "physics/engine/course/impulse.h"

#include "physics/engine/quantities.h"

#include <cmath>

namespace rbw {

namespace {

struct Side {
    Vec3 v = Vec3::Zero();
    Vec3 omega = Vec3::Zero();
    Mat3 Iinv = Mat3::Zero();
    double invM = 0.0;
    double M = 0.0;
};

Side sideOf(const ResponseBody& b)
{
    Side s;
    if (b.state == nullptr || b.mass == nullptr || b.mass->invM == 0.0) {
        return s;   // fixed: 1/M = 0 and I^-1 = 0 (docs/references.md §3)
    }
    // A "particle" side (angular response off) moves with its centre of mass only:
    // its contact velocity is v, and the impulse does not change its L.
    s.v = b.state->v_W;
    s.omega = b.angular ? b.state->omega_W : Vec3::Zero();
    s.Iinv = b.angular ? b.state->Iinv_W : Mat3::Zero();
    s.invM = b.mass->invM;
    s.M = b.mass->M;
    return s;
}

double kinetic(const ResponseBody& b)
{
    if (b.state == nullptr || b.mass == nullptr || b.mass->invM == 0.0) return 0.0;
    // T = 1/2 M |v|^2 + 1/2 omega . L
    return 0.5 * b.mass->M * b.state->v_W.squaredNorm() + 0.5 * b.state->omega_W.dot(b.state->L_W);
}

// [(I^-1 (x x d)) x x] . d: the rotational term of the effective-mass denominator along d.
double rotationalTerm(const Mat3& Iinv, const Vec3& x, const Vec3& d)
{
    const Vec3 Iinv_xd = Iinv * x.cross(d);
    return Iinv_xd.cross(x).dot(d);
}

// v += P / M, L += x x P, omega = I^-1 L, for the impulse P on a body at lever arm x.
void applyImpulse(ResponseBody& b, const Vec3& x, const Vec3& P_W, Vec3& dv, Vec3& dL)
{
    if (b.state == nullptr || b.mass == nullptr || b.mass->invM == 0.0) return;
    const Vec3 dv_step = b.mass->invM * P_W;
    b.state->v_W += dv_step;
    dv += dv_step;
    if (b.angular) {
        const Vec3 dL_step = x.cross(P_W);
        b.state->L_W += dL_step;
        dL += dL_step;
        updateDerived(*b.mass, *b.state, b.convention);
    }
}

} // namespace

ImpulseResult applyContactImpulse(const ContactGeometry& g, ResponseBody A, ResponseBody B, double restitution,
                                  double mu, StepTrace* trace, int contact)
{
    const int a = A.index;
    const int b = B.index;
    const int k = contact;
    ImpulseResult r;
    r.restitution = restitution;
    r.mu = mu;
    const Vec3& n = g.n_W;
    const Side sa = sideOf(A);
    const Side sb = sideOf(B);
    // x_a = p - x_A, x_b = p - x_B (a plane has no centre: its x_b is unused)
    r.x_a = A.state != nullptr ? Vec3(g.p_W - A.state->x_W) : Vec3::Zero();
    record(trace, q::x_a, a, r.x_a, k);
    r.x_b = B.state != nullptr ? Vec3(g.p_W - B.state->x_W) : Vec3::Zero();
    if (b >= 0) record(trace, q::x_b, b, r.x_b, k);

    // v_X(p) = v_X + omega_X x x_x,  v_rel = v_A(p) - v_B(p)
    r.velocity_a = sa.v + sa.omega.cross(r.x_a);
    record(trace, q::velocity_a, a, r.velocity_a, k);
    r.velocity_b = sb.v + sb.omega.cross(r.x_b);
    record(trace, q::velocity_b, b, r.velocity_b, k);
    r.v_rel = r.velocity_a - r.velocity_b;
    record(trace, q::relative_velocity, a, r.v_rel, k);
    r.v_rel_n = r.v_rel.dot(n);
    record(trace, q::normal_velocity, a, r.v_rel_n, k);

    // v_rel . n > 0: the bodies are separating, no impulse (the contact's header says
    // so). The terms of J's denominator are still computed, for a student to compare,
    // but only an approaching contact records them.
    r.separating = r.v_rel_n > 0.0;
    StepTrace* const impulseTrace = r.separating ? nullptr : trace;

    // Terms of J's denominator: 1/M_A + 1/M_B + [(I_A^-1 (x_a x n)) x x_a] . n + [...]_B
    r.invMassA = sa.invM;
    record(impulseTrace, q::inv_mass_a, a, r.invMassA, k);
    r.invMassB = sb.invM;
    record(impulseTrace, q::inv_mass_b, b, r.invMassB, k);
    r.rotationalA = rotationalTerm(sa.Iinv, r.x_a, n);
    record(impulseTrace, q::rotational_a, a, r.rotationalA, k);
    r.rotationalB = rotationalTerm(sb.Iinv, r.x_b, n);
    record(impulseTrace, q::rotational_b, b, r.rotationalB, k);
    r.denominator = r.invMassA + r.invMassB + r.rotationalA + r.rotationalB;
    record(impulseTrace, q::denominator, a, r.denominator, k);
    if (r.separating || r.denominator <= 0.0) {
        // no impulse (a denominator <= 0 means two immovable sides: nothing can move)
        r.kineticBefore = r.kineticAfter = kinetic(A) + kinetic(B);
        return r;
    }
    record(trace, q::restitution, a, r.restitution, k);
    // T = sum over A, B of 1/2 M |v|^2 + 1/2 omega . L
    r.kineticBefore = kinetic(A) + kinetic(B);
    record(trace, q::kinetic_energy_before, a, r.kineticBefore, k);

    // J = -(1 + c) (v_rel . n) / denominator
    r.numerator = -(1.0 + restitution) * r.v_rel_n;
    record(trace, q::numerator, a, r.numerator, k);
    r.J = r.numerator / r.denominator;
    record(trace, q::impulse, a, r.J, k);
    applyImpulse(A, r.x_a, r.J * n, r.dv_A, r.dL_A);
    applyImpulse(B, r.x_b, Vec3(-r.J * n), r.dv_B, r.dL_B);

    // Coulomb friction: a tangential impulse against the sliding velocity after the
    // normal impulse, clamped to mu J.
    if (mu > 0.0) {
        record(trace, q::friction_coefficient, a, r.mu, k);
        const Side a2 = sideOf(A);
        const Side b2 = sideOf(B);
        const Vec3 v_rel2 = (a2.v + a2.omega.cross(r.x_a)) - (b2.v + b2.omega.cross(r.x_b));
        const Vec3 v_t = v_rel2 - v_rel2.dot(n) * n;
        const double speed_t = v_t.norm();
        record(trace, q::tangent_speed, a, speed_t, k);
        if (speed_t > 1e-12 * std::max(1.0, v_rel2.norm())) {
            r.t_W = -v_t / speed_t;   // friction opposes sliding
            record(trace, q::friction_direction, a, r.t_W, k);
            const double k_t = a2.invM + b2.invM + rotationalTerm(a2.Iinv, r.x_a, r.t_W) +
                               rotationalTerm(b2.Iinv, r.x_b, r.t_W);
            record(trace, q::tangent_denominator, a, k_t, k);
            // J_t* = -(v_rel' . t) / k_t = speed_t / k_t stops the sliding exactly
            const double J_t_stop = speed_t / k_t;
            r.J_t = std::min(J_t_stop, mu * r.J);
            r.frictionClamped = J_t_stop > mu * r.J;
            r.frictionImpulse_W = r.J_t * r.t_W;
            applyImpulse(A, r.x_a, r.frictionImpulse_W, r.dv_A, r.dL_A);
            applyImpulse(B, r.x_b, Vec3(-r.frictionImpulse_W), r.dv_B, r.dL_B);
        }
        // J_t t, and whether it slides (J_t* > mu J)
        record(trace, q::friction_impulse, a, r.frictionImpulse_W, k);
        record(trace, q::sliding, a, r.frictionClamped ? 1.0 : 0.0, k);
    }

    // The changes of A: dv_A = (J n + J_t t)/M_A, dL_A = x_a x (J n + J_t t), and its new v, L, omega
    record(trace, q::delta_v_a, a, r.dv_A, k);
    record(trace, q::delta_L_a, a, r.dL_A, k);
    record(trace, q::linear_velocity_a, a, A.state->v_W, k);
    record(trace, q::angular_momentum_a, a, A.state->L_W, k);
    record(trace, q::angular_velocity_a, a, A.state->omega_W, k);
    if (b >= 0 && B.invM() != 0.0) {
        // and of B, with the opposite impulse
        record(trace, q::delta_v_b, b, r.dv_B, k);
        record(trace, q::delta_L_b, b, r.dL_B, k);
        record(trace, q::linear_velocity_b, b, B.state->v_W, k);
        record(trace, q::angular_momentum_b, b, B.state->L_W, k);
        record(trace, q::angular_velocity_b, b, B.state->omega_W, k);
    }
    // T' after both impulses
    r.kineticAfter = kinetic(A) + kinetic(B);
    record(trace, q::kinetic_energy_after, a, r.kineticAfter, k);
    return r;
}

} // namespace rbw
