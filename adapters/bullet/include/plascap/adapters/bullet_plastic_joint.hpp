#pragma once
// A plastic joint in an unmodified Bullet: a constraint whose rows follow a PlasticJointLaw
// (adapters/common). By default the constraint is plascap's own (BulletPlasticConstraint: exactly
// the rows the dofs need, both capacities as a row's bounds, swing–twist rotations without a 90°
// singularity). The paper's route drives one of Bullet's 6-dof spring constraints from outside
// (BulletPlasticJointSpring2, BulletPlasticJoint6DofSpring); bullet_six_dof_rows.hpp holds what
// differs between the three. Per dof: free (no row), rigid (a locked row) or plastic (Hold = a
// rate target bounded by the capacity; Push = exactly the capped spring force). After every step,
// as a btActionInterface, it reads the joint feedback (world frame, torque about b's centre of mass)
// and hands it to the engine-neutral PlasticJointDriver, which settles the law and plans the next
// step's rows. A joint that yields or breaks wakes its bodies (a slow plastic flow is never frozen by
// Bullet's sleeping); a joint whose island sleeps is not settled or planned until it wakes; a broken
// joint leaves the world, so its bodies collide again, and calls the break callback. Destroying an
// attached joint detaches it.
#include <btBulletDynamicsCommon.h>

#include <optional>

#include "plascap/adapters/bullet_plastic_constraint.hpp"
#include "plascap/adapters/plastic_joint_driver.hpp"
#include "plascap/adapters/rows_work.hpp"

namespace plascap {

template <class Constraint>
class BasicBulletPlasticJoint : public btActionInterface {
public:
    // `a` may be nullptr: b is then joined to the world. `frame_in_world`: origin = anchor, basis
    // columns = the joint's x, y (beam axis) and z.
    BasicBulletPlasticJoint(btRigidBody* a, btRigidBody& b, const btTransform& frame_in_world,
                            const PlasticJointSettings& settings);
    ~BasicBulletPlasticJoint() override;
    BasicBulletPlasticJoint(const BasicBulletPlasticJoint&) = delete;
    BasicBulletPlasticJoint& operator=(const BasicBulletPlasticJoint&) = delete;

    // Adds the constraint (collisions between a and b disabled while it holds) and this action to
    // `world` and plans the first step of length dt; `now` is the world's time [s], for broken_at.
    // Call once; the joint's positions now are its unloaded state.
    void attach(btDynamicsWorld& world, double dt, double now = 0.0);
    // Takes the joint out of its world (the destructor does it too). Harmless if not attached.
    void detach();
    // Breaks the joint at the end of the next step, whatever its load (a member removed).
    void sever() { driver_.sever(); }
    // Called once when the joint breaks (from inside the world's step).
    void on_break(BreakCallback callback) { driver_.on_break(std::move(callback)); }

    void updateAction(btCollisionWorld* world, btScalar dt) override;
    void debugDraw(btIDebugDraw*) override {}

    const PlasticJointLaw& law() const { return driver_.law(); }
    Constraint& constraint() { return *constraint_; }
    // Dof positions now: b relative to a in the joint frame [m, rad].
    PerDof<double> positions();
    // The generalised forces the rows applied to b during the last step [N, N·m].
    const PerDof<double>& forces() const { return driver_.forces(); }
    double time() const { return driver_.time(); }
    // Whether Bullet solved the joint in the last step: false where its island slept through it (the
    // joint then costs no settle and no plan), once it is broken, and before it is attached.
    bool solved() const { return solved_; }
    // From now on, count the work the rows' velocity solve does on the two bodies (rows_work.hpp; the
    // split-impulse pushes are not in it): rows_work() [J]. Off by default (about 1 % of a joint's cost).
    void count_rows_work() { rows_work_.start_counting(); }
    double rows_work() const { return rows_work_.total(); }

private:
    void note_step_start();
    void plan(double dt, const JointFrameState& state);
    void wake();
    void leave_world();
    bool asleep() const;  // its bodies' island sleeps: Bullet did not solve it
    // Wakes the bodies on any event; a broken joint leaves the world. False once broken.
    bool act_on(JointEvent event);

    btRigidBody* a_;
    btRigidBody& b_;
    // Held in place, not on its own allocation: Bullet scans constraints every step, and a scattered
    // layout measurably slows that scan (bench_bullet_joints).
    std::optional<Constraint> constraint_;
    btJointFeedback feedback_{};
    PlasticJointDriver driver_;
    RowsWork rows_work_;
    // The axes and b's centre of mass the step was planned with: its feedback's forces act on them.
    JointAxesInWorld planned_axes_{};
    Vec3 planned_centre_of_b_{};
    btDynamicsWorld* world_ = nullptr;  // while attached
    bool constraint_in_world_ = false;  // until it breaks
    bool solved_ = false;
};

extern template class BasicBulletPlasticJoint<BulletPlasticConstraint>;
extern template class BasicBulletPlasticJoint<btGeneric6DofSpring2Constraint>;
extern template class BasicBulletPlasticJoint<btGeneric6DofSpringConstraint>;

// The default: plascap's own constraint (bullet_plastic_constraint.hpp).
using BulletPlasticJoint = BasicBulletPlasticJoint<BulletPlasticConstraint>;
// The paper's route: Bullet's 6-dof spring constraints driven from outside.
using BulletPlasticJointSpring2 = BasicBulletPlasticJoint<btGeneric6DofSpring2Constraint>;
using BulletPlasticJoint6DofSpring = BasicBulletPlasticJoint<btGeneric6DofSpringConstraint>;

}  // namespace plascap
