#include "plascap/adapters/ode_plastic_joint.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "plascap/adapters/joint_loads.hpp"
#include "plascap/adapters/prefetch.hpp"
#include "plascap/adapters/row_effective_mass.hpp"
#include "plascap/adapters/swing_twist.hpp"
#include "ode_body_velocity.hpp"
#include "ode_plastic_rows.hpp"

namespace plascap {
namespace {

// What plascap's ODE rows (ode_plastic_rows.hpp) measure and carry: swing and twist, and both
// capacities of a Hold row as its two bounds, as plascap's Bullet constraint.
constexpr RowCapabilities kOdeRows{RotationMeasure::SwingTwist, true};

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
    // I_body⁻¹ by Cramer's rule (adjugate / det), one division for all. ODE keeps I as 3 rows of 4,
    // symmetric (dMassSetParameters takes six values, dMassRotate keeps the symmetry), so its inverse
    // is too and six entries make it: s[i][j] for i ≤ j.
    const double a = m.I[0], b = m.I[1], c = m.I[2], e = m.I[5], f = m.I[6], k = m.I[10];
    const double co_a = e * k - f * f, co_b = f * c - b * k, co_c = b * f - e * c;
    const double inv_det = 1.0 / (a * co_a + b * co_b + c * co_c);
    const double s00 = co_a * inv_det, s01 = co_b * inv_det, s02 = co_c * inv_det;
    const double s11 = (a * k - c * c) * inv_det, s12 = (c * b - a * f) * inv_det, s22 = (a * e - b * b) * inv_det;
    const Mat3 inverse_body = {{{s00, s01, s02}, {s01, s11, s12}, {s02, s12, s22}}};
    // I_world⁻¹ = R·I_body⁻¹·Rᵀ (Baraff, "An Introduction to Physically Based Modeling: Rigid Body
    // Simulation I", eq. 2-37ff: I = R·I_body·Rᵀ, so its inverse turns the same way): symmetric
    // again, so of (R·I_body⁻¹)·Rᵀ the upper triangle is computed and mirrored. R is ODE's, 3 rows
    // of 4, read here rather than through pose_of (a Pose built for its rotation: 19 instructions more).
    const dReal* rotation = dBodyGetRotation(body);
    const Mat3 r = {{{rotation[0], rotation[1], rotation[2]}, {rotation[4], rotation[5], rotation[6]},
                     {rotation[8], rotation[9], rotation[10]}}};
    const Mat3 rs = multiply(r, inverse_body);
    const double w00 = dot(rs[0], r[0]), w01 = dot(rs[0], r[1]), w02 = dot(rs[0], r[2]);
    const double w11 = dot(rs[1], r[1]), w12 = dot(rs[1], r[2]), w22 = dot(rs[2], r[2]);
    BodyInertia inertia;
    inertia.inverse_inertia_world = {{{w00, w01, w02}, {w01, w11, w12}, {w02, w12, w22}}};
    inertia.inverse_mass = 1.0 / m.mass;
    const dReal* x = dBodyGetPosition(body);
    inertia.centre = {x[0], x[1], x[2]};
    return inertia;
}

// Dof i's row for the next step; none for a free dof.
std::optional<OdeRowTarget> row_target(DofMode mode, const std::optional<RowCommand>& command, double position,
                                       double reference, double dt) {
    if (mode == DofMode::Free) return std::nullopt;
    if (mode == DofMode::Rigid) return OdeRowTarget{-kHoldCorrection * (position - reference) / dt, -dInfinity, dInfinity};
    if (command->kind == RowCommand::Kind::Hold) return OdeRowTarget{command->velocity, command->lower, command->upper};
    return OdeRowTarget{0.0, command->force, command->force};  // pinned: the spring's force, pushed (set_rows)
}

}  // namespace

OdePlasticJoint::OdePlasticJoint(dWorldID world, dBodyID a, dBodyID b, const Pose& frame_in_world,
                                 const PlasticJointSettings& settings)
    : a_(a), b_(b), driver_(settings, kOdeRows) {
    frame_on_a_ = a ? relative(pose_of(a), frame_in_world) : frame_in_world;
    frame_on_b_ = relative(pose_of(b), frame_in_world);
    rows_ = OdePlasticRows::create(world, b_, a_);
    dJointSetFeedback(rows_, &feedback_);
}

OdePlasticJoint::~OdePlasticJoint() {
    rows_->withdraw_pushes();  // a push no step took would act on the bodies without the joint
    dJointDestroy(rows_);
}

void OdePlasticJoint::engage(double now) {
    driver_.engage(measure().positions, now);
    mark_feedback_unwritten();
}

// A NaN with a payload of plascap's own: ODE's arithmetic makes NaNs with its CPU's default payload,
// so it never writes this one.
static_assert(sizeof(dReal) == sizeof(std::uint64_t), "plascap's ODE adapter needs ODE in double precision");
constexpr std::uint64_t kUnwrittenBits = 0x7ff8'0000'5e1e'e9edULL;

void OdePlasticJoint::mark_feedback_unwritten() { std::memcpy(&feedback_.f1[0], &kUnwrittenBits, sizeof(dReal)); }

