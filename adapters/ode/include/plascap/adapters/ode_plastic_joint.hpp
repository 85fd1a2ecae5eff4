#pragma once
// A plastic joint in ODE (0.16, double precision), driving ODE rows from the shared
// PlasticJointLaw (adapters/common), as the Bullet adapter drives Bullet's: one joint of plascap's
// own type (src/ode_plastic_rows.hpp, on ODE's joint object) with exactly the rows the dofs need,
// all at the anchor: none for a free dof, a rigid row (unbounded, Baumgarte target at ERP
// kHoldCorrection) for a rigid one, and for a plastic one the row the law commands (Hold: a rate
// target within the force range [lower, upper], both capacities at once; Push: the spring force,
// put on the bodies as a force and torque rather than a row that ODE would iterate).
// Rotations are measured as swing and twist (swing_twist.hpp), as plascap's Bullet constraint
// measures them, so a dof means the same in both engines; their rows lie along the angles'
// gradients. The joint's feedback (dJointFeedback, world frame, torque about b's centre) is handed
// to the engine-neutral PlasticJointDriver, which settles the law and plans the rows. A joint that
// yields or breaks enables (wakes) its bodies; a broken joint is disabled for good, and it calls
// its break callback. A joint whose bodies sleep (ODE's auto-disable) is not settled or planned
// while ODE skips their island: its law waits as it was, and its rows as they were planned.
//
// Use OdePlasticJoints (ode_plastic_joints.hpp): one call per step for every joint of a world. By
// hand: construct after the bodies; engage(now) when the joint takes hold (its positions then are
// its unloaded state); then before_step(dt) before each dWorldStep/dWorldQuickStep and
// after_step(dt) after it.
// A spring's push waits in the bodies' force and torque accumulators from the plan to the step
// (OdePlasticJoints plans a joint's next step as it settles the last): add loads with
// dBodyAddForce/dBodyAddTorque, as ODE intends; dBodySetForce/dBodySetTorque on a joined body
// between two steps would erase the push.
#include <ode/ode.h>

#include <optional>
#include <utility>

#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/plastic_joint_driver.hpp"
#include "plascap/adapters/rows_work.hpp"

namespace plascap {

class OdePlasticRows;  // plascap's ODE joint (src/ode_plastic_rows.hpp)

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
    // after_step(dt), then at once before_step(dt) for a next step of the same dt, while the joint's
    // state is still in the cache: one pass over the joint a step instead of two (OdePlasticJoints
    // does this). The plan reads what before_step would read then — the state after_step measured —
    // so the rows are the same; it is skipped for a joint that counts its rows' work, which needs
    // the velocities the next step starts from. `ready`: the joint needs no before_step before a
    // next step of dt (planned, or broken).
    struct Settled {
        JointEvent event;
        bool ready;
    };
    Settled after_step_and_plan(double dt);
    // Ask the CPU to load the joint's state for its coming turn (prefetch.hpp), in two stages:
    // prefetch() this object, kPrefetchAhead joints ahead; prefetch_rows() its ODE rows, found
    // through this object, kPrefetchRowsAhead joints ahead — by then this object has arrived, so
    // reading where its rows are does not wait on memory (as it did when both came at once).
    // OdePlasticJoints does both.
    void prefetch() const;
    void prefetch_rows() const;
    // The bytes the two load [B].
    static std::size_t state_bytes();

    const PlasticJointLaw& law() const { return driver_.law(); }
    PerDof<double> positions() const { return measure().positions; }
    const PerDof<double>& forces() const { return driver_.forces(); }
    double time() const { return driver_.time(); }
    // Whether ODE solved the joint in the last step: false where its bodies slept through it (ODE,
    // with auto-disable on, skips a disabled island: the joint then costs no settle and no plan),
    // once it is broken, and before it takes hold.
    bool solved() const { return solved_; }
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

    // Split corrections (OdePlasticJoints::Stepper::QuickSplit; ode_plastic_rows.hpp): from the
    // next plan on, the rows start warm and leave their position corrections to a pass of their own.
    void split_corrections(bool on);
    // The correction pass, which OdePlasticJoints runs as a second QuickStep between a step and its
    // settle. end_correction_pass returns the work the joint's own loads in the bodies'
    // accumulators (pushes, warm starts) do over the pass's motion, with the bodies' velocities
    // still those of the pass [J].
    void begin_correction_pass();
    double end_correction_pass(double dt);
    // The largest rate the pass would correct at [m/s | rad/s].
    double largest_correction() const;

private:
    JointFrameState measure() const;
    // The rows of the next step of dt, from the joint as measured at its start.
    void plan(const JointFrameState& state, double dt);
    // The law after a step, from the rows' feedback and the joint as measured at its end.
    JointEvent settle(const JointFrameState& state, double dt);
    std::optional<BodyVelocity> a_body_velocity() const;  // none when b is joined to the world
    WorldLoad feedback_on_b() const;  // what ODE's feedback says the rows applied to b
    void wake();
    // ODE writes a joint's feedback only in a step that solves it: one whose bodies sleep (auto-
    // disabled) is skipped with their island. A value ODE never writes, put in the feedback once
    // it is read, tells such a step: stepped() is false after it.
    void mark_feedback_unwritten();
    bool stepped() const;
    // After a step: records and returns whether ODE solved the joint in it (solved()).
    bool note_solved();
    // A step that did not solve the joint (PlasticJointDriver::idle).
    JointEvent idle(double dt);
    // Wakes the bodies on any event, and disables the rows of a broken joint.
    JointEvent act_on(JointEvent event);

    dBodyID a_, b_;
    Pose frame_on_a_, frame_on_b_;  // in a's and b's body coordinates (a = world: world coordinates)
    OdePlasticRows* rows_ = nullptr;  // owned by ODE: destroyed with dJointDestroy
    dJointFeedback feedback_{};
    PlasticJointDriver driver_;
    RowsWork rows_work_;
    bool solved_ = false;
};

}  // namespace plascap
