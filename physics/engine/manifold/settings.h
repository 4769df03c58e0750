// Settings of the manifold contact model (contact_model "manifold", docs/collisions.md):
// what the scene chooses (iterations, sleeping, the position fix) and the fixed
// tolerances of the solver, with their sources.
//
// Glossary
//   iterations         velocity iterations of the sequential-impulse solver         [-]
//   normalSweeps       passes over one manifold's normal rows in each iteration,
//                      before its friction rows: its points share two bodies, and
//                      one pass leaves an order-dependent residual that rocks stacks
//                      (docs/collisions.md, "Tall stacks")                            [-]
//   margin             speculative margin: points up to this far apart are kept, so
//                      a body approaching a surface is stopped at it in time         [m]
//   slop               overlap the position fix leaves (Box2D b2_linearSlop)         [m]
//   beta               fraction of the overlap removed per position iteration
//                      (Box2D b2_baumgarte)                                          [-]
//   maxCorrection      most a position iteration moves a point (b2_maxLinearCorrection) [m]
//   positionTolerance  the position iterations stop when no point is deeper than this
//                      (Box2D: 3 slop; here the slop itself, see docs/collisions.md)  [m]
//   convergence        the velocity iterations stop early when no accumulated impulse
//                      changed by more than this in an iteration                     [N s]
//   sleepLinear, sleepAngular   a body is at rest below these speeds (Box2D
//                      b2_linearSleepTolerance, b2_angularSleepTolerance)            [m/s], [rad/s]
//   maxPoints          points kept per box-box manifold (reduceManifold; 8: all)
//   timeToSleep        an island sleeps when all its bodies rested this long
//                      (b2_timeToSleep)                                              [s]
//   solver             sequential impulses (contact_solver.h) or the soft step
//                      (soft_step_solver.h)                                          [-]
//   substeps           the soft step's substeps per step                             [-]
//   contactHertzPerSubstepRate  the soft contacts' frequency f over the substep rate
//                      1/h_s (f = 1/(8 h_s): Box2D's cap on contactHertz)           [-]
//   contactDampingRatio  the soft contacts' damping ratio (Box2D's)                  [-]
//   maxPushOut         the soft contacts' fastest push-out (Box2D contactSpeed)      [m/s]
#pragma once

#include "physics/engine/scene.h"

#include <vector>

namespace rbw {

struct ManifoldSettings {
    int iterations = 10;
    int normalSweeps = 3;
    bool sleep = true;
    PositionFix positionFix = PositionFix::Ngs;
    double margin = 0.02;
    double slop = 0.005;
    double beta = 0.2;
    double maxCorrection = 0.2;
    int positionIterations = 3;
    double positionTolerance = 0.005;
    int maxPoints = 8;   // points kept per box pair (of up to 8 clipped; box_box_clip.h)
    double convergence = 1e-9;
    double sleepLinear = 0.01;
    double sleepAngular = 2.0 * 3.14159265358979323846 / 180.0;
    double timeToSleep = 0.5;
    // The soft step (soft_step_solver.h; Box2D v3 b2DefaultWorldDef: contactHertz 30,
    // contactDampingRatio 10, contactSpeed 3 m/s, 4 substeps), the default solver since
    // it rests the 1000-box rain where the sequential impulses do not, in half their
    // time (docs/collisions.md, "The soft step")
    ManifoldSolver solver = ManifoldSolver::SoftStep;
    // 5 substeps and f = 1/(8 h_s), 37.5 Hz at h = 1/60 s: a soft contact sags under
    // the weight it carries, s = F / (m_n omega^2) per point, and in the rain's columns
    // of 10 the lowest contacts sagged 1.12 cm at Box2D's 30 Hz (4 substeps; with more
    // stiffness per substep than f = 1/(8 h_s) the piles jitter). docs/collisions.md,
    // "The soft step: how deep a column sinks".
    int substeps = 5;
    double contactHertzPerSubstepRate = 0.125;   // [-]: f = 0.125 / h_s
    double contactDampingRatio = 10.0;   // [-]
    double maxPushOut = 3.0;             // [m/s]: the fastest a soft contact pushes overlap out
};

// The scene's choices, the rest at their defaults.
ManifoldSettings manifoldSettings(const SceneDef& scene);

// validate()'s rules for the contact-model keys: the manifold model's keys only with
// it, the course model's correction switches only with the course model, and
// 1 <= solver_iterations <= 1000.
void checkContactModel(std::vector<SceneIssue>& out, const SceneDef& scene);

} // namespace rbw
