#pragma once
// The calls in which the plastic joint's three Bullet constraints differ: building one in place,
// setting up its rows for the dofs' modes, locking a rigid dof, measuring the joint and commanding a
// plastic row. plascap's own BulletPlasticConstraint does each natively; Bullet's two 6-dof spring
// constraints share the rest by name and by convention: a motor row's velocity is minus the dof's
// rate, getAngle() turns against the right-hand rule, the motor bound is one symmetric force (both
// divide it by fps), and rotations are Euler angles. tests/test_bullet_plastic_joint.cpp runs the
// analytic cases on all three.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <optional>
#include <type_traits>

#include "plascap/adapters/bullet_plastic_constraint.hpp"
#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/plastic_joint_law.hpp"
#include "plascap/adapters/row_command.hpp"

namespace plascap::bullet_rows {

// A Push row of a 6-dof spring asks for a relative speed it can never reach, so the solver always
// ends on its bound: the force applied is exactly the bound (as Bullet's own Spring2 spring rows do).
inline constexpr double kPushSpeed = 1e9;  // [m/s or rad/s]

template <class Constraint>
constexpr RowCapabilities capabilities() {
    if constexpr (std::is_same_v<Constraint, BulletPlasticConstraint>) {
        return BulletPlasticConstraint::kRows;
    } else {
        return {};
    }
}

// b joined to a (or to the world when a is nullptr) at a frame given in the world.
template <class Constraint>
void emplace(std::optional<Constraint>& constraint, btRigidBody* a, btRigidBody& b, const btTransform& frame) {
    if constexpr (std::is_same_v<Constraint, BulletPlasticConstraint>) {
        constraint.emplace(a, b, frame);
        return;
    } else {
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

// Before the joint takes hold: plascap's constraint starts with no rows (a free dof keeps none;
// attach() locks the rigid ones and commands the plastic ones); the 6-dof springs get limits and
// motors per mode.
inline void set_up(BulletPlasticConstraint&, const PlasticJointLaw&) {}

template <class Constraint>
void set_up(Constraint& c, const PlasticJointLaw& law) {
    for (Dof dof : kAllDofs) {
        const int i = static_cast<int>(index(dof));
        switch (law.mode(dof)) {
            case DofMode::Rigid:
                c.setLimit(i, 0.0, 0.0);  // lo == hi: locked at the assembled position
                break;
            case DofMode::Free:
            case DofMode::Plastic:
                c.setLimit(i, 1.0, -1.0);  // lo > hi: no limit row; a motor still acts
                break;
        }
        set_motor(c, i, law.mode(dof) == DofMode::Plastic, 0.0, 0.0);
        c.enableSpring(i, false);  // both constraints: never Bullet's own springs
    }
}

// Locks dof i at position `at` (the law's sign). Spring2 treats lo == hi as a lock; the first
// 6-dof constraint adds a limit row only once the position has left [lo, hi], so a body would move
// freely for a step before it took hold: an unbounded motor at zero velocity holds it meanwhile
// (Bullet switches the motor off while the limit row acts).
inline void lock(BulletPlasticConstraint& c, std::size_t i, double at) { c.lock_row(i, at); }

template <class Constraint>
void lock(Constraint& c, std::size_t dof, double at) {
    const int i = static_cast<int>(dof);
    const double bullet_at = dof >= 3 ? -at : at;  // Bullet's 6-dof angles turn the other way
    c.setLimit(i, bullet_at, bullet_at);
    if constexpr (!std::is_same_v<Constraint, btGeneric6DofSpring2Constraint>) set_motor(c, i, true, 0.0, BT_LARGE_FLOAT);
}

inline JointFrameState measure(BulletPlasticConstraint& c) { return c.measure(); }

template <class Constraint>
JointFrameState measure(Constraint& c) {
    const auto to_vec3 = [](const btVector3& v) { return Vec3{v.x(), v.y(), v.z()}; };
    c.calculateTransforms();
    JointFrameState s;
    const btMatrix3x3& basis = c.getCalculatedTransformA().getBasis();
    for (int i = 0; i < 3; ++i) {
        s.positions[i] = c.getRelativePivotPosition(i);
        s.positions[i + 3] = -c.getAngle(i);  // Bullet's 6-dof angles turn the other way
        s.axes.translation[i] = to_vec3(basis.getColumn(i));
        s.axes.rotation[i] = to_vec3(c.getAxis(i));
    }
    s.axes.anchor = to_vec3(c.getCalculatedTransformB().getOrigin());
    return s;
}

// Per dof, the motion the last solve's split-impulse pushes made along its row: plascap's
// constraint is pushed by BulletPlasticSolver; the 6-dof springs' rows are not (zeros).
inline PerDof<double> corrected_motion(const BulletPlasticConstraint& c) { return c.corrected_motion(); }

template <class Constraint>
PerDof<double> corrected_motion(const Constraint&) {
    return {};
}

// Per dof, the rows' effective masses as the last solve formed them (NaN: not known): plascap's
// constraint is told them by BulletPlasticSolver; the 6-dof springs' are not known.
inline PerDof<double> solved_masses(const BulletPlasticConstraint& c) { return c.solved_masses(); }

template <class Constraint>
PerDof<double> solved_masses(const Constraint&) {
    PerDof<double> unknown;
    unknown.fill(NAN);
    return unknown;
}

inline void command(BulletPlasticConstraint& c, std::size_t i, const RowCommand& command) { c.command_row(i, command); }

template <class Constraint>
void command(Constraint& c, std::size_t dof, const RowCommand& command) {
    const int i = static_cast<int>(dof);
    // A motor row's velocity is −(the dof's rate) for every 6-dof axis (its Jacobian is +axis on a,
    // −axis on b); its bound is a force (Bullet ≥ 2.83 divides it by fps).
    if (command.kind == RowCommand::Kind::Hold) {
        set_motor(c, i, true, -command.velocity, command.bound);
    } else {
        set_motor(c, i, true, command.force > 0.0 ? -kPushSpeed : kPushSpeed, std::abs(command.force));
    }
}

}  // namespace plascap::bullet_rows
