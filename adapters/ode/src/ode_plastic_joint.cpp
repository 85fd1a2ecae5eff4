#include "plascap/adapters/ode_plastic_joint.hpp"

#include <cmath>

#include "plascap/adapters/joint_loads.hpp"
#include "plascap/adapters/row_effective_mass.hpp"
#include "plascap/adapters/swing_twist.hpp"
#include "ode_body_velocity.hpp"

namespace plascap {
namespace {

// What ODE's rows measure and carry: swing and twist (swing_twist.hpp) on the AMotor's rows, as on
// plascap's Bullet constraint, and a motor's one symmetric bound.
constexpr RowCapabilities kOdeRows{RotationMeasure::SwingTwist, false};

// As in the Bullet adapter: a Push row asks for an unreachable speed and so ends on its bound.
constexpr double kPushSpeed = 1e4;
// Makes a contact joint's normal row inert: its force is (error)/(CFM) ≈ 0.
constexpr double kInertCfm = 1e3;
// The bound of a rigid row. Not dInfinity: a contact joint counts a friction row with an infinite
// bound as unbounded and ODE's dWorldStep then takes its (bounded) normal row for unbounded too and
// fails an assertion inside its LCP solver.
constexpr double kUnbounded = 1e12;  // [N, N·m]

Pose pose_of(dBodyID body) {
    Pose p;
    const dReal* x = dBodyGetPosition(body);
    const dReal* r = dBodyGetRotation(body);  // 3 rows of 4
    p.origin = {x[0], x[1], x[2]};
    for (int i = 0; i < 3; ++i) p.rotation[i] = {r[4 * i], r[4 * i + 1], r[4 * i + 2]};
    return p;
}

BodyInertia inertia_of(dBodyID body) {
    dMass m;
    dBodyGetMass(body, &m);
    const Pose p = pose_of(body);
    // I_world⁻¹ = R·I_body⁻¹·Rᵀ
    const double a = m.I[0], b = m.I[1], c = m.I[2], d = m.I[4], e = m.I[5], f = m.I[6], g = m.I[8], h = m.I[9], k = m.I[10];
    const double det = a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
    const Mat3 inverse_body = {{{(e * k - f * h) / det, (c * h - b * k) / det, (b * f - c * e) / det},
                                {(f * g - d * k) / det, (a * k - c * g) / det, (c * d - a * f) / det},
                                {(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det}}};
    BodyInertia inertia;
    inertia.inverse_mass = 1.0 / m.mass;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double sum = 0.0;
            for (int p1 = 0; p1 < 3; ++p1)
                for (int p2 = 0; p2 < 3; ++p2) sum += p.rotation[i][p1] * inverse_body[p1][p2] * p.rotation[j][p2];
            inertia.inverse_inertia_world[i][j] = sum;
        }
    inertia.centre = p.origin;
    return inertia;
}

// A row's target velocity and force bound for one dof this step.
struct RowSetting {
    double velocity = 0.0;
    double bound = 0.0;  // 0: no row
};

RowSetting row_setting(DofMode mode, const std::optional<RowCommand>& command, double position, double reference,
                       double dt) {
    if (mode == DofMode::Free) return {};
    if (mode == DofMode::Rigid) return {-kHoldCorrection * (position - reference) / dt, kUnbounded};
    if (command->kind == RowCommand::Kind::Hold) return {command->velocity, command->bound};
    return {command->force > 0.0 ? kPushSpeed : -kPushSpeed, std::abs(command->force)};
}

// A rotation row along the unit direction n = g/|g| of its angle's gradient g (ODE normalises an
// AMotor's axes, and a hinge's axis is that direction while it holds the other two rotations)
// measures n·ω = θ̇/|g| and applies, with a moment λ·n, the generalised force λ/|g|
// (swing_twist.hpp): its target rate is the angle's over |g|, its bound the dof's times |g|.
RowSetting rotation_row_setting(const PlasticJointDriver& driver, const JointFrameState& state,
                                const std::optional<RowCommand>& command, std::size_t dof, double dt) {
    const double length = norm(state.axes.rotation[dof - 3]);
    const RowSetting row = row_setting(driver.law().mode(kAllDofs[dof]), command, state.positions[dof],
                                       driver.engaged_positions()[dof], dt);
    return {row.velocity / length, row.bound * length};
}

// The one rotation a hinge joint may carry: all three translations rigid, exactly one rotation not
// rigid (plastic, elastic or free), the other two rigid. ODE's hinge joint is then the whole joint,
// six rows in one joint as ODE's fixed joint has, where a ball joint and an AMotor are two.
std::optional<std::size_t> hinge_dof(const PlasticJointLaw& law) {
    std::optional<std::size_t> turning;
    for (std::size_t i = 0; i < kAllDofs.size(); ++i) {
        if (law.mode(kAllDofs[i]) == DofMode::Rigid) continue;
        if (!is_rotation(kAllDofs[i]) || turning) return std::nullopt;
        turning = i;
    }
    return turning;
}

// Bodies are attached as (b, a): ODE's f1, t1 act on b, and f2, t2 on a.
void add(WorldLoad& on_b, WorldLoad& on_a, const dJointFeedback& fb) {
    for (int i = 0; i < 3; ++i) {
        on_b.force[i] += fb.f1[i];
        on_b.torque_about_com[i] += fb.t1[i];
        on_a.force[i] += fb.f2[i];
        on_a.torque_about_com[i] += fb.t2[i];
    }
}


}  // namespace

OdePlasticJoint::OdePlasticJoint(dWorldID world, dBodyID a, dBodyID b, const Pose& frame_in_world,
                                 const PlasticJointSettings& settings)
    : world_(world), a_(a), b_(b), driver_(settings, kOdeRows) {
    frame_on_a_ = a ? relative(pose_of(a), frame_in_world) : frame_in_world;
    frame_on_b_ = relative(pose_of(b), frame_in_world);
    translations_ = dJointGroupCreate(0);
    const PlasticJointLaw& law = driver_.law();
    hinge_dof_ = hinge_dof(law);
    if (hinge_dof_) {
        hinge_ = dJointCreateHinge(world_, nullptr);
        dJointAttach(hinge_, b_, a_);  // body 1 = b: the motor row's velocity is +(the dof's rate)
        dJointSetFeedback(hinge_, &rotation_feedback_);
        hold_hinge_where_it_is(measure());
        return;
    }
    bool any_rotation_row = false;
    for (Dof dof : kAllDofs) {
        if (is_rotation(dof) && law.mode(dof) != DofMode::Free) any_rotation_row = true;
    }
    if (any_rotation_row) {
        rotations_ = dJointCreateAMotor(world_, nullptr);
        dJointAttach(rotations_, b_, a_);  // body 1 = b: a row's velocity is +(the dof's rate)
        dJointSetAMotorMode(rotations_, dAMotorUser);
        dJointSetAMotorNumAxes(rotations_, 3);
        dJointSetFeedback(rotations_, &rotation_feedback_);
    }
    if (law.mode(Dof::Qx) == DofMode::Rigid && law.mode(Dof::N) == DofMode::Rigid && law.mode(Dof::Qz) == DofMode::Rigid) {
        ball_ = dJointCreateBall(world_, nullptr);
        dJointAttach(ball_, b_, a_);
        dJointSetBallAnchor(ball_, frame_in_world.origin[0], frame_in_world.origin[1], frame_in_world.origin[2]);
        dJointSetFeedback(ball_, &ball_feedback_);
    }
}

OdePlasticJoint::~OdePlasticJoint() {
    if (hinge_) dJointDestroy(hinge_);
    if (rotations_) dJointDestroy(rotations_);
    if (ball_) dJointDestroy(ball_);
    dJointGroupDestroy(translations_);
}

void OdePlasticJoint::engage(double now) {
    const JointFrameState state = measure();
    // Hold the anchor (and a hinge the other two rotations) where it is now.
    if (ball_) dJointSetBallAnchor(ball_, state.axes.anchor[0], state.axes.anchor[1], state.axes.anchor[2]);
    if (hinge_) hold_hinge_where_it_is(state);
    driver_.engage(state.positions, now);
}

void OdePlasticJoint::hold_hinge_where_it_is(const JointFrameState& state) {
    // ODE keeps the axis in each body's coordinates as it is in the world now: the hinge holds the
    // anchor and the two other rotations as they are, and its motor row turns about the axis.
    const Vec3& axis = state.axes.rotation[*hinge_dof_ - 3];
    dJointSetHingeAnchor(hinge_, state.axes.anchor[0], state.axes.anchor[1], state.axes.anchor[2]);
    dJointSetHingeAxis(hinge_, axis[0], axis[1], axis[2]);
}

JointFrameState OdePlasticJoint::measure() const {
    const Pose on_a = a_ ? compose(pose_of(a_), frame_on_a_) : frame_on_a_;
    return measure_joint_swing_twist(on_a, compose(pose_of(b_), frame_on_b_));
}

std::optional<BodyVelocity> OdePlasticJoint::a_body_velocity() const {
    return a_ ? std::optional<BodyVelocity>(body_velocity(a_)) : std::nullopt;
}

void OdePlasticJoint::before_step(double dt) {
    if (driver_.broken()) return;
    const JointFrameState state = measured_ ? *measured_ : measure();  // the end of a step is the start of the next
    measured_.reset();
    if (rows_work_.counting()) rows_work_.step_starts(body_velocity(b_), a_body_velocity());
    const dReal* centre = dBodyGetPosition(b_);
    const PerDof<std::optional<RowCommand>> commands =
        driver_.plan(state, {centre[0], centre[1], centre[2]}, dt, [&] {
            return std::pair{inertia_of(b_), a_ ? std::optional<BodyInertia>(inertia_of(a_)) : std::nullopt};
        });
    set_rotation_rows(state, commands, dt);
    set_translation_rows(state, commands, dt);
}

void OdePlasticJoint::set_rotation_rows(const JointFrameState& state, const PerDof<std::optional<RowCommand>>& commands,
                                        double dt) {
    if (hinge_) {
        set_hinge_motor(state, commands, dt);
        return;
    }
    if (!rotations_) return;
    static constexpr int kVel[3] = {dParamVel1, dParamVel2, dParamVel3};
    static constexpr int kFMax[3] = {dParamFMax1, dParamFMax2, dParamFMax3};
    for (int i = 0; i < 3; ++i) {
        const Vec3& gradient = state.axes.rotation[i];
        dJointSetAMotorAxis(rotations_, i, 0, gradient[0], gradient[1], gradient[2]);  // rel 0: world axes
        const std::size_t dof = 3 + static_cast<std::size_t>(i);
        const RowSetting row = rotation_row_setting(driver_, state, commands[dof], dof, dt);
        dJointSetAMotorParam(rotations_, kVel[i], row.velocity);
        dJointSetAMotorParam(rotations_, kFMax[i], row.bound);
    }
}

void OdePlasticJoint::set_hinge_motor(const JointFrameState& state, const PerDof<std::optional<RowCommand>>& commands,
                                      double dt) {
    const RowSetting row = rotation_row_setting(driver_, state, commands[*hinge_dof_], *hinge_dof_, dt);
    dJointSetHingeParam(hinge_, dParamVel, row.velocity);
    dJointSetHingeParam(hinge_, dParamFMax, row.bound);
}

void OdePlasticJoint::set_translation_rows(const JointFrameState& state,
                                           const PerDof<std::optional<RowCommand>>& commands, double dt) {
    if (ball_ || hinge_) return;  // they hold all three
    dJointGroupEmpty(translations_);
    translation_joints_ = 0;
    std::array<RowSetting, 3> rows;
    for (std::size_t i = 0; i < 3; ++i) {
        rows[i] = row_setting(driver_.law().mode(kAllDofs[i]), commands[i], state.positions[i],
                              driver_.engaged_positions()[i], dt);
    }
    // Contact 1: normal along z, rows along x (fdir1) and y (= z × x); contact 2: normal along x,
    // a row along z.
    struct Pair {
        std::size_t normal, first, second;
        bool has_second;
    };
    const Pair pairs[2] = {{2, 0, 1, true}, {0, 2, 0, false}};
    for (const Pair& p : pairs) {
        const bool first = rows[p.first].bound > 0.0, second = p.has_second && rows[p.second].bound > 0.0;
        if (!first && !second) continue;
        dContact c{};
        c.surface.mode = dContactMu2 | dContactFDir1 | dContactMotion1 | dContactMotion2 | dContactSoftCFM;
        c.surface.mu = rows[p.first].bound;
        c.surface.motion1 = rows[p.first].velocity;
        c.surface.mu2 = second ? rows[p.second].bound : 0.0;
        c.surface.motion2 = second ? rows[p.second].velocity : 0.0;
        c.surface.soft_cfm = kInertCfm;
        for (int k = 0; k < 3; ++k) {
            c.geom.pos[k] = state.axes.anchor[k];
            c.geom.normal[k] = state.axes.translation[p.normal][k];
            c.fdir1[k] = state.axes.translation[p.first][k];
        }
        dJointID joint = dJointCreateContact(world_, translations_, &c);
        dJointAttach(joint, b_, a_);
        dJointSetFeedback(joint, &translation_feedback_[translation_joints_++]);
    }
}

void OdePlasticJoint::disable_rows() {
    if (hinge_) dJointDisable(hinge_);
    if (rotations_) dJointDisable(rotations_);
    if (ball_) dJointDisable(ball_);
    dJointGroupEmpty(translations_);
    translation_joints_ = 0;
}

void OdePlasticJoint::wake() {
    dBodyEnable(b_);
    if (a_) dBodyEnable(a_);
}

JointEvent OdePlasticJoint::after_step(double dt) {
    if (driver_.broken()) return driver_.settle({}, {}, dt);  // None; keeps the clock
    WorldLoad load, on_a;
    if (rotations_ || hinge_) add(load, on_a, rotation_feedback_);
    if (ball_) add(load, on_a, ball_feedback_);
    for (int i = 0; i < translation_joints_; ++i) add(load, on_a, translation_feedback_[i]);
    if (rows_work_.counting()) rows_work_.step_ends(load, on_a, body_velocity(b_), a_body_velocity(), dt);
    measured_ = measure();
    const JointEvent event = driver_.settle(load, measured_->positions, dt);
    if (event != JointEvent::None) wake();
    if (event == JointEvent::Broke) disable_rows();  // broken stays broken
    return event;
}

}  // namespace plascap
