#include "ode_plastic_rows.hpp"

#include <algorithm>
#include <bitset>
#include <cmath>

#include "ode_body_velocity.hpp"
#include "plascap/adapters/prefetch.hpp"

namespace plascap {
namespace {

Vec3 centre_of(dBodyID body) {
    const dReal* x = dBodyGetPosition(body);
    return {x[0], x[1], x[2]};
}

void store(dReal* at, const Vec3& v) {
    at[0] = v[0], at[1] = v[1], at[2] = v[2];
}

// A Push row asks for an unreachable rate and so ends on its bound, as in the Bullet adapter. Its
// force range stays [−|F|, |F|]: ODE's dWorldStep (Dantzig) needs lower ≤ 0 ≤ upper.
constexpr double kPushSpeed = 1e4;

// sign × load into the body's force and torque accumulators. A joint whose body has gone
// (dBodyDestroy detaches its joints) has nothing to push.
void add_to_accumulators(dxBody* body, const WorldLoad& load, double sign) {
    if (!body) return;
    const Vec3 f = scaled(load.force, sign), t = scaled(load.torque_about_com, sign);
    dBodyAddForce(body, f[0], f[1], f[2]);
    dBodyAddTorque(body, t[0], t[1], t[2]);
}

}  // namespace

const PerDof<double> OdePlasticRows::kNoMotion{};

OdePlasticRows::RowJacobian OdePlasticRows::jacobian(std::size_t i) const {
    // +J on b, −J on a (plascap's Bullet constraint writes the same rows). A translation row acts at
    // the anchor: J·v = axis·(v_b + ω_b × r_b − v_a − ω_a × r_a); a rotation row along the angle's
    // gradient: J·v = g·(ω_b − ω_a).
    if (i < 3) {
        const Vec3& axis = axes_.translation[i];
        return {axis, cross(lever_b_, axis), scaled(axis, -1.0), scaled(cross(lever_a_, axis), -1.0)};
    }
    const Vec3& gradient = axes_.rotation[i - 3];
    return {Vec3{}, gradient, Vec3{}, scaled(gradient, -1.0)};
}

OdePlasticRows* OdePlasticRows::create(dWorldID world, dBodyID b, dBodyID a) {
    auto* joint = new OdePlasticRows(world);  // dBase's operator new: ODE's allocator, as dJointDestroy frees
    dJointAttach(joint, b, a);                // b first: ODE's J1, f1 and t1 are b's
    return joint;
}

void OdePlasticRows::set_geometry(const JointFrameState& state) {
    dxBody* b = node[0].body;  // ODE's first body
    dxBody* a = node[1].body;  // 0: the world
    axes_ = state.axes;
    lever_b_ = difference(state.axes.anchor, centre_of(b));
    lever_a_ = a ? difference(state.axes.anchor, centre_of(a)) : Vec3{};
}

void OdePlasticRows::count_rows() {
    count_ = 0;
    all_unbounded_ = true;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!has_row(i)) continue;
        ++count_;
        all_unbounded_ = all_unbounded_ && targets_[i].lower == -dInfinity && targets_[i].upper == dInfinity;
    }
}

void OdePlasticRows::getInfo1(Info1* info) {
    if (correcting_) {
        info->m = static_cast<std::uint8_t>(std::bitset<kDofCount>(pass_rows()).count());
        info->nub = 0;  // the pass is QuickStep's, which reads no nub
        return;
    }
    info->m = count_;
    info->nub = all_unbounded_ ? count_ : 0;  // ODE solves a joint of only unbounded rows apart
}

void OdePlasticRows::getSureMaxInfo(SureMaxInfo* info) { info->max_m = 6; }

void OdePlasticRows::load_next_joint() const {
    // `next` may be any of ODE's joints, and smaller than this one: lines past its end are loaded
    // for nothing, and a prefetch never faults.
    if (next) prefetch_bytes<sizeof(OdePlasticRows), PrefetchFor::Reading>(next);
}

void OdePlasticRows::getInfo2(dReal, dReal, int rowskip, dReal* J1, dReal* J2, int pairskip, dReal* pairRhsCfm,
                              dReal* pairLoHi, int*) {
    using namespace ode_joint_object;
    load_next_joint();
    const std::uint8_t written = correcting_ ? pass_rows() : rows_;
    int r = 0;
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        if (!((written >> i) & 1u)) continue;
        dReal* on_b = J1 + r * rowskip;
        dReal* on_a = J2 ? J2 + r * rowskip : nullptr;  // ODE zeroed both
        const RowJacobian j = jacobian(i);
        if (i < 3) store(on_b + dDA_LX, j.linear_b);  // a rotation row's linear parts are 0
        store(on_b + dDA_AX, j.angular_b);
        if (on_a) {
            if (i < 3) store(on_a + dDA_LX, j.linear_a);
            store(on_a + dDA_AX, j.angular_a);
        }
        const OdeRowTarget& t = targets_[i];
        if (correcting_) {
            // A rigid or held row's rate is all correction; its range what the step left of it.
            pairRhsCfm[r * pairskip + kRhs] = t.rate;
            pairLoHi[r * pairskip + kLo] = std::min(0.0, t.lower - split_->solved_forces[i]);
            pairLoHi[r * pairskip + kHi] = std::max(0.0, t.upper - split_->solved_forces[i]);
        } else if (!split_ || ((kept_push_ >> i) & 1u)) {
            pairRhsCfm[r * pairskip + kRhs] = t.rate;
            pairLoHi[r * pairskip + kLo] = t.lower;
            pairLoHi[r * pairskip + kHi] = t.upper;
        } else {
            // Split: the rate without its correction (for a rigid or held row, 0), from the warm
            // start f₀. A warm row solves for λ − f₀; with ODE's CFM the row reads J·v = c − cfm·λ
            // (ODE's user guide, "Constraint Force Mixing"), which holds for the whole force when c
            // carries −cfm·f₀.
            const double f0 = is_warm(i) ? split_->warm_force[i] : 0.0;
            pairRhsCfm[r * pairskip + kRhs] = -pairRhsCfm[r * pairskip + kCfm] * f0;
            pairLoHi[r * pairskip + kLo] = t.lower - f0;
            pairLoHi[r * pairskip + kHi] = t.upper - f0;
        }
        ++r;
    }
}

