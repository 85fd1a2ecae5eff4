#pragma once
// plascap's own ODE joint (ODE 0.16's joint object, ode_joint_object.hpp): exactly the rows a
// plastic joint's dofs need, all at the anchor, in one joint — as ODE's own fixed joint has its six.
// ODE's public joints could not do it: a bounded row at an anchor existed only as a contact joint's
// friction row, so the adapter rebuilt two contact joints per joint per step (with two inert normal
// rows) beside a ball joint or an AMotor whose axes it reset every step.
//   translation dof i: J·v = axisᵢ·(v_b + ω_b × r_b − v_a − ω_a × r_a), r = anchor − centre: the
//     rate of b's anchor relative to a's along the axis, so the row's force acts at the anchor;
//   rotation dof i: J·v = gᵢ·(ω_b − ω_a), gᵢ the angle's gradient (swing_twist.hpp): the angle's
//     exact rate, and the row's force its generalised force.
// Each row has its own target rate and force range [lower, upper] (±dInfinity: a rigid row). ODE
// fills the joint's dJointFeedback from the rows' forces, as for its own joints.
#include <ode/ode.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "ode_joint_object.hpp"
#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/joint_loads.hpp"

namespace plascap {

// One dof's row for the next step: J·v driven to `rate` with a force in [lower, upper] on b. A
// target whose range is one force (lower == upper: a spring's push) is that force, applied to the
// bodies (OdePlasticRows::set_rows), not a row.
struct OdeRowTarget {
    double rate = 0.0;    // [m/s | rad/s]
    double lower = 0.0;   // [N | N·m], ≤ 0 for a row
    double upper = 0.0;   // ≥ 0 for a row
    bool pinned() const { return lower == upper; }
};

class OdePlasticRows final : public dxJoint {
public:
    // A joint of `world` holding b to a (0: the world), with no rows until set_rows. ODE owns it:
    // dJointDestroy(joint) frees it.
    static OdePlasticRows* create(dWorldID world, dBodyID b, dBodyID a);

    // The rows of the next step, for the joint as measured now (state's anchor is b's): dof i's is
    // target_of(i), a std::optional<OdeRowTarget>; no row for a dof without one. Written straight
    // into the joint: a step of 1,000 joints calls this 1,000 times (issue 16, docs/adapters.md "Cost").
    //
    // A pinned target (a spring's push: one force, not a range) is no row: its force goes on the
    // bodies as the force and torque its row would apply at its bound (Jᵀ·f), added to their
    // accumulators (dBodyAddForce, dBodyAddTorque), which ODE's next step applies and clears. ODE's
    // iterations then carry the rows that need solving only: a row pinned at its bound costs them as
    // much as any other (issue 16). One push stays a row where the joint would have no row, since
    // ODE writes the feedback, and so tells a solved joint, only for a joint with rows.
    // Forces applied for a step that did not take them (the joint planned again before a step, or
    // asleep: ODE keeps a disabled body's accumulators) are taken back first.
    template <class TargetOf>
    void set_rows(const JointFrameState& state, TargetOf&& target_of) {
        withdraw_pushes();
        set_geometry(state);
        rows_ = pushes_ = kept_push_ = 0;
        for (std::size_t i = 0; i < kDofCount; ++i) {
            const std::optional<OdeRowTarget> target = target_of(i);
            if (!target) continue;
            targets_[i] = *target;
            (target->pinned() ? pushes_ : rows_) |= static_cast<std::uint8_t>(1u << i);
        }
        if (rows_ == 0 && pushes_ != 0) keep_one_push_as_row();
        count_rows();
        if (split_) start_warm();
        if (pushes_ != 0 || warm_ != 0) apply_pushes(1.0);
    }

    // Split corrections (OdePlasticJoints::Stepper::QuickSplit): from the next set_rows on, the rows
    // hold their rates without their position corrections (Baumgarte), which a pass of their own
    // applies (correction_pass), and start from the forces of the step before (a warm start).
    // Off: the corrections are in the rows' rates, and the rows start from 0, as ODE's own joints.
    void split_corrections(bool on) {
        split_ = on ? std::make_unique<Split>() : nullptr;
        last_rows_ = warm_ = 0;
    }
    // The rows' forces of the step just solved (generalised, on b), for the next step's warm start.
    void remember_forces(const PerDof<double>& forces) {
        if (!split_) return;
        split_->last_forces = forces;
        last_rows_ = rows_;
    }
    // The correction pass: while it lasts, the joint's rows are its corrections alone — each rigid
    // or held row driven to its correction rate, no warm start — and ODE writes no feedback (that of
    // the velocity solve stays). A held row's correction may use only what its force range leaves
    // beyond the force f the velocity solve gave it: [min(0, lower − f), max(0, upper − f)], as
    // Bullet bounds a row's split impulse (btSequentialImpulseConstraintSolver's
    // resolveSplitPenetrationImpulse). So a row at its capacity is not pushed back against its flow.
    // `solved`: the rows' forces in the step (forces_on_b of the whole load), or none where the
    // step did not solve the joint (no rows in the pass then). Its end records, per dof, the motion
    // the pass made along each row: J·v·dt with v the bodies' velocities of the pass.
    void begin_correction_pass(const std::optional<PerDof<double>>& solved);
    // Whether the step solved the joint (`solved` was given).
    bool end_correction_pass(double dt);
    // The largest correction rate of the rows [m/s | rad/s]: 0 when there is nothing to correct.
    double largest_correction() const;
    // Per dof, the motion the last correction pass made along the row [m | rad]; 0 without one.
    const PerDof<double>& corrected_motion() const { return split_ ? split_->corrected_motion : kNoMotion; }

