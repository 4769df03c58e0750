// The mistake models only a simulator shows, over several steps (issue 21 item 1;
// MistakeInfo::oneStep false): what it stores between steps enters the hand step
// through BodyStepInputs (IinvStored_W, keptF_W, keptq_W, orientationSet), as the probes'
// replay gives it (physics/workbook/probes/simulator_state.h). Hand derivations per test.
//
// Table 2.1's box (a, b, c = 1, 0.6, 0.5, M = 2): I0^-1 = diag(9.836066, 4.8, 4.411765).
#include "tests/test_support.h"

#include "physics/workbook/checker/mistakes.h"
#include "physics/engine/quantities.h"

#include <QtTest>

using rbw::Mistake;
using rbw::Quat;
using rbw::Vec3;

namespace {

const double kA = 1.0 / (0.61 / 6.0), kB = 4.8, kC = 1.0 / (1.36 / 6.0);   // I0^-1 = diag(a, b, c)

rbw::BodyStepInputs box()
{
    rbw::BodyStepInputs in;
    in.mass = 2.0;
    in.size = Vec3(1, 0.6, 0.5);
    return in;
}

QList<double> valueOf(const rbw::HandEulerStep& s, const char* id)
{
    rbw::TraceValue v;
    if (!s.value(id, -1, v)) qFatal("no %s in the hand step", id);
    return rbw::test::flatten(v);
}

void expectNear(const QList<double>& got, const QList<double>& want)
{
    const QString m = rbw::test::mismatch(got, want, 2e-6);
    QVERIFY2(m.isEmpty(), qPrintable(m));
}

// A later step (not the body's first) of the box at r = Rz(90) = (s, 0, 0, s), at rest
// (L = 0, omega = 0, so r stays), with a couple (1, 0, 0) and h = 0.1: L' = (0.1, 0, 0).
// The right I^-1 = Rz(90) diag(a, b, c) Rz(90)^T = diag(b, a, c): omega' = (0.48, 0, 0).
rbw::BodyStepInputs turnedAtRest()
{
    rbw::BodyStepInputs in = box();
    in.h = 0.1;
    in.q_WB = Quat(std::sqrt(0.5), 0, 0, std::sqrt(0.5));
    in.couple_W = Vec3(1, 0, 0);
    in.firstStep = false;
    in.omega_W = Vec3::Zero();
    return in;
}

} // namespace

class TestSimulatorMistakes : public QObject {
    Q_OBJECT
private slots:
    void rightStep() { expectNear(valueOf(rbw::handEulerStep(turnedAtRest()), "angular_velocity"), {0.48, 0, 0}); }

    // inertia-not-updated: the tensor stored at the body's first step, at r = 1: diag(a, b, c);
    // omega' = (0.1 a, 0, 0) = (0.983607, 0, 0). Negative control: at the body's first step it is
    // computed from r_n, which here is the step's r: the right omega'.
    void inertiaNotUpdated()
    {
        rbw::BodyStepInputs in = turnedAtRest();
        in.IinvStored_W = Vec3(kA, kB, kC).asDiagonal();
        expectNear(valueOf(rbw::handEulerStep(in, Mistake::InertiaNotUpdated), "angular_velocity"), {0.983607, 0, 0});
        in.firstStep = true;
        expectNear(valueOf(rbw::handEulerStep(in, Mistake::InertiaNotUpdated), "angular_velocity"), {0.48, 0, 0});
    }

    // inertia-accumulated-rotation: last step's world tensor diag(b, a, c) (at Rz(90)) turned
    // again by Rz(90): diag(a, b, c), 180 deg in all; omega' = (0.983607, 0, 0). Unset, the
    // stored tensor is the one of r_n, R_n I0^-1 R_n^T: the same here. Negative control: a
    // stored I0^-1 (a body whose tensor was never turned) gives the right step.
    void inertiaAccumulatedRotation()
    {
        rbw::BodyStepInputs in = turnedAtRest();
        expectNear(valueOf(rbw::handEulerStep(in, Mistake::InertiaAccumulatedRotation), "angular_velocity"),
                   {0.983607, 0, 0});
        in.IinvStored_W = Vec3(kB, kA, kC).asDiagonal();
        expectNear(valueOf(rbw::handEulerStep(in, Mistake::InertiaAccumulatedRotation), "inverse_inertia_world"),
                   {kA, 0, 0, 0, kB, 0, 0, 0, kC});
        in.IinvStored_W = Vec3(kA, kB, kC).asDiagonal();
        expectNear(valueOf(rbw::handEulerStep(in, Mistake::InertiaAccumulatedRotation), "angular_velocity"),
                   {0.48, 0, 0});
    }

