#include "physics/engine/manifold/manifold_contact_stage.h"

#include "physics/engine/manifold/box_box_clip.h"
#include "physics/engine/manifold/box_plane_manifold.h"
#include "physics/engine/manifold/contact_axis.h"
#include "physics/engine/manifold/work_limits.h"
#include "physics/engine/quantities.h"
#include "physics/engine/course/contact_response.h"
#include "physics/engine/scene_words.h"

#include <algorithm>
#include <functional>

namespace rbw {

namespace {

bool awakeMovable(const StepContext& ctx, int b)
{
    return ctx.movable[static_cast<std::size_t>(b)] && !ctx.contacts.sleep.asleep(b);
}

// The soft step's points from which lanes pay for waking the second thread (the
// rain's 1000 boxes have some 4000; a lesson's few boxes stay on one thread), and the
// lanes then: the caller runs the first half, the worker the second (the same lanes on
// the same core from step to step: lanes handed out to whoever is free change core and
// were slower, 1.55 against 1.11 ms/step), and each takes over what the other has not
// started (solver_worker.h), so a worker slowed by another process on its core holds
// back at most one lane.
constexpr int kPointsForTwoLanes = 256;
constexpr int kLanes = 8;

int pointCount(const std::vector<Manifold>& manifolds)
{
    int points = 0;
    for (const Manifold& m : manifolds) points += m.count;
    return points;
}

bool sleepingBody(const StepContext& ctx, int b)
{
    return ctx.movable[static_cast<std::size_t>(b)] && ctx.contacts.sleep.asleep(b);
}

} // namespace

void ManifoldContactStage::run(StepContext& ctx)
{
    ContactScratch& w = *world_;
    // What this step starts from beside the bodies (the warm-start impulses, who sleeps)
    // is the world's state, ctx.contacts: nothing here depends on earlier steps.
    if (w.settings.sleep) wakeLoadedBodies(ctx);
    findManifolds(ctx);
    if (!ctx.status.ok) return;   // a work limit was exceeded (work_limits.h)
    solve(ctx);
    if (ctx.trace != nullptr) recordPoints(ctx);
    // Keep the impulses of this step's manifolds, and of the sleeping pairs not solved.
    ctx.contacts.cache.store(w.manifolds, [&ctx](std::uint64_t key) {
        const ManifoldKeyParts pair = decodeManifoldKey(key);
        const int a = pair.a;
        const int b = pair.b;
        if (a >= static_cast<int>(ctx.states.size()) || b >= static_cast<int>(ctx.states.size())) return false;
        const bool sleepingA = sleepingBody(ctx, a);
        return sleepingA && (b < 0 || !awakeMovable(ctx, b));
    }, w.cacheSpare);
}

void ManifoldContactStage::wakeLoadedBodies(StepContext& ctx)
{
    for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
        if (!sleepingBody(ctx, b)) continue;
        const BodyState& s = ctx.states[static_cast<std::size_t>(b)];
        // A sleeping body has v = L = 0 and no load but its weight M g; anything else
        // (a drag, a push, a force of the scene, a restored moving state) wakes it.
        const Vec3 weight_W = ctx.mass[static_cast<std::size_t>(b)].M * ctx.scene.g_W;
        const BodyLoad& load = ctx.loads[static_cast<std::size_t>(b)];
        if (s.v_W != Vec3::Zero() || s.L_W != Vec3::Zero() || load.F_W != weight_W || load.q_W != Vec3::Zero()) {
            ctx.contacts.sleep.wake(b);
        }
    }
}

bool ManifoldContactStage::collidePair(StepContext& ctx, int a, int b)
{
    ContactScratch& w = *world_;
    Manifold& m = w.manifolds.emplace_back();
    if (!collideBoxBoxManifold(poseOf(ctx, a), poseOf(ctx, b), w.settings.margin, m, w.settings.maxPoints)) {
        w.manifolds.pop_back();
        return false;
    }
    m.a = a;
    m.b = b;
    m.plane = -1;
    m.mu = ctx.scene.frictionFor(a, b, -1);
    m.restitution = ctx.scene.restitutionFor(a, b, -1);
    ctx.contacts.cache.warmStart(m);
    return true;
}