void OdePlasticRows::keep_one_push_as_row() {
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!has_push(i)) continue;
        const double f = targets_[i].upper;
        targets_[i] = OdeRowTarget{f > 0.0 ? kPushSpeed : -kPushSpeed, -std::abs(f), std::abs(f)};
        pushes_ &= static_cast<std::uint8_t>(~(1u << i));
        rows_ |= static_cast<std::uint8_t>(1u << i);
        kept_push_ = static_cast<std::uint8_t>(1u << i);
        return;
    }
}

void OdePlasticRows::add_row_load(std::size_t i, double f, WorldLoad& on_b, WorldLoad& on_a) const {
    // A row's force f on the bodies is Jᵀ·f: what ODE's feedback reports of a row at f.
    const RowJacobian j = jacobian(i);
    add_scaled(on_b.force, j.linear_b, f);
    add_scaled(on_b.torque_about_com, j.angular_b, f);
    add_scaled(on_a.force, j.linear_a, f);
    add_scaled(on_a.torque_about_com, j.angular_a, f);
}

void OdePlasticRows::add_each_push(WorldLoad& on_b, WorldLoad& on_a) const {
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (has_push(i)) add_row_load(i, targets_[i].upper, on_b, on_a);
        if (is_warm(i)) add_row_load(i, split_->warm_force[i], on_b, on_a);
    }
}

void OdePlasticRows::start_warm() {
    // As a sequential-impulse solver carries each row's impulse to the next step (Catto, "Iterative
    // Dynamics with Temporal Coherence", GDC 2005: warm starting); ODE 0.16 has it only as a
    // compile-time option of its quickstep.cpp, off in its builds.
    warm_ = 0;
    split_->corrected_motion = {};
    const std::uint8_t carried = static_cast<std::uint8_t>(rows_ & last_rows_ & ~kept_push_);
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!((carried >> i) & 1u)) continue;
        const double f0 = std::clamp(split_->last_forces[i], targets_[i].lower, targets_[i].upper);
        if (f0 == 0.0) continue;
        split_->warm_force[i] = f0;
        warm_ |= static_cast<std::uint8_t>(1u << i);
    }
}

double OdePlasticRows::largest_correction() const {
    double largest = 0.0;
    if (!split_) return largest;
    const std::uint8_t corrected = corrected_rows();
    for (std::size_t i = 0; i < kDofCount; ++i)
        if ((corrected >> i) & 1u) largest = std::max(largest, std::abs(targets_[i].rate));
    return largest;
}

void OdePlasticRows::begin_correction_pass(const std::optional<PerDof<double>>& solved) {
    if (!split_) return;  // a joint of another stepper: no rows in the pass
    correcting_ = true;
    split_->pass_solved = solved.has_value();
    if (solved) split_->solved_forces = *solved;
    split_->velocity_feedback = feedback;
    feedback = nullptr;
}

bool OdePlasticRows::end_correction_pass(double dt) {
    if (!correcting_) return false;
    correcting_ = false;
    feedback = split_->velocity_feedback;
    if (!split_->pass_solved) return false;
    const BodyVelocity on_b = body_velocity(node[0].body);
    const BodyVelocity on_a = body_velocity(node[1].body);  // the world (0): at rest
    const std::uint8_t corrected = pass_rows();
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!((corrected >> i) & 1u)) continue;
        const RowJacobian j = jacobian(i);
        split_->corrected_motion[i] = (dot(j.linear_b, on_b.linear) + dot(j.angular_b, on_b.angular) + dot(j.linear_a, on_a.linear) +
                                dot(j.angular_a, on_a.angular)) *
                               dt;
    }
    return true;
}

void OdePlasticRows::apply_pushes(double sign) {
    WorldLoad on_b, on_a;
    add_each_push(on_b, on_a);
    add_to_accumulators(node[0].body, on_b, sign);
    add_to_accumulators(node[1].body, on_a, sign);
    pushes_applied_ = sign > 0.0;
}

}  // namespace plascap