    // forces-not-cleared: Table 2.1's loads of step 0, F = (1, 1, 0), q = (-0.25, 0.25, -0.2),
    // kept into step 1 (no force of its own), h = 2, M = 2, v = 0, L = 0:
    // v' = h F/M = (1, 1, 0), L' = h q = (-0.5, 0.5, -0.4). Right: no load, v' = 0, L' = 0.
    void forcesNotCleared()
    {
        rbw::BodyStepInputs in = box();
        in.h = 2.0;
        in.firstStep = false;
        in.keptF_W = Vec3(1, 1, 0);
        in.keptq_W = Vec3(-0.25, 0.25, -0.2);
        const rbw::HandEulerStep wrong = rbw::handEulerStep(in, Mistake::ForcesNotCleared);
        expectNear(valueOf(wrong, "linear_velocity"), {1, 1, 0});
        expectNear(valueOf(wrong, "angular_momentum"), {-0.5, 0.5, -0.4});
        const rbw::HandEulerStep right = rbw::handEulerStep(in);
        expectNear(valueOf(right, "linear_velocity"), {0, 0, 0});
        expectNear(valueOf(right, "angular_momentum"), {0, 0, 0});
    }

    // gravity-always-on: Table 2.1 (f = (1, 1, 0), h = 2, M = 2, no gravity in the scene):
    // v' = h (f/M + g) = 2 ((0.5, 0.5, 0) + (0, -9.81, 0)) = (1, -18.62, 0). Right (1, 1, 0).
    void gravityAlwaysOn()
    {
        rbw::BodyStepInputs in = box();
        in.h = 2.0;
        in.forces = {{Vec3(0.3, 0.5, 0.25), Vec3(1, 1, 0)}};
        expectNear(valueOf(rbw::handEulerStep(in, Mistake::GravityAlwaysOn), "linear_velocity"), {1, -18.62, 0});
        expectNear(valueOf(rbw::handEulerStep(in), "linear_velocity"), {1, 1, 0});
    }

    // orientation-zero-quaternion: the box spinning about x (omega0 = (10, 0, 0), L =
    // (1.016667, 0, 0)), a couple (0, 1, 0), h = 0.1, orientation never set: r = 0 stays 0
    // ((0, omega) 0 = 0, nothing to normalise), R(0) = E, so I^-1 = I0^-1 and omega' =
    // (a L_x, 0.1 b, 0) = (10, 0.48, 0). Right (tst_mistakes' spinningAboutX): r' =
    // (0.894427, 0.447214, 0, 0), omega' = (10, 0.455153, 0.018635). Negative control: a body
    // whose orientation was set is stepped right.
    void orientationZeroQuaternion()
    {
        rbw::BodyStepInputs in = box();
        in.h = 0.1;
        in.couple_W = Vec3(0, 1, 0);
        in.L_W = Vec3(0.61 / 6.0 * 10.0, 0, 0);
        in.orientationSet = false;
        const rbw::HandEulerStep wrong = rbw::handEulerStep(in, Mistake::OrientationZeroQuaternion);
        expectNear(valueOf(wrong, "orientation"), {0, 0, 0, 0});
        expectNear(valueOf(wrong, "angular_velocity"), {10, 0.48, 0});
        in.orientationSet = true;
        const rbw::HandEulerStep set = rbw::handEulerStep(in, Mistake::OrientationZeroQuaternion);
        expectNear(valueOf(set, "orientation"), {0.894427, 0.447214, 0, 0});
        expectNear(valueOf(set, "angular_velocity"), {10, 0.455153, 0.018635});
    }

    // These are exactly the models the catalogue marks as seen only over several steps.
    void severalStepModelsAreMarked()
    {
        QStringList marked;
        for (const rbw::MistakeInfo& m : rbw::mistakeCatalogue()) {
            if (!m.oneStep) marked << QString::fromLatin1(m.id);
        }
        QCOMPARE(marked, (QStringList{"inertia-not-updated", "inertia-accumulated-rotation", "forces-not-cleared",
                                      "gravity-always-on", "orientation-zero-quaternion"}));
    }
};

QTEST_APPLESS_MAIN(TestSimulatorMistakes)
#include "tst_simulator_mistakes.moc"