bool ManifoldContactStage::findPairs(StepContext& ctx, long& tested)
{
    ContactScratch& w = *world_;
    const int n = static_cast<int>(ctx.states.size());
    BroadPhaseStats& stats = ctx.scratch.broadPhase;
    // The caps that keep a step linear in the bodies (work_limits.h); beyond one the
    // step stops with the limit named.
    const int movableBodies =
        static_cast<int>(std::count_if(ctx.movable.begin(), ctx.movable.end(), [](char m) { return m != 0; }));
    const PairLimits limits = manifoldPairLimits(movableBodies);
    // Sleeping bodies stay out of the tree (a pair of two is never solved): they are
    // only tested against it, for an awake body that would wake them.
    w.resting.resize(static_cast<std::size_t>(n));
    bool anyResting = false;
    for (int b = 0; b < n; ++b) {
        const bool rests = w.settings.sleep && sleepingBody(ctx, b);
        w.resting[static_cast<std::size_t>(b)] = rests ? 1 : 0;
        anyResting = anyResting || rests;
    }
    w.broadPhase.findPairs(w.aabbs, ctx.movable, w.pairs, stats, limits, anyResting ? &w.resting : nullptr);
    tested += stats.pairsTested;
    w.pairDone.assign(w.pairs.size(), 0);
    if (stats.limitHit == PairLimitHit::None) return true;
    ctx.status = workLimitStatus(ctx.scene, ctx.k, limits, stats);
    return false;
}

// A sleeping body touched by an awake movable one wakes with its island; repeated until
// no more wake, since a woken body may touch another sleeping one. True if any woke.
bool ManifoldContactStage::wakeTouched(StepContext& ctx)
{
    ContactScratch& w = *world_;
    bool any = false;
    bool woke = w.settings.sleep;
    while (woke) {
        woke = false;
        for (std::size_t i = 0; i < w.pairs.size(); ++i) {
            if (w.pairDone[i]) continue;
            const auto [a, b] = w.pairs[i];
            const bool wakesB = awakeMovable(ctx, a) && sleepingBody(ctx, b);
            const bool wakesA = awakeMovable(ctx, b) && sleepingBody(ctx, a);
            if (!wakesA && !wakesB) continue;
            w.pairDone[i] = 1;
            if (collidePair(ctx, a, b)) {
                ctx.contacts.sleep.wake(wakesB ? b : a);
                woke = true;
                any = true;
            }
        }
    }
    return any;
}

