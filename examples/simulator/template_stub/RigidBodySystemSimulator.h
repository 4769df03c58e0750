// A stand-in for the TUM template's Simulations/RigidBodySystemSimulator.h, only so
// that tum_template_adapter.cpp can be compiled and run on Linux without DirectX.
// It is NOT the template: it declares just what the adapter uses, with the template's
// signatures (GamePhysicsTUM/gamephysicstemplate, branch Ex2):
//   - vector3Dim<Scalar> with members x, y, z and a constructor (x, y, z);
//   - Quaternion<Scalar> with members x, y, z, w and the constructor
//     Quaternion(x, y, z, w): the scalar part comes LAST (util/quaternion.h);
//   - Real = double (the template's default, FLOATINGPOINT_PRECISION 2);
//   - Simulator::m_iTestCase, TESTCASEUSEDTORUNTEST = 2;
//   - the rigid-body functions, e.g. addRigidBody(Vec3, Vec3, int) and
//     simulateTimestep(float). The GUI functions (initUI, drawFrame) are left out.
// RigidBodySystemSimulator.cpp next to this file implements the class with the
// reference simulator, so the adapter's output can be checked (selfcheck.sh).
#ifndef RIGIDBODYSYSTEMSIMULATOR_h
#define RIGIDBODYSYSTEMSIMULATOR_h

#include <cmath>
#include <memory>

namespace GamePhysics {

typedef double Real;

template <class Scalar>
class vector3Dim {
public:
    vector3Dim() : x(0), y(0), z(0) {}
    vector3Dim(Scalar s1, Scalar s2, Scalar s3) : x(s1), y(s2), z(s3) {}
    Scalar x, y, z;
};

template <class Scalar>
class Quaternion {
public:
    Scalar x, y, z, w;
    Quaternion() : x(0), y(0), z(0), w(0) {}
    Quaternion(Scalar nx, Scalar ny, Scalar nz, Scalar nw) : x(nx), y(ny), z(nz), w(nw) {}
    Quaternion(const vector3Dim<Scalar>& axis, Scalar angle)
    {
        const Scalar mult = std::sin(angle * .5);
        x = axis.x * mult;
        y = axis.y * mult;
        z = axis.z * mult;
        w = std::cos(angle * .5);
    }
};

typedef vector3Dim<Real> Vec3;
typedef Quaternion<Real> Quat;

}   // namespace GamePhysics

using namespace GamePhysics;

#define TESTCASEUSEDTORUNTEST 2

class Simulator {
public:
    virtual ~Simulator() = default;
    int m_iTestCase = 0;
};

struct RigidBodySystemSimulatorState;   // the reference simulator behind the stub

class RigidBodySystemSimulator : public Simulator {
public:
    RigidBodySystemSimulator();
    ~RigidBodySystemSimulator() override;

    const char* getTestCasesStr();
    void reset();
    void notifyCaseChanged(int testCase);
    void externalForcesCalculations(float timeElapsed);
    void simulateTimestep(float timeStep);
    void onClick(int x, int y);
    void onMouse(int x, int y);

    int getNumberOfRigidBodies();
    Vec3 getPositionOfRigidBody(int i);
    Vec3 getLinearVelocityOfRigidBody(int i);
    Vec3 getAngularVelocityOfRigidBody(int i);
    void applyForceOnBody(int i, Vec3 loc, Vec3 force);
    void addRigidBody(Vec3 position, Vec3 size, int mass);
    void setOrientationOf(int i, Quat orientation);
    void setVelocityOf(int i, Vec3 velocity);

private:
    std::unique_ptr<RigidBodySystemSimulatorState> m_state;
};

#endif
