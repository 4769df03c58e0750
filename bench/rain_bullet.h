// The box rain of rain_scene.h in Bullet 3.24 (Debian's libbullet-dev), one copy for
// bench_rain.cpp and bench_contact.cpp: btDiscreteDynamicsWorld with the default
// btSequentialImpulseConstraintSolver and btDbvtBroadphase, a btStaticPlaneShape ground,
// unit boxes of 1 kg, friction sqrt(0.5) per body (Bullet multiplies them: 0.5 per
// pair), restitution 0, no sleeping; and its boxes read back for rain::measure.
// Include only where RBW_HAVE_BULLET is defined.
#pragma once

#include "bench/rain_scene.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <vector>

namespace rain {

class BulletRain {
public:
    explicit BulletRain(const std::vector<RainBox>& poses)
        : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_)
    {
        world_.setGravity(btVector3(0.0, -9.81, 0.0));
        const btScalar friction = std::sqrt(0.5);
        ground_.setFriction(friction);
        ground_.setRestitution(0.0);
        world_.addRigidBody(&ground_);
        btVector3 inertia(0, 0, 0);
        boxShape_.calculateLocalInertia(1.0, inertia);
        for (const RainBox& r : poses) {
            const btTransform t(btQuaternion(r.q_WB.x(), r.q_WB.y(), r.q_WB.z(), r.q_WB.w()),
                                btVector3(r.x_W.x(), r.x_W.y(), r.x_W.z()));
            motions_.push_back(std::make_unique<btDefaultMotionState>(t));
            btRigidBody::btRigidBodyConstructionInfo info(1.0, motions_.back().get(), &boxShape_, inertia);
            bodies_.push_back(std::make_unique<btRigidBody>(info));
            bodies_.back()->setFriction(friction);
            bodies_.back()->setRestitution(0.0);
            bodies_.back()->setActivationState(DISABLE_DEACTIVATION);
            world_.addRigidBody(bodies_.back().get());
        }
    }
    BulletRain(const BulletRain&) = delete;
    BulletRain& operator=(const BulletRain&) = delete;
    ~BulletRain()
    {
        for (const std::unique_ptr<btRigidBody>& b : bodies_) world_.removeRigidBody(b.get());
        world_.removeRigidBody(&ground_);
    }

    // One step of h = kH
    void step() { world_.stepSimulation(kH, 1, kH); }

    std::vector<FinalBox> boxes() const
    {
        std::vector<FinalBox> out;
        for (const std::unique_ptr<btRigidBody>& b : bodies_) {
            const btTransform& t = b->getWorldTransform();
            const btQuaternion q = t.getRotation();
            const rbw::Quat q_WB(q.w(), q.x(), q.y(), q.z());
            const rbw::Vec3 x_W(t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z());
            const btVector3& v = b->getLinearVelocity();
            const btVector3& w = b->getAngularVelocity();
            out.push_back(FinalBox{rbw::BoxPose{x_W, q_WB.toRotationMatrix(), rbw::Vec3::Constant(0.5)},
                                   rbw::Vec3(v.x(), v.y(), v.z()), rbw::Vec3(w.x(), w.y(), w.z()),
                                   b->getActivationState() == ISLAND_SLEEPING});
        }
        return out;
    }

private:
    btDefaultCollisionConfiguration config_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    btSequentialImpulseConstraintSolver solver_;
    btDiscreteDynamicsWorld world_;
    btStaticPlaneShape groundShape_{btVector3(0, 1, 0), 0};
    btRigidBody ground_{0.0, nullptr, &groundShape_};
    btBoxShape boxShape_{btVector3(0.5, 0.5, 0.5)};
    std::vector<std::unique_ptr<btDefaultMotionState>> motions_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

} // namespace rain