void ManifoldContactStage::findManifolds(StepContext& ctx)
{
    ContactScratch& w = *world_;
    const int n = static_cast<int>(ctx.states.size());
    const double margin = w.settings.margin;
    w.manifolds.clear();
    if (boxPairs_) {
        // AABBs grown by the speculative margin, so pairs about to touch are found.
        w.aabbs.resize(static_cast<std::size_t>(n));
        for (int b = 0; b < n; ++b) {
            Aabb box = boxAabb(poseOf(ctx, b));
            box.min_W -= Vec3::Constant(margin);
            box.max_W += Vec3::Constant(margin);
            w.aabbs[static_cast<std::size_t>(b)] = box;
        }
        // The pairs with a body awake at the start (sleeping ones stay out of the tree);
        // the islands they touch wake, and if any did, the pairs again with them awake,
        // so that a woken island's own contacts are solved in this step too.
        long tested = 0;
        if (!findPairs(ctx, tested)) return;
        if (wakeTouched(ctx)) {
            w.pairsBefore.swap(w.pairs);
            w.pairDoneBefore.swap(w.pairDone);
            if (!findPairs(ctx, tested)) return;
            // A pair collided before the broad phase ran again is done: both lists are sorted
            for (std::size_t i = 0, j = 0; i < w.pairs.size() && j < w.pairsBefore.size();) {
                if (w.pairsBefore[j] < w.pairs[i]) {
                    ++j;
                } else {
                    if (w.pairsBefore[j] == w.pairs[i]) w.pairDone[i] = w.pairDoneBefore[j];
                    ++i;
                }
            }
            wakeTouched(ctx);
        }
        record(ctx.trace, q::pairs_tested, -1, double(tested));
        record(ctx.trace, q::pairs_overlapping, -1, double(w.pairs.size()));
        // Every other pair with an awake movable body; pairs of sleeping (or fixed)
        // bodies are left alone, their impulses kept for when they wake.
        for (std::size_t i = 0; i < w.pairs.size(); ++i) {
            if (w.pairDone[i]) continue;
            const auto [a, b] = w.pairs[i];
            if (awakeMovable(ctx, a) || awakeMovable(ctx, b)) collidePair(ctx, a, b);
        }
    }
    if (planes_) {
        for (int p = 0; p < static_cast<int>(ctx.scene.planes.size()); ++p) {
            for (int b = 0; b < n; ++b) {
                if (!awakeMovable(ctx, b)) continue;
                Manifold& m = w.manifolds.emplace_back();
                if (!collideBoxPlaneManifold(poseOf(ctx, b), ctx.scene.planes[static_cast<std::size_t>(p)], margin, m)) {
                    w.manifolds.pop_back();
                    continue;
                }
                m.a = b;
                m.b = -1;
                m.plane = p;
                m.mu = ctx.scene.frictionFor(b, -1, p);
                m.restitution = ctx.scene.restitutionFor(b, -1, p);
                ctx.contacts.cache.warmStart(m);
            }
        }
    }
}

void ManifoldContactStage::solve(StepContext& ctx)
{
    ContactScratch& w = *world_;
    const int n = static_cast<int>(ctx.states.size());
    const double h = ctx.scene.dt;
    w.bodies.resize(static_cast<std::size_t>(n + 1));   // every entry is set below
    for (int b = 0; b <= n; ++b) {
        SolverBody& sb = w.bodies[static_cast<std::size_t>(b)];
        sb = SolverBody{};
        if (b == n || !awakeMovable(ctx, b)) continue;   // static: fixed, asleep, the planes' body
        const BodyState& s = ctx.states[static_cast<std::size_t>(b)];
        const MassProperties& mp = ctx.mass[static_cast<std::size_t>(b)];
        const BodyLoad& load = ctx.loads[static_cast<std::size_t>(b)];
        sb.invM = mp.invM;
        sb.Iinv_W = ctx.scene.bodies[static_cast<std::size_t>(b)].angularResponse ? s.Iinv_W : Mat3::Zero();
        // The free velocities: v* = v + h F / M, omega* = omega + h I^-1 q
        sb.v_W = s.v_W + (h * mp.invM) * load.F_W;
        sb.omega_W = s.omega_W + h * (s.Iinv_W * load.q_W);
    }
    if (w.settings.solver == ManifoldSolver::SoftStep) {
        solveSoftStep(ctx);
    } else {
        solveSequentialImpulses(ctx);
    }
    // The impulses become loads of the integration: F_c = P / h, q_c = L_c / h.
    for (int b = 0; b < n; ++b) {
        if (!ctx.movable[static_cast<std::size_t>(b)]) continue;
        BodyLoad& load = ctx.loads[static_cast<std::size_t>(b)];
        if (ctx.contacts.sleep.asleep(b)) {
            // Asleep: the support cancels every load, F_c = -F, q_c = -q.
            const Vec3 F_c = -load.F_W;
            record(ctx.trace, q::sleep_contact_force, b, F_c);
            const Vec3 q_c = -load.q_W;
            record(ctx.trace, q::sleep_contact_torque, b, q_c);
            load.F_W += F_c;
            load.q_W += q_c;
            continue;
        }
        const SolverBody& sb = w.bodies[static_cast<std::size_t>(b)];
        if (sb.P_W == Vec3::Zero() && sb.Lc_W == Vec3::Zero()) continue;
        // F_c = P / h
        record(ctx.trace, q::contact_impulse_sum, b, sb.P_W);
        const Vec3 F_c = sb.P_W / h;
        record(ctx.trace, q::contact_force, b, F_c);
        load.F_W += F_c;
        // A body without angular response is a particle for the contacts (its solver
        // body has I^-1 = 0): the impulses' moments do not turn it.
        if (!ctx.scene.bodies[static_cast<std::size_t>(b)].angularResponse) continue;
        // q_c = L_c / h
        record(ctx.trace, q::contact_moment_sum, b, sb.Lc_W);
        const Vec3 q_c = sb.Lc_W / h;
        record(ctx.trace, q::contact_torque, b, q_c);
        load.q_W += q_c;
    }
}

