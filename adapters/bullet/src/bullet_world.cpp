#include "plascap/adapters/bullet_world.hpp"

#include <algorithm>

#include "plascap/adapters/bullet_vec3.hpp"

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

void BulletWorld::step(double dt) {
    if (counting_contacts_) note_step_start();
    world_->stepSimulation(dt, 0, dt);
    if (counting_contacts_) contact_work_ += contact_work_of_step();
}

namespace {

BodyVelocity velocity_of(const btCollisionObject* object) {
    const btRigidBody* body = btRigidBody::upcast(object);
    return body ? body_velocity(*body) : BodyVelocity{};
}

}  // namespace

void BulletWorld::note_step_start() {
    const btCollisionObjectArray& objects = world_->getCollisionObjectArray();
    start_.resize(static_cast<std::size_t>(objects.size()));
    for (int i = 0; i < objects.size(); ++i)
        start_[static_cast<std::size_t>(i)] = {objects[i]->getWorldTransform().getOrigin(), velocity_of(objects[i])};
}

// Each contact point the solver used (within its manifold's processing threshold; the others keep an
// old impulse) gave body 0 the impulse P = n·λ + t1·λ1 + t2·λ2 at its point on body 0 and body 1 the
// opposite at its point on body 1 (btSequentialImpulseConstraintSolver's convention: the normal on B
// pushes A), with lever arms from the centres at the step's start, where the solver took them.
double BulletWorld::contact_work_of_step() const {
    double work = 0.0;
    btDispatcher* dispatcher = world_->getDispatcher();
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
        const btCollisionObject* object[2] = {manifold->getBody0(), manifold->getBody1()};
        const std::size_t index[2] = {static_cast<std::size_t>(object[0]->getWorldArrayIndex()),
                                      static_cast<std::size_t>(object[1]->getWorldArrayIndex())};
        if (index[0] >= start_.size() || index[1] >= start_.size()) continue;  // added during the step
        const BodyVelocity end[2] = {velocity_of(object[0]), velocity_of(object[1])};
        for (int p = 0; p < manifold->getNumContacts(); ++p) {
            const btManifoldPoint& point = manifold->getContactPoint(p);
            if (point.getDistance() > manifold->getContactProcessingThreshold()) continue;
            const btVector3 impulse = point.m_normalWorldOnB * point.m_appliedImpulse +
                                      point.m_lateralFrictionDir1 * point.m_appliedImpulseLateral1 +
                                      point.m_lateralFrictionDir2 * point.m_appliedImpulseLateral2;
            const btVector3 at[2] = {point.getPositionWorldOnA(), point.getPositionWorldOnB()};
            for (int k = 0; k < 2; ++k) {
                const btVector3 on_body = k == 0 ? impulse : -impulse;
                const BodyStart& start = start_[index[k]];
                work += impulse_work(to_vec3(on_body), to_vec3((at[k] - start.centre).cross(on_body)), start.velocity, end[k]);
            }
        }
    }
    return work;
}

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
