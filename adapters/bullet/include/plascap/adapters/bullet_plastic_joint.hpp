#pragma once
// A plastic joint in an unmodified Bullet: a 6-dof constraint whose rows follow a PlasticJointLaw
// (adapters/common). The paper develops both of Bullet's 6-dof spring constraints, and so does this:
// BulletPlasticJoint drives a btGeneric6DofSpring2Constraint, BulletPlasticJoint6DofSpring a
// btGeneric6DofSpringConstraint; they differ only in how a motor is set (bullet_six_dof_rows.hpp). Per dof: free (no row), rigid (a locked limit row) or plastic
// (a motor row: Hold = target velocity 0 bounded by the capacity; Push = exactly the capped spring
// force). After every step, as a btActionInterface, it reads the joint feedback (world frame, torque
// about b's centre of mass), turns it into joint-frame dof forces, settles the law, plans the next
// step's rows, and disables the constraint when the joint breaks.
#include <btBulletDynamicsCommon.h>

#include <optional>

#include "plascap/adapters/joint_loads.hpp"
#include "plascap/adapters/plastic_joint_law.hpp"

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

    // Adds the constraint (collisions between a and b disabled) and this action to `world` and
    // plans the first step of length dt; `now` is the world's time [s], for broken_at. Call once.
    void attach(btDynamicsWorld& world, double dt, double now = 0.0);
    void detach(btDynamicsWorld& world);

    void updateAction(btCollisionWorld* world, btScalar dt) override;
    void debugDraw(btIDebugDraw*) override {}

    const PlasticJointLaw& law() const { return law_; }
    Constraint& constraint() { return *constraint_; }
    // Dof positions now: b relative to a in the joint frame [m, rad].
    PerDof<double> positions();
    // The generalised forces the rows applied to b during the last step [N, N·m].
    const PerDof<double>& forces() const { return forces_; }
    double time() const { return time_; }

private:
    void set_up_rows();
    void plan(double dt, const PerDof<double>& positions);
    void apply(const PerDof<std::optional<RowCommand>>& commands);
    JointAxesInWorld axes_in_world() const;
    PerDof<double> effective_masses(const JointAxesInWorld& axes) const;

    btRigidBody* a_;
    btRigidBody& b_;
    // Held in place, not on its own allocation: Bullet scans constraints every step, and a scattered
    // layout measurably slows that scan (bench_bullet_joints).
    std::optional<Constraint> constraint_;
    btJointFeedback feedback_{};
    PlasticJointLaw law_;
    JointAxesInWorld planned_axes_{};
    Vec3 planned_centre_of_b_{};
    PerDof<double> forces_{};
    bool needs_masses_ = false;
    double time_ = 0.0;
};

extern template class BasicBulletPlasticJoint<btGeneric6DofSpring2Constraint>;
extern template class BasicBulletPlasticJoint<btGeneric6DofSpringConstraint>;

using BulletPlasticJoint = BasicBulletPlasticJoint<btGeneric6DofSpring2Constraint>;
using BulletPlasticJoint6DofSpring = BasicBulletPlasticJoint<btGeneric6DofSpringConstraint>;

}  // namespace plascap
