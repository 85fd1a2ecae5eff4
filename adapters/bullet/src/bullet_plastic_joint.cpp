#include "plascap/adapters/bullet_plastic_joint.hpp"

#include <cmath>
#include <utility>

#include "bullet_six_dof_rows.hpp"
#include "plascap/adapters/bullet_vec3.hpp"

namespace plascap {
namespace {


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
    : a_(a), b_(b), driver_(settings, bullet_rows::capabilities<Constraint>()) {
    bullet_rows::emplace(constraint_, a, b, frame_in_world);
    constraint_->setJointFeedback(&feedback_);
    constraint_->enableFeedback(true);
    bullet_rows::set_up(*constraint_, driver_.law());
}

template <class Constraint>
BasicBulletPlasticJoint<Constraint>::~BasicBulletPlasticJoint() {
    detach();
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::attach(btDynamicsWorld& world, double dt, double now) {
    const JointFrameState state = bullet_rows::measure(*constraint_);
    driver_.engage(state.positions, now);
    for (Dof dof : kAllDofs) {  // rigid dofs lock where the joint takes hold
        if (driver_.law().mode(dof) == DofMode::Rigid) bullet_rows::lock(*constraint_, index(dof), state.positions[index(dof)]);
    }
    world_ = &world;
    world.addConstraint(&*constraint_, /*disableCollisionsBetweenLinkedBodies=*/true);
    constraint_in_world_ = true;
    world.addAction(this);
    plan(dt, state);
    note_step_start();
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::note_step_start() {
    if (!rows_work_.counting()) return;
    rows_work_.step_starts(body_velocity(b_), a_ ? std::optional<BodyVelocity>(body_velocity(*a_)) : std::nullopt);
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
    return bullet_rows::measure(*constraint_).positions;
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::plan(double dt, const JointFrameState& state) {
    planned_axes_ = state.axes;
    planned_centre_of_b_ = to_vec3(b_.getCenterOfMassPosition());
    const PerDof<std::optional<RowCommand>> commands =
        driver_.plan(state, dt, [&] {
            return std::pair{inertia_of(b_), a_ ? std::optional<BodyInertia>(inertia_of(*a_)) : std::nullopt};
        }, bullet_rows::solved_masses(*constraint_));
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (commands[i]) bullet_rows::command(*constraint_, i, *commands[i]);
    }
}

template <class Constraint>
bool BasicBulletPlasticJoint<Constraint>::asleep() const {
    // Bullet puts a whole island to sleep at once and solves no constraint of a sleeping island; a
    // static or kinematic body is in no island.
    return !b_.isActive() && (!a_ || a_->isStaticOrKinematicObject() || !a_->isActive());
}

template <class Constraint>
bool BasicBulletPlasticJoint<Constraint>::act_on(JointEvent event) {
    switch (event) {
        case JointEvent::Broke:
            wake();
            constraint_->setEnabled(false);  // broken stays broken: nothing re-enables it
            leave_world();                   // and its bodies collide again
            return false;
        case JointEvent::Yielded:
        case JointEvent::AtCapacity: wake(); return true;
        case JointEvent::None: return true;
    }
    return true;
}

template <class Constraint>
void BasicBulletPlasticJoint<Constraint>::updateAction(btCollisionWorld*, btScalar dt) {
    solved_ = !driver_.broken() && !asleep();
    if (!solved_) {
        // Broken, or its island asleep: nothing moved and no row acted, so the law stays as it is
        // (the clock runs on) and the rows planned for this step hold for the next.
        act_on(driver_.idle(dt));
        note_step_start();
        return;
    }
    const WorldLoad load{to_vec3(feedback_.m_appliedForceBodyB), to_vec3(feedback_.m_appliedTorqueBodyB)};
    if (rows_work_.counting()) {
        const WorldLoad on_a{to_vec3(feedback_.m_appliedForceBodyA), to_vec3(feedback_.m_appliedTorqueBodyA)};
        rows_work_.step_ends(load, on_a, body_velocity(b_), a_ ? std::optional<BodyVelocity>(body_velocity(*a_)) : std::nullopt, dt);
        note_step_start();  // this step's end is the next one's start
    }
    const JointFrameState state = bullet_rows::measure(*constraint_);  // the end of this step is the start of the next
    const PerDof<double> forces = joint_frame_loads(load, planned_centre_of_b_, planned_axes_);
    if (!act_on(driver_.settle(forces, state.positions, dt, bullet_rows::corrected_motion(*constraint_)))) return;
    plan(dt, state);
}

template class BasicBulletPlasticJoint<BulletPlasticConstraint>;
template class BasicBulletPlasticJoint<btGeneric6DofSpring2Constraint>;
template class BasicBulletPlasticJoint<btGeneric6DofSpringConstraint>;

}  // namespace plascap
