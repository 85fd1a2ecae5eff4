#include "plascap/adapters/elastic_plastic_law.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "plascap/input_error.hpp"

namespace plascap {
namespace {

bool positive_finite(double value) { return value > 0.0 && std::isfinite(value); }

}  // namespace

void validate_dof_law(const DofLaw& law, const char* where) {
    if (!positive_finite(law.capacity_positive) || !positive_finite(law.capacity_negative)) {
        throw InputError(std::string(where) + ": capacities must be positive and finite (got " +
                         std::to_string(law.capacity_positive) + " and " + std::to_string(law.capacity_negative) + ")");
    }
    if (law.stiffness && !positive_finite(*law.stiffness)) {
        throw InputError(std::string(where) + ": stiffness must be positive and finite (got " +
                         std::to_string(*law.stiffness) + ")");
    }
}

ElasticPlasticLaw::ElasticPlasticLaw(const DofLaw& law, bool two_sided_bounds)
    : capacity_positive_(law.capacity_positive), capacity_negative_(law.capacity_negative),
      stiffness_(law.stiffness.value_or(0.0)), regime_(law.stiffness ? Regime::ElasticPlastic : Regime::RigidPlastic),
      two_sided_bounds_(two_sided_bounds) {}

void ElasticPlasticLaw::start(double position) {
    plastic_offset_ = position;
    planned_position_ = position;
}

RowCommand ElasticPlasticLaw::plan(double position, double dt, double effective_mass, std::optional<double> joint_bound) {
    planned_position_ = position;
    planned_stopping_stiffness_ = effective_mass / (dt * dt);
    planned_ = true;
    regime_ = choose_regime(stiffness(), effective_mass, dt);  // eq. 3.2
    if (regime_ != Regime::ElasticPlastic) {
        // Paper §2: target velocity 0, force bounded by the capacity; plus the correction.
        RowCommand hold;
        hold.kind = RowCommand::Kind::Hold;
        hold.bound = joint_bound ? *joint_bound : hold_bound();
        held_on_both_capacities_ = two_sided_bounds_ && !joint_bound;
        last_bound_ = hold.bound;
        hold.lower = -side_bound(-1.0), hold.upper = side_bound(1.0);  // f on b
        hold.velocity = -kHoldCorrection * (position - plastic_offset_) / dt;
        return hold;
    }
    // Explicit spring force from the start-of-step position, capped at the capacities.
    const double spring = -stiffness_ * (position - plastic_offset_);
    const double force = coupled_ ? spring : std::clamp(spring, -capacity_positive_, capacity_negative_);
    RowCommand push;
    push.kind = RowCommand::Kind::Push;
    push.force = force;
    return push;
}

void ElasticPlasticLaw::settle(double position, double applied_force, double corrected_motion) {
    moved_ = false;
    if (regime_ == Regime::ElasticPlastic) {
        if (!coupled_) settle_elastic_plastic(position);
    } else {
        settle_rigid_plastic(position, applied_force, corrected_motion);
    }
    last_force_sign_ = static_cast<std::int8_t>((applied_force > 0.0) - (applied_force < 0.0));
}

void ElasticPlasticLaw::settle_rigid_plastic(double position, double applied_force, double corrected_motion) {
    // Motion at capacity is plastic flow (flow_criterion.hpp) and the row's work on it, −f·Δx, is
    // absorbed. A flow confirmed late takes up the motion of the steps at the bound before it, and
    // the row's work on that motion.
    const double side_bound = this->side_bound(applied_force);
    const double share = side_bound > 0.0 ? applied_force / side_bound : 0.0;
    const double motion = position - planned_position_;
    const double stopping = std::isfinite(planned_stopping_stiffness_) && side_bound > 0.0
                                ? planned_stopping_stiffness_ * std::abs(motion) / side_bound
                                : 0.0;  // m·|Δx|/dt² over the bound
    const bool flowed = flow_.flowed(share, stopping);
    if (!flow_.at_bound()) {
        if (pending_) clear_pending();  // the solver's motion: the hold takes it back
        return;
    }
    Books& books = *books_;
    books.pending_motion += motion;
    books.pending_work += -applied_force * motion * books.work_factor;
    books.pending_correction_work += -applied_force * corrected_motion * books.work_factor;
    pending_ = true;
    if (!flowed) return;
    plastic_offset_ += books.pending_motion;
    books.accumulated += std::abs(books.pending_motion);
    books.dissipated += books.pending_work;
    books.dissipated_by_corrections += books.pending_correction_work;
    moved_ = true;
    clear_pending();
}

void ElasticPlasticLaw::clear_pending() {
    books_->pending_motion = books_->pending_work = books_->pending_correction_work = 0.0;
    pending_ = false;
}

void ElasticPlasticLaw::settle_elastic_plastic(double position) {
    // Return mapping: move x_p until the elastic force is back on the capacity it passed.
    const double k = stiffness_;
    const double trial = -k * (position - plastic_offset_);
    double moved_to = plastic_offset_;
    double capacity = 0.0;
    if (trial < -capacity_positive_) {
        moved_to = position - capacity_positive_ / k;
        capacity = capacity_positive_;
    } else if (trial > capacity_negative_) {
        moved_to = position + capacity_negative_ / k;
        capacity = capacity_negative_;
    }
    if (moved_to == plastic_offset_) return;  // inside the capacities: nothing to book
    const double step = std::abs(moved_to - plastic_offset_);
    books_->accumulated += step;
    books_->dissipated += capacity * step * books_->work_factor;  // the force stays on the capacity while x_p moves
    plastic_offset_ = moved_to;
    moved_ = true;
}

void ElasticPlasticLaw::flow(double step, double load) {
    plastic_offset_ += step;
    books_->accumulated += std::abs(step);
    books_->dissipated += load * step * books_->work_factor;  // the joint's resisting force −load does −(−load)·step of work on the flow
    moved_ = true;
}

double ElasticPlasticLaw::omega_dt() const {
    if (!has_stiffness() || !planned_) return 0.0;
    // √(k/m)·dt = √(k/(m/dt²)) (regime.hpp); spring_omega_dt's ∞ for a mass not > 0.
    if (!(planned_stopping_stiffness_ > 0.0)) return INFINITY;
    return std::sqrt(stiffness_ / planned_stopping_stiffness_);
}

double ElasticPlasticLaw::elastic_energy(double position) const {
    if (regime_ != Regime::ElasticPlastic) return 0.0;
    const double stretch = position - plastic_offset_;
    return 0.5 * stiffness_ * stretch * stretch;
}

}  // namespace plascap
