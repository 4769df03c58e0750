// The stand-in RigidBodySystemSimulator (see RigidBodySystemSimulator.h here): each
// function forwards to the reference simulator, so tum_template_adapter.cpp built
// against this stub must print what reference_simulator prints (selfcheck.sh).
// Like many students' code it also prints debug text to stdout in every step, which
// the adapter must keep out of its answers.
#include "RigidBodySystemSimulator.h"

#include <cstdio>
#include <iostream>

#include "../reference_simulator.h"

struct RigidBodySystemSimulatorState {
    rbwref::ReferenceSimulator<Real> sim{rbwref::Mistakes{}, Real(0.5), false};
};

namespace {

rbwref::Vec3<Real> toRef(const Vec3& v) { return {v.x, v.y, v.z}; }

}   // namespace

RigidBodySystemSimulator::RigidBodySystemSimulator() : m_state(new RigidBodySystemSimulatorState) {}
RigidBodySystemSimulator::~RigidBodySystemSimulator() = default;

const char* RigidBodySystemSimulator::getTestCasesStr() { return "Stub"; }
void RigidBodySystemSimulator::reset() {}
void RigidBodySystemSimulator::notifyCaseChanged(int testCase) { m_iTestCase = testCase; }
void RigidBodySystemSimulator::externalForcesCalculations(float) {}
void RigidBodySystemSimulator::onClick(int, int) {}
void RigidBodySystemSimulator::onMouse(int, int) {}

void RigidBodySystemSimulator::simulateTimestep(float timeStep)
{
    // A chatty student: both kinds of stdout output.
    std::printf("debug: simulateTimestep(%g)\n", timeStep);
    std::cout << "debug: " << getNumberOfRigidBodies() << " bodies" << std::endl;
    m_state->sim.step(Real(timeStep));
}

int RigidBodySystemSimulator::getNumberOfRigidBodies() { return m_state->sim.bodyCount(); }

Vec3 RigidBodySystemSimulator::getPositionOfRigidBody(int i)
{
    const auto s = m_state->sim.state(i);
    return Vec3(s[0], s[1], s[2]);
}

Vec3 RigidBodySystemSimulator::getLinearVelocityOfRigidBody(int i)
{
    const auto s = m_state->sim.state(i);
    return Vec3(s[3], s[4], s[5]);
}

Vec3 RigidBodySystemSimulator::getAngularVelocityOfRigidBody(int i)
{
    const auto s = m_state->sim.state(i);
    return Vec3(s[6], s[7], s[8]);
}

void RigidBodySystemSimulator::applyForceOnBody(int i, Vec3 loc, Vec3 force)
{
    m_state->sim.applyForce(i, toRef(loc), toRef(force));
}

void RigidBodySystemSimulator::addRigidBody(Vec3 position, Vec3 size, int mass)
{
    m_state->sim.addBody(toRef(position), toRef(size), Real(mass));
}

void RigidBodySystemSimulator::setOrientationOf(int i, Quat orientation)
{
    // The reference simulator's quaternion is (w, x, y, z).
    m_state->sim.setOrientation(i, {orientation.w, orientation.x, orientation.y, orientation.z});
}

void RigidBodySystemSimulator::setVelocityOf(int i, Vec3 velocity) { m_state->sim.setVelocity(i, toRef(velocity)); }
