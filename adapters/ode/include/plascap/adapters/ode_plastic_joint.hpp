#pragma once
// A plastic joint in an unmodified ODE (double precision), driving ODE rows from the shared
// PlasticJointLaw (adapters/common), as the Bullet adapter drives Bullet's:
//   rotations: one dJointTypeAMotor in user mode whose three axes are reset every step to the
//     directions of the swing and twist angles' gradients (swing_twist.hpp), as plascap's Bullet
//     constraint measures them, so a dof means the same in both engines and there is no Euler
//     singularity at a 90° twist;
//   translations: ODE's LMotor applies its rows at the midpoint between the bodies' centres, not at
//     the anchor, so the translation rows are the two tangential rows of contact joints placed at
//     the anchor each step (their bounds are forces, their target velocities set; the contact's own
//     normal row is made inert with a large CFM). A row at the anchor is what a joint is. When all
//     three translations are rigid, one ball-and-socket joint at the anchor does it more cheaply.
//   a plastic hinge (one rotation not rigid, the other five dofs rigid): one ODE hinge joint about
//     that rotation's axis, whose motor row is the dof's row: six rows in one joint, as ODE's own
//     fixed joint, instead of a ball joint and an AMotor.
// Rigid dofs are rows with unbounded force and a Baumgarte target (ERP kHoldCorrection); free dofs
// get no row. Feedback (dJointFeedback, world frame, torque about b's centre) of all of them is
// summed and handed to the engine-neutral PlasticJointDriver, which settles the law and plans the
// rows. A joint that yields or breaks enables (wakes) its bodies; a broken joint's rows are disabled
// for good, and it calls its break callback.
//
// Use OdePlasticJoints (ode_plastic_joints.hpp): one call per step for every joint of a world. By
// hand: construct after the bodies; engage(now) when the joint takes hold (its positions then are
// its unloaded state); then before_step(dt) before each dWorldStep/dWorldQuickStep and
// after_step(dt) after it.
#include <ode/ode.h>

#include <array>
#include <optional>
#include <utility>

#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/plastic_joint_driver.hpp"
#include "plascap/adapters/rows_work.hpp"

namespace plascap {

class OdePlasticJoint {
public:
    // a may be 0: b is then joined to the world. frame_in_world: origin = anchor, columns = the
    // joint's x, y (beam axis) and z.
    OdePlasticJoint(dWorldID world, dBodyID a, dBodyID b, const Pose& frame_in_world, const PlasticJointSettings& settings);
    ~OdePlasticJoint();
    OdePlasticJoint(const OdePlasticJoint&) = delete;
    OdePlasticJoint& operator=(const OdePlasticJoint&) = delete;

    void before_step(double dt);
    // What the step did to the joint (None once it is broken).
    JointEvent after_step(double dt);

    const PlasticJointLaw& law() const { return driver_.law(); }
    PerDof<double> positions() const { return measure().positions; }
    const PerDof<double>& forces() const { return driver_.forces(); }
    double time() const { return driver_.time(); }
    // From now on, count the work the rows do on the two bodies (rows_work.hpp): rows_work() [J].
    // Off by default (about 1 % of a joint's cost).
    void count_rows_work() { rows_work_.start_counting(); }
    double rows_work() const { return rows_work_.total(); }
    void engage(double now);
    bool engaged() const { return driver_.engaged(); }
    // Breaks the joint at the end of the next step, whatever its load (a member removed).
    void sever() { driver_.sever(); }
    // Called once when the joint breaks (from after_step).
    void on_break(BreakCallback callback) { driver_.on_break(std::move(callback)); }
    dBodyID body_a() const { return a_; }
    dBodyID body_b() const { return b_; }

private:
    JointFrameState measure() const;
    std::optional<BodyVelocity> a_body_velocity() const;  // none when b is joined to the world
    void wake();
    void set_rotation_rows(const JointFrameState& state, const PerDof<std::optional<RowCommand>>& commands, double dt);
    void set_translation_rows(const JointFrameState& state, const PerDof<std::optional<RowCommand>>& commands, double dt);
    void set_hinge_motor(const JointFrameState& state, const PerDof<std::optional<RowCommand>>& commands, double dt);
    void hold_hinge_where_it_is(const JointFrameState& state);
    void disable_rows();

    dWorldID world_;
    dBodyID a_, b_;
    Pose frame_on_a_, frame_on_b_;  // in a's and b's body coordinates (a = world: world coordinates)
    dJointID rotations_ = nullptr;
    dJointID hinge_ = nullptr;               // one rotation turns, the other five dofs rigid: the whole joint
    std::optional<std::size_t> hinge_dof_;  // that rotation's dof
    dJointID ball_ = nullptr;  // all translations rigid
    dJointFeedback ball_feedback_{};
    dJointGroupID translations_ = nullptr;
    dJointFeedback rotation_feedback_{};
    std::array<dJointFeedback, 2> translation_feedback_{};
    int translation_joints_ = 0;
    PlasticJointDriver driver_;
    RowsWork rows_work_;
    std::optional<JointFrameState> measured_;  // after_step's state: the next before_step's start
};

}  // namespace plascap