void ManifoldContactStage::solveSequentialImpulses(StepContext& ctx)
{
    ContactScratch& w = *world_;
    const int n = static_cast<int>(ctx.states.size());
    const double h = ctx.scene.dt;
    w.solver.prepare(w.manifolds, w.bodies, n, ctx.states, w.settings, h, ctx.scene.restitutionThreshold);
    w.solver.warmStart(w.bodies);
    // Sequential impulses: up to solver_iterations sweeps, stopping when no accumulated
    // impulse changed by more than the convergence tolerance in a sweep. With a trace,
    // every point's impulses after each iteration are kept (recordPoints).
    w.iterationsUsed = 0;
    for (int it = 1; it <= w.settings.iterations && !w.manifolds.empty(); ++it) {
        const double largest = w.solver.solve(w.bodies, w.settings.normalSweeps);
        if (ctx.trace != nullptr) w.solver.recordIteration();
        w.iterationsUsed = it;
        if (largest <= w.settings.convergence) break;
    }
    w.solver.store(w.manifolds, w.bodies);
    record(ctx.trace, q::solver_iterations_used, -1, double(w.iterationsUsed));
}

void ManifoldContactStage::solveSoftStep(StepContext& ctx)
{
    ContactScratch& w = *world_;
    const int n = static_cast<int>(ctx.states.size());
    const double h = ctx.scene.dt;
    const int substeps = w.settings.substeps;
    const double h_s = h / substeps;
    // The soft step starts from v, not from v + h F/M: each substep adds h_s F/M itself.
    // Its loads per body, a = F/M and alpha = I^-1 q (none for a body it does not move).
    w.motion.assign(static_cast<std::size_t>(n + 1), SubstepMotion{});
    w.moving.assign(static_cast<std::size_t>(n + 1), 0);
    for (int b = 0; b < n; ++b) {
        if (!awakeMovable(ctx, b)) continue;
        w.moving[static_cast<std::size_t>(b)] = 1;
        SolverBody& sb = w.bodies[static_cast<std::size_t>(b)];
        const BodyState& s = ctx.states[static_cast<std::size_t>(b)];
        const BodyLoad& load = ctx.loads[static_cast<std::size_t>(b)];
        SubstepMotion& m = w.motion[static_cast<std::size_t>(b)];
        m.a_W = ctx.mass[static_cast<std::size_t>(b)].invM * load.F_W;
        m.alpha_W = s.Iinv_W * load.q_W;
        sb.v_W = s.v_W;
        sb.omega_W = s.omega_W;
    }
    SoftStepSolver& solver = w.softSolver;
    // Lanes of whole islands shared by two threads when the step is worth it (not with a
    // trace, which records every point after each substep); the same bits either way.
    const bool twoThreads = w.threads >= 2 && ctx.trace == nullptr && pointCount(w.manifolds) >= kPointsForTwoLanes;
    solver.begin(w.manifolds, w.bodies, n, w.moving, w.settings, h_s, twoThreads ? kLanes : 1);
    const double threshold = ctx.scene.restitutionThreshold;
    int lanesWithWork = 0;
    for (int l = 0; l < solver.laneCount(); ++l) lanesWithWork += solver.lane(l).constraints.empty() ? 0 : 1;
    // What the integration gets: the step's impulses as loads (store(), then below); the
    // loads it spent in the substeps are the same F and q, so v_{n+1} = v + h (F + P/h) / M.
    if (lanesWithWork >= 2) {
        const std::function<void(int)> lane = [&w, &solver, &ctx, substeps, h_s, threshold](int l) {
            solver.prepare(w.manifolds, w.bodies, ctx.states, l);
            for (int i = 0; i < substeps; ++i) solver.substep(w.bodies, w.motion, h_s, l);
            solver.applyRestitution(w.bodies, threshold, l);
            solver.store(w.manifolds, w.bodies, l);
        };
        w.worker.run(solver.laneCount(), lane);
        ctx.scratch.contactLanes = solver.laneCount();
    } else {
        ctx.scratch.contactLanes = 1;
        for (int l = 0; l < solver.laneCount(); ++l) solver.prepare(w.manifolds, w.bodies, ctx.states, l);
        for (int i = 0; i < substeps; ++i) {
            for (int l = 0; l < solver.laneCount(); ++l) solver.substep(w.bodies, w.motion, h_s, l);
            if (ctx.trace != nullptr) solver.recordSubstep();
        }
        for (int l = 0; l < solver.laneCount(); ++l) {
            solver.applyRestitution(w.bodies, threshold, l);
            solver.store(w.manifolds, w.bodies, l);
        }
    }
    w.iterationsUsed = substeps;
    record(ctx.trace, q::soft_substep, -1, h_s);
    record(ctx.trace, q::soft_contact_hertz, -1, softContactHertz(w.settings.contactHertzPerSubstepRate, h_s));
    record(ctx.trace, q::soft_bias_rate, -1, solver.contactSoftness().biasRate);
    record(ctx.trace, q::soft_mass_scale, -1, solver.contactSoftness().massScale);
    record(ctx.trace, q::soft_impulse_scale, -1, solver.contactSoftness().impulseScale);
}

