#include "plascap/adapters/bullet_world.hpp"

#include <algorithm>

namespace plascap {

namespace {

std::unique_ptr<btSequentialImpulseConstraintSolver> make_solver(BulletSolverKind kind) {
    if (kind == BulletSolverKind::Bullet) return std::make_unique<btSequentialImpulseConstraintSolver>();
    return std::make_unique<BulletPlasticSolver>();
}

}  // namespace

BulletWorld::BulletWorld(const btVector3& gravity, int iterations, BulletSolverKind solver)
    : configuration_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(configuration_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(make_solver(solver)),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                        configuration_.get())) {
    if (solver == BulletSolverKind::Plascap) plascap_solver_ = static_cast<const BulletPlasticSolver*>(solver_.get());
    world_->setGravity(gravity);
    world_->getSolverInfo().m_numIterations = iterations;
    // Split-impulse turns at full rate: plascap's rows correct their rotations' drift by them.
    world_->getSolverInfo().m_splitImpulseTurnErp = 1.0;
}

BulletWorld::~BulletWorld() = default;

void BulletWorld::step(double dt) { world_->stepSimulation(dt, 0, dt); }

BulletBox::BulletBox(const btVector3& half, double mass, const btTransform& transform, const btVector3* given_inertia)
    : shape_(std::make_unique<btBoxShape>(half)), motion_(std::make_unique<btDefaultMotionState>(transform)) {
    // Bullet's default collision margin (0.04 m) lies inside the box: a box thinner than twice it
    // would collide as a different shape. Keep the margin within a fifth of the smallest half edge.
    shape_->setMargin(std::min<btScalar>(shape_->getMargin(), 0.2 * half[half.minAxis()]));
    btVector3 inertia(0, 0, 0);
    if (mass > 0.0) {
        if (given_inertia) inertia = *given_inertia;
        else shape_->calculateLocalInertia(mass, inertia);
    }
    body_ = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(mass, motion_.get(), shape_.get(), inertia));
    body_->setActivationState(DISABLE_DEACTIVATION);
}

BulletBox::~BulletBox() = default;

}  // namespace plascap