bool OdePlasticJoint::stepped() const {
    std::uint64_t bits;
    std::memcpy(&bits, &feedback_.f1[0], sizeof bits);
    return bits != kUnwrittenBits;
}

bool OdePlasticJoint::note_solved() {
    solved_ = !driver_.broken() && stepped();
    return solved_;
}

JointEvent OdePlasticJoint::idle(double dt) { return act_on(driver_.idle(dt)); }

JointEvent OdePlasticJoint::act_on(JointEvent event) {
    if (event != JointEvent::None) wake();
    if (event == JointEvent::Broke) {
        rows_->withdraw_pushes();  // broken while asleep: its last push must not act when they wake
        dJointDisable(rows_);      // broken stays broken
    }
    return event;
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
    plan(measure(), dt);
}

void OdePlasticJoint::plan(const JointFrameState& state, double dt) {
    if (rows_work_.counting()) rows_work_.step_starts(body_velocity(b_), a_body_velocity());
    const PerDof<std::optional<RowCommand>> commands =
        driver_.plan(state, dt, [&] {
            return std::pair{inertia_of(b_), a_ ? std::optional<BodyInertia>(inertia_of(a_)) : std::nullopt};
        });
    rows_->set_rows(state, [&](std::size_t i) {
        return row_target(driver_.law().mode(kAllDofs[i]), commands[i], state.positions[i],
                          driver_.engaged_positions()[i], dt);
    });
}

void OdePlasticJoint::split_corrections(bool on) { rows_->split_corrections(on); }

void OdePlasticJoint::begin_correction_pass() {
    if (driver_.broken() || !stepped()) {
        rows_->begin_correction_pass(std::nullopt);
        return;
    }
    WorldLoad on_b = feedback_on_b();
    WorldLoad on_a;
    rows_->add_pushes(on_b, on_a);
    rows_->begin_correction_pass(rows_->forces_on_b(on_b));
}

double OdePlasticJoint::end_correction_pass(double dt) {
    if (!rows_->end_correction_pass(dt)) return 0.0;  // not in the step: its loads were not either
    // The pushes' and warm starts' loads were in the bodies' accumulators for the step, with the
    // caller's: their work over the pass's motion is the joint's, not the caller's loads'.
    WorldLoad on_b, on_a;
    rows_->add_pushes(on_b, on_a);
    return held_load_work(on_b, body_velocity(b_), dt) + held_load_work(on_a, body_velocity(a_), dt);  // a_ 0: at rest
}

double OdePlasticJoint::largest_correction() const { return rows_->largest_correction(); }

void OdePlasticJoint::prefetch() const { prefetch_object(this); }

void OdePlasticJoint::prefetch_rows() const { prefetch_object(rows_); }

std::size_t OdePlasticJoint::state_bytes() { return sizeof(OdePlasticJoint) + sizeof(OdePlasticRows); }

void OdePlasticJoint::wake() {
    dBodyEnable(b_);
    if (a_) dBodyEnable(a_);
}

JointEvent OdePlasticJoint::after_step(double dt) {
    if (!note_solved()) return idle(dt);  // broken: None, keeps the clock
    return settle(measure(), dt);
}

WorldLoad OdePlasticJoint::feedback_on_b() const {
    // Bodies are attached as (b, a): ODE's f1, t1 act on b, and f2, t2 on a.
    return {{feedback_.f1[0], feedback_.f1[1], feedback_.f1[2]}, {feedback_.t1[0], feedback_.t1[1], feedback_.t1[2]}};
}

JointEvent OdePlasticJoint::settle(const JointFrameState& state, double dt) {
    WorldLoad on_b = feedback_on_b();
    WorldLoad on_a{{feedback_.f2[0], feedback_.f2[1], feedback_.f2[2]}, {feedback_.t2[0], feedback_.t2[1], feedback_.t2[2]}};
    rows_->pushes_taken();  // the step that solved the joint applied them
    rows_->add_pushes(on_b, on_a);
    if (rows_work_.counting()) rows_work_.step_ends(on_b, on_a, body_velocity(b_), a_body_velocity(), dt);
    const PerDof<double> forces = rows_->forces_on_b(on_b);
    rows_->remember_forces(forces);
    const JointEvent event = driver_.settle(forces, state.positions, dt, rows_->corrected_motion());
    mark_feedback_unwritten();  // read: a step that leaves it so did not solve the joint
    return act_on(event);
}

OdePlasticJoint::Settled OdePlasticJoint::after_step_and_plan(double dt) {
    if (!note_solved()) {
        // Broken (before_step has nothing to do), or asleep: nothing moved, so the rows planned for
        // this step of dt hold for the next — unless they count their work, which needs before_step.
        const JointEvent event = idle(dt);
        return {event, driver_.broken() || !rows_work_.counting()};
    }
    const JointFrameState state = measure();  // the end of this step is the start of the next
    const JointEvent event = settle(state, dt);
    if (driver_.broken()) return {event, true};
    if (rows_work_.counting()) return {event, false};
    plan(state, dt);
    return {event, true};
}

}  // namespace plascap