void ManifoldContactStage::recordPoints(StepContext& ctx) const
{
    const ContactScratch& w = *world_;
    const bool soft = w.settings.solver == ManifoldSolver::SoftStep;
    // The accumulated impulses after each iteration (sequential impulses) or substep (soft step)
    const std::vector<PointImpulses>& history = soft ? w.softSolver.history() : w.solver.history();
    const std::size_t stride = static_cast<std::size_t>(soft ? w.softSolver.pointCount() : w.solver.pointCount());
    const int planeBody = static_cast<int>(ctx.states.size());   // the solver's body for the planes
    int points = 0;
    for (const Manifold& m : w.manifolds) {
        for (int k = 0; k < m.count; ++k) {
            const ManifoldPoint& p = m.points[static_cast<std::size_t>(k)];
            const int i = ctx.scratch.contactCount++;
            ContactHeader& header = ctx.trace->contacts.emplace_back();
            header.bodyA = m.a;
            header.bodyB = m.b;
            header.plane = m.plane;
            header.feature = m.featureName();
            header.resolution = sceneWord(ContactModel::Manifold).data();   // scene_words.h, a literal
            header.pointCount = m.count;
            header.separating = p.lambda_n == 0.0;
            header.iteration = soft ? SoftStepSolver::kIteration : ContactSolver::kIteration;
            // The accumulated impulses after each velocity iteration (the solver's
            // history, ContactSolver::recordIteration), lambda_t = lambda_t1 t1 + lambda_t2 t2
            for (std::size_t it = 0; stride > 0 && (it + 1) * stride <= history.size(); ++it) {
                const PointImpulses& iterate = history[it * stride + static_cast<std::size_t>(points)];
                header.iterations.push_back(
                    ImpulseIterate{iterate.lambda_n, iterate.lambda_t1 * m.t1_W + iterate.lambda_t2 * m.t2_W});
            }
            // p, n, d and the feature id as the narrow phase computed them (m.where)
            ctx.trace->add(q::manifold_point, m.a, p.p_W, i, m.where);
            ctx.trace->add(q::manifold_normal, m.a, m.n_W, i, m.where);
            ctx.trace->add(q::manifold_depth, m.a, -p.separation, i, m.where);
            ctx.trace->add(q::feature_id, m.a, double(p.feature), i, m.where);
            // The solver's numbers (contact_solver.cpp: ContactSolver::prepare, warmStart,
            // ContactSolver::solve), accumulated over the iterations.
            record(ctx.trace, q::manifold_normal_velocity, m.a, p.normalVelocity, i);
            if (!soft) {
                const QuantityInfo& target = w.settings.positionFix == PositionFix::Baumgarte
                                                 ? q::target_normal_velocity_baumgarte
                                                 : q::target_normal_velocity;
                record(ctx.trace, target, m.a, p.v_target, i);
                // Which case applied (targetNormalVelocity): a bounce (v_n* > 0) shows its c; else
                // v_n* = min(0, d/h), d = -s (Baumgarte has its own formula and neither row)
                if (w.settings.positionFix != PositionFix::Baumgarte) {
                    if (p.v_target > 0.0) {
                        record(ctx.trace, q::restitution, m.a, m.restitution, i);
                    } else {
                        record(ctx.trace, q::gap_rate, m.a, -p.separation / ctx.scene.dt, i);
                    }
                }
            }
            // m_n = 1 / (1/M_A + 1/M_B + [.]_A + [.]_B), its terms (contact_axis.h)
            record(ctx.trace, q::r_A_W, m.a, p.r_A_W, i);
            record(ctx.trace, q::r_B_W, m.a, p.r_B_W, i);
            const SolverBody& A = w.bodies[static_cast<std::size_t>(m.a)];
            const SolverBody& B = w.bodies[static_cast<std::size_t>(m.b >= 0 ? m.b : planeBody)];
            record(ctx.trace, q::inv_mass_a, m.a, A.invM, i);
            record(ctx.trace, q::inv_mass_b, m.a, B.invM, i);
            const ContactAxis axis(p.r_A_W, p.r_B_W, m.n_W, A.Iinv_W, B.Iinv_W);
            record(ctx.trace, q::manifold_rotational_a, m.a, axis.rAxd_W.dot(axis.IArAxd_W), i);
            record(ctx.trace, q::manifold_rotational_b, m.a, axis.rBxd_W.dot(axis.IBrBxd_W), i);
            record(ctx.trace, q::normal_mass, m.a, p.m_n, i);
            record(ctx.trace, q::warm_start_normal, m.a, p.warm_n, i);
            record(ctx.trace, q::warm_start_tangent, m.a, p.warm_t_W, i);
            record(ctx.trace, soft ? q::soft_normal_impulse : q::normal_impulse, m.a, p.lambda_n, i);
            if (soft) record(ctx.trace, q::step_normal_impulse, m.a, p.P_n, i);
            // lambda_t = lambda_t1 t1 + lambda_t2 t2
            const Vec3 lambda_t_W = p.lambda_t1 * m.t1_W + p.lambda_t2 * m.t2_W;
            record(ctx.trace, q::tangent_impulse, m.a, lambda_t_W, i);
            ++points;
        }
    }
    record(ctx.trace, q::manifold_points, -1, double(points));
}

} // namespace rbw
