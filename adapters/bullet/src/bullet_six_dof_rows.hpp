#pragma once
// The few calls in which Bullet's two 6-dof spring constraints differ, for the plastic joint:
// building one in place, and setting an axis's motor. Everything else (limits, positions, angles,
// axes, feedback) they share by name and by convention: a motor row's velocity is minus the dof's
// rate, getAngle() turns against the right-hand rule, and the motor bound is a force (both divide
// it by fps). tests/test_bullet_plastic_joint.cpp runs the analytic cases on both.
#include <btBulletDynamicsCommon.h>

#include <optional>
#include <type_traits>

namespace plascap::bullet_rows {

// b joined to a (or to the world when a is nullptr) at a frame given in the world.
template <class Constraint>
void emplace(std::optional<Constraint>& constraint, btRigidBody* a, btRigidBody& b, const btTransform& frame) {
    const btTransform in_b = b.getCenterOfMassTransform().inverse() * frame;
    if constexpr (std::is_same_v<Constraint, btGeneric6DofSpring2Constraint>) {
        if (a == nullptr) {
            constraint.emplace(b, in_b);
        } else {
            constraint.emplace(*a, b, a->getCenterOfMassTransform().inverse() * frame, in_b);
        }
    } else {
        // Translations measured along frame a's axes, as Spring2 always does.
        if (a == nullptr) {
            constraint.emplace(b, in_b, true);
        } else {
            constraint.emplace(*a, b, a->getCenterOfMassTransform().inverse() * frame, in_b, true);
        }
    }
}

inline void set_motor(btGeneric6DofSpring2Constraint& c, int axis, bool on, double velocity, double force) {
    c.enableMotor(axis, on);
    c.setTargetVelocity(axis, velocity);
    c.setMaxMotorForce(axis, force);
}

inline void set_motor(btGeneric6DofConstraint& c, int axis, bool on, double velocity, double force) {
    if (axis < 3) {
        btTranslationalLimitMotor& m = *c.getTranslationalLimitMotor();
        m.m_enableMotor[axis] = on;
        m.m_targetVelocity[axis] = velocity;
        m.m_maxMotorForce[axis] = force;
    } else {
        btRotationalLimitMotor& m = *c.getRotationalLimitMotor(axis - 3);
        m.m_enableMotor = on;
        m.m_targetVelocity = velocity;
        m.m_maxMotorForce = force;
    }
}

// Locks an axis at `at` (Bullet's sign for angles). Spring2 treats lo == hi as a lock; the first
// constraint adds a limit row only once the position has left [lo, hi], so a body would move freely
// for a step before it took hold: an unbounded motor at zero velocity holds it meanwhile (Bullet
// switches the motor off while the limit row acts).
inline void lock(btGeneric6DofSpring2Constraint& c, int axis, double at) { c.setLimit(axis, at, at); }

inline void lock(btGeneric6DofConstraint& c, int axis, double at) {
    c.setLimit(axis, at, at);
    set_motor(c, axis, true, 0.0, BT_LARGE_FLOAT);
}


}  // namespace plascap::bullet_rows
