#include "plascap/adapters/bullet_plastic_joint.hpp"

#include <cmath>
#include <utility>

#include "bullet_six_dof_rows.hpp"

namespace plascap {
namespace {

// A Push row asks for a relative speed it can never reach, so the solver always ends on its bound:
// the force applied is exactly the bound (as Bullet's own Spring2 spring rows do).
constexpr double kPushSpeed = 1e9;  // [m/s or rad/s]

Vec3 to_vec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

BodyInertia inertia_of(const btRigidBody& body) {
    BodyInertia inertia;
    inertia.inverse_mass = body.getInvMass();
    const btMatrix3x3& i = body.getInvInertiaTensorWorld();
    for (int r = 0; r < 3; ++r) inertia.inverse_inertia_world[r] = {i[r].x(), i[r].y(), i[r].z()};
    inertia.centre = to_vec3(body.getCenterOfMassPosition());
    return inertia;
}

}  // namespace

template <class Constraint>
BasicBulletPlasticJoint<Constraint>::BasicBulletPlasticJoint(btRigidBody* a, btRigidBody& b,
                                                             const btTransform& frame_in_world,
                                                             const PlasticJointSettings& settings)
    : a_(a), b_(b), driver_(settings) {
    bullet_rows::emplace(constraint_, a, b, frame_in_world);
    constraint_->setJointFeedback(&feedback_);
    constraint_->enableFeedback(true);
    set_up_rows();
}

template <class Constraint>
BasicBulletPlasticJoint<Constraint>::~BasicBulletPlasticJoint() {
    detach();
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::set_up_rows() {
    for (Dof dof : kAllDofs) {
        const int i = static_cast<int>(index(dof));
        switch (driver_.law().mode(dof)) {
            case DofMode::Rigid:
                constraint_->setLimit(i, 0.0, 0.0);  // lo == hi: locked at the assembled position
                break;
            case DofMode::Free:
            case DofMode::Plastic:
                constraint_->setLimit(i, 1.0, -1.0);  // lo > hi: no limit row; a motor still acts
                break;
        }
        bullet_rows::set_motor(*constraint_, i, driver_.law().mode(dof) == DofMode::Plastic, 0.0, 0.0);
        constraint_->enableSpring(i, false);  // both constraints: never Bullet's own springs
    }
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::attach(btDynamicsWorld& world, double dt, double now) {
    const PerDof<double> x = positions();
    driver_.engage(x, now);
    for (Dof dof : kAllDofs) {  // rigid dofs lock where the joint takes hold
        const int i = static_cast<int>(index(dof));
        const double at = is_rotation(dof) ? -x[index(dof)] : x[index(dof)];  // Bullet's angle sign
        if (driver_.law().mode(dof) == DofMode::Rigid) bullet_rows::lock(*constraint_, i, at);
    }
    world_ = &world;
    world.addConstraint(&*constraint_, /*disableCollisionsBetweenLinkedBodies=*/true);
    constraint_in_world_ = true;
    world.addAction(this);
    plan(dt, x);
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::leave_world() {
    if (world_ && constraint_in_world_) world_->removeConstraint(&*constraint_);
    constraint_in_world_ = false;
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::detach() {
    if (!world_) return;
    world_->removeAction(this);
    leave_world();
    world_ = nullptr;
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::wake() {
    b_.activate();  // not forced: a static body stays static
    if (a_) a_->activate();
}

template <class Constraint>
PerDof<double> BasicBulletPlasticJoint<Constraint>::positions() {
    constraint_->calculateTransforms();
    PerDof<double> x{};
    for (int i = 0; i < 3; ++i) {
        x[i] = constraint_->getRelativePivotPosition(i);
        x[i + 3] = -constraint_->getAngle(i);  // Bullet's 6-dof angles turn the other way
    }
    return x;
}

template <class Constraint>
JointAxesInWorld BasicBulletPlasticJoint<Constraint>::axes_in_world() const {
    JointAxesInWorld axes;
    axes.anchor = to_vec3(constraint_->getCalculatedTransformB().getOrigin());
    const btMatrix3x3& basis = constraint_->getCalculatedTransformA().getBasis();
    for (int i = 0; i < 3; ++i) {
        axes.translation[i] = to_vec3(basis.getColumn(i));
        axes.rotation[i] = to_vec3(constraint_->getAxis(i));
    }
    return axes;
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::plan(double dt, const PerDof<double>& x) {
    const JointFrameState state{x, axes_in_world()};
    apply(driver_.plan(state, to_vec3(b_.getCenterOfMassPosition()), dt, [&] {
        return std::pair{inertia_of(b_), a_ ? std::optional<BodyInertia>(inertia_of(*a_)) : std::nullopt};
    }));
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::apply(const PerDof<std::optional<RowCommand>>& commands) {
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!commands[i]) continue;
        const int row = static_cast<int>(i);
        const RowCommand& c = *commands[i];
        // A motor row's velocity is −(the dof's rate) for every Spring2 axis (its Jacobian is
        // +axis on a, −axis on b); its bound is a force (Bullet ≥ 2.83 divides it by fps).
        if (c.kind == RowCommand::Kind::Hold) {
            bullet_rows::set_motor(*constraint_, row, true, -c.velocity, c.bound);
        } else {
            bullet_rows::set_motor(*constraint_, row, true, c.force > 0.0 ? -kPushSpeed : kPushSpeed, std::abs(c.force));
        }
    }
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::updateAction(btCollisionWorld*, btScalar dt) {
    if (driver_.broken()) {
        driver_.settle({}, {}, dt);  // keeps the clock
        return;
    }
    const WorldLoad load{to_vec3(feedback_.m_appliedForceBodyB), to_vec3(feedback_.m_appliedTorqueBodyB)};
    const PerDof<double> x = positions();  // the end of this step is the start of the next
    switch (driver_.settle(load, x, dt)) {
        case JointEvent::Broke:
            wake();
            constraint_->setEnabled(false);  // broken stays broken: nothing re-enables it
            leave_world();                   // and its bodies collide again
            return;
        case JointEvent::Yielded: wake(); break;
        case JointEvent::None: break;
    }
    plan(dt, x);
}

template class BasicBulletPlasticJoint<btGeneric6DofSpring2Constraint>;
template class BasicBulletPlasticJoint<btGeneric6DofSpringConstraint>;

}  // namespace plascap
