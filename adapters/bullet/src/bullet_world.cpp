#include "plascap/adapters/bullet_world.hpp"

namespace plascap {

BulletWorld::BulletWorld(const btVector3& gravity, int iterations)
    : configuration_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(configuration_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                        configuration_.get())) {
    world_->setGravity(gravity);
    world_->getSolverInfo().m_numIterations = iterations;
}

BulletWorld::~BulletWorld() = default;

void BulletWorld::step(double dt) { world_->stepSimulation(dt, 0, dt); }

BulletBox::BulletBox(const btVector3& half, double mass, const btTransform& transform)
    : shape_(std::make_unique<btBoxShape>(half)), motion_(std::make_unique<btDefaultMotionState>(transform)) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0.0) shape_->calculateLocalInertia(mass, inertia);
    body_ = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(mass, motion_.get(), shape_.get(), inertia));
    body_->setActivationState(DISABLE_DEACTIVATION);
}

BulletBox::~BulletBox() = default;

}  // namespace plascap