    // The step solved the joint: ODE applied the pushes and cleared its bodies' accumulators.
    void pushes_taken() { pushes_applied_ = false; }
    // Takes back pushes no step has taken (a joint that breaks, or goes, while its bodies sleep).
    void withdraw_pushes() {
        if (pushes_applied_) apply_pushes(-1.0);
    }
    // Adds the loads the pushes put on b and on a (world frame, torques about each centre, as ODE's
    // feedback) to what ODE's feedback says the rows applied: the joint's whole action.
    void add_pushes(WorldLoad& on_b, WorldLoad& on_a) const {
        if (pushes_ != 0 || warm_ != 0) add_each_push(on_b, on_a);  // inline: most joints have none (rigid-plastic)
    }

    // The generalised forces the rows and pushes applied to b in the step they were set for
    // (joint_frame_loads), from their whole load on b (on_b, add_pushes).
    PerDof<double> forces_on_b(const WorldLoad& on_b) const {
        return joint_frame_loads(on_b, difference(axes_.anchor, lever_b_), axes_);
    }

    void getInfo1(Info1* info) override;
    void getInfo2(dReal worldFPS, dReal worldERP, int rowskip, dReal* J1, dReal* J2, int pairskip, dReal* pairRhsCfm,
                  dReal* pairLoHi, int* findex) override;
    void getSureMaxInfo(SureMaxInfo* info) override;
    dJointType type() const override { return dJointTypeNull; }  // no ODE type; ODE's setters refuse it
    std::size_t size() const override { return sizeof(OdePlasticRows); }

private:
    explicit OdePlasticRows(dWorldID world) : dxJoint(world) {}

    // Asks the CPU for the next joint in the world's list (the one created before this) while this
    // one writes its rows. ODE steps islands in the order of its list of bodies, also newest first;
    // where each body's joint was made with it (10,000 hanging boxes, bench_ode_joints), that joint
    // is the next whose rows ODE asks for, which then no longer waits on memory (docs/adapters.md,
    // ODE "Cost"). Elsewhere it is a hint for nothing, 9 instructions.
    void load_next_joint() const;

    // set_rows's parts before and after the targets: the axes and levers as measured; how many rows
    // the targets make, and whether all are unbounded.
    void set_geometry(const JointFrameState& state);
    void count_rows();
    bool has_row(std::size_t i) const { return (rows_ >> i) & 1u; }
    bool has_push(std::size_t i) const { return (pushes_ >> i) & 1u; }
    // Dof i's row: J on b and on a (the linear parts 0 for a rotation row).
    struct RowJacobian {
        Vec3 linear_b, angular_b, linear_a, angular_a;
    };
    RowJacobian jacobian(std::size_t i) const;
    // The lowest pushed dof becomes a row again: an unreachable rate bounded by its force.
    void keep_one_push_as_row();
    // Dof i's row load Jᵀ·f on b and on a (world frame, torques about each body's centre).
    void add_row_load(std::size_t i, double f, WorldLoad& on_b, WorldLoad& on_a) const;
    void add_each_push(WorldLoad& on_b, WorldLoad& on_a) const;
    // With split corrections, each row that had a row in the step before starts from that step's
    // force f₀ (clamped into its range): f₀ goes on the bodies with the pushes, and the row solves
    // for the rest, within [lower − f₀, upper − f₀]. Clears the last pass's corrected motion.
    void start_warm();
    bool is_warm(std::size_t i) const { return (warm_ >> i) & 1u; }
    // The rows the correction pass drives: all but a push kept as a row.
    std::uint8_t corrected_rows() const { return rows_ & static_cast<std::uint8_t>(~kept_push_); }
    // The rows the pass writes: none where the step did not solve the joint.
    std::uint8_t pass_rows() const { return split_ && split_->pass_solved ? corrected_rows() : 0; }
    // Adds sign × the pushes' loads to the bodies' accumulators; pushes_applied_ after +1.
    void apply_pushes(double sign);

    // The rows of the next step: the joint's axes and levers as measured, and each dof's target
    // where it has a row (a bit each in rows_, not a std::optional's flag each: 48 B less for a
    // step to touch, issue 16).
    JointAxesInWorld axes_{};
    Vec3 lever_b_{}, lever_a_{};  // anchor − centre of b, of a [m]
    PerDof<OdeRowTarget> targets_{};
    std::uint8_t rows_ = 0;    // bit i: dof i has a row
    std::uint8_t pushes_ = 0;  // bit i: dof i's target is pinned, a push on the bodies
    std::uint8_t count_ = 0;
    bool all_unbounded_ = false;
    bool pushes_applied_ = false;  // in the bodies' accumulators, not yet taken by a step
    // Split corrections (split_corrections): the flags here, the forces apart, made only for a
    // split joint, so that a joint of the default stepper keeps its size (issue 16's cost).
    bool correcting_ = false;     // in the correction pass
    std::uint8_t kept_push_ = 0;  // bit i: dof i is a push kept as a row (keep_one_push_as_row)
    std::uint8_t warm_ = 0;       // bit i: row i starts from warm_force[i]
    std::uint8_t last_rows_ = 0;  // the rows whose forces last_forces holds
    struct Split {
        PerDof<double> warm_force{};  // [N | N·m]
        PerDof<double> last_forces{};
        PerDof<double> corrected_motion{};
        PerDof<double> solved_forces{};  // the rows' forces in the step, during the correction pass
        bool pass_solved = false;
        dJointFeedback* velocity_feedback = nullptr;  // set aside during the correction pass
    };
    std::unique_ptr<Split> split_;  // none: not split
    static const PerDof<double> kNoMotion;
};

}  // namespace plascap
