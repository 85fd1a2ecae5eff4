#include "plascap/adapters/plastic_joint_law.hpp"

#include <cmath>

#include "coupled_yield.hpp"

namespace plascap {

PlasticJointLaw::PlasticJointLaw(const PlasticJointSettings& settings) : settings_(settings) {
    validate_joint_settings(settings, "plastic joint");
    for (Dof dof : kAllDofs) {
        if (mode(dof) != DofMode::Plastic) continue;
        laws_[index(dof)].emplace(settings.laws[index(dof)]);
        if (settings.yield_condition) laws_[index(dof)]->couple();
    }
    if (settings.yield_condition) {
        axis_positive_ = settings.yield_condition->axis_capacity(true);
        axis_negative_ = settings.yield_condition->axis_capacity(false);
    }
}

PerDof<ElasticPlasticLaw*> PlasticJointLaw::plastic_laws() {
    PerDof<ElasticPlasticLaw*> laws{};
    for (std::size_t i = 0; i < kDofCount; ++i) laws[i] = laws_[i] ? &*laws_[i] : nullptr;
    return laws;
}

const ElasticPlasticLaw* PlasticJointLaw::law(Dof dof) const {
    const auto& law = laws_[index(dof)];
    return law ? &*law : nullptr;
}

PerDof<double> PlasticJointLaw::continuous(const PerDof<double>& measured) const {
    // A rotation dof's measured angle wraps at ±π; the law needs it continuous, or a joint turning
    // past π books a 2π jump as flow (and its work with the wrong sign).
    PerDof<double> out = measured;
    for (Dof dof : kAllDofs) {
        if (!is_rotation(dof)) continue;
        const std::size_t i = index(dof);
        const double turn = 2.0 * std::acos(-1.0);
        const double step = measured[i] - last_measured_[i];
        out[i] = last_continuous_[i] + (step - turn * std::round(step / turn));
    }
    return out;
}

void PlasticJointLaw::track(const PerDof<double>& measured, const PerDof<double>& continuous_positions) {
    last_measured_ = measured;
    last_continuous_ = continuous_positions;
}

void PlasticJointLaw::start(const PerDof<double>& measured) {
    track(measured, measured);
    const PerDof<double>& positions = measured;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (laws_[i]) laws_[i]->start(positions[i]);
    }
}

PerDof<std::optional<RowCommand>> PlasticJointLaw::plan(const PerDof<double>& measured, double dt,
                                                        const PerDof<double>& effective_masses) {
    const PerDof<double> positions = continuous(measured);
    track(measured, positions);
    PerDof<std::optional<RowCommand>> commands;
    PerDof<std::optional<double>> bounds;
    if (settings_.yield_condition)
        bounds = detail::coupled_hold_bounds(*settings_.yield_condition, {axis_positive_, axis_negative_}, hint_,
                                             last_loads_, plastic_laws());
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (laws_[i]) commands[i] = laws_[i]->plan(positions[i], dt, effective_masses[i], bounds[i]);
    }
    return commands;
}

bool PlasticJointLaw::settle(const PerDof<double>& measured, const PerDof<double>& forces, double time) {
    if (broken()) return false;
    const PerDof<double> positions = continuous(measured);
    track(measured, positions);
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (laws_[i]) laws_[i]->settle(positions[i], forces[i]);
        last_loads_[i] = -forces[i];
    }
    if (settings_.yield_condition)
        detail::coupled_return_mapping(*settings_.yield_condition, {axis_positive_, axis_negative_}, hint_, positions,
                                       last_loads_, plastic_laws());
    if (plastic_displacement() > settings_.max_plastic_displacement ||
        plastic_rotation() > settings_.max_plastic_rotation) {
        broken_at_ = time;
        return true;
    }
    return false;
}

double PlasticJointLaw::accumulated(bool rotations) const {
    double sum = 0.0;
    for (Dof dof : kAllDofs) {
        if (is_rotation(dof) == rotations && laws_[index(dof)]) sum += laws_[index(dof)]->accumulated_plastic();
    }
    return sum;
}

double PlasticJointLaw::plastic_displacement() const { return accumulated(false); }
double PlasticJointLaw::plastic_rotation() const { return accumulated(true); }

double PlasticJointLaw::dissipated() const {
    double sum = 0.0;
    for (const auto& law : laws_) {
        if (law) sum += law->dissipated();
    }
    return sum;
}

double PlasticJointLaw::elastic_energy(const PerDof<double>& measured) const {
    const PerDof<double> positions = continuous(measured);
    double sum = 0.0;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (laws_[i]) sum += laws_[i]->elastic_energy(positions[i]);
    }
    return sum;
}

}  // namespace plascap
