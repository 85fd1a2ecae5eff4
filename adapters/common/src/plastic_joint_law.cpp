#include "plascap/adapters/plastic_joint_law.hpp"

#include <algorithm>
#include <cmath>

#include "coupled_yield.hpp"

namespace plascap {

struct PlasticJointLaw::Coupling {
    const YieldCondition& condition;  // owned by settings_
    detail::AxisCapacities axes;      // where the condition meets each dof axis
    YieldHint hint;                   // the last solve's point, to start the next from
};

PlasticJointLaw::PlasticJointLaw(const PlasticJointSettings& settings, RowCapabilities rows)
    : settings_(std::make_shared<const PlasticJointSettings>(settings)), modes_(settings.modes), rows_(rows),
      max_plastic_displacement_(settings.max_plastic_displacement),
      max_plastic_rotation_(settings.max_plastic_rotation) {
    validate_joint_settings(settings, "plastic joint");
    for (Dof dof : kAllDofs) {
        if (mode(dof) != DofMode::Plastic) continue;
        laws_[index(dof)] = ElasticPlasticLaw(settings.laws[index(dof)], rows.two_sided_bounds);
        if (settings.yield_condition) laws_[index(dof)].couple();
    }
    if (const YieldCondition* condition = settings_->yield_condition.get()) {
        // new, not make_unique: an aggregate with a reference member (GCC 12 will not build it from parentheses).
        coupling_.reset(new Coupling{*condition, {condition->axis_capacity(true), condition->axis_capacity(false)}, {}});
    }
}

PlasticJointLaw::~PlasticJointLaw() = default;
PlasticJointLaw::PlasticJointLaw(PlasticJointLaw&&) noexcept = default;
PlasticJointLaw& PlasticJointLaw::operator=(PlasticJointLaw&&) noexcept = default;

PerDof<ElasticPlasticLaw*> PlasticJointLaw::plastic_laws() {
    PerDof<ElasticPlasticLaw*> laws{};
    for (std::size_t i = 0; i < kDofCount; ++i) laws[i] = plastic(i) ? &laws_[i] : nullptr;
    return laws;
}

const ElasticPlasticLaw* PlasticJointLaw::law(Dof dof) const {
    return plastic(index(dof)) ? &laws_[index(dof)] : nullptr;
}

PerDof<double> PlasticJointLaw::continuous(const PerDof<double>& measured) const {
    // A rotation dof's measured angle wraps at ±π, and the Euler triple of R = Rz(θz)·Ry(θy)·Rx(θx)
    // has a second branch, (θx + π, π − θy, θz + π), the same rotation (e.g. Diebel, "Representing
    // attitude", 2006, §5.6): engines report |θy| ≤ π/2, so a joint twisting past 90° jumps from one
    // branch to the other, θx and θz by π. The law needs the angles continuous, or it books each jump
    // as flow (and its work with the wrong sign): of both branches, each unwrapped by whole turns
    // against the last continuous angles, take the nearer. Swing–twist angles have one branch: only
    // the twist wraps.
    const double pi = std::acos(-1.0), turn = 2.0 * pi;
    const std::size_t x = index(Dof::Mx), y = index(Dof::My), z = index(Dof::Mz);
    const auto last = [&](std::size_t i) { return last_continuous_[angle_index(kAllDofs[i])]; };  // dof i's last continuous angle
    const auto unwrap = [&](double angle, std::size_t i) {
        const double step = angle - last(i);
        if (std::abs(step) < pi) return angle;  // within half a turn: no whole turn to take off
        return last(i) + (step - turn * std::round(step / turn));
    };
    PerDof<double> same = measured, other = measured;
    same[x] = unwrap(measured[x], x), same[y] = unwrap(measured[y], y), same[z] = unwrap(measured[z], z);
    if (!euler_rows()) return same;
    const auto distance = [&](const PerDof<double>& p) {
        return std::abs(p[x] - last(x)) + std::abs(p[y] - last(y)) + std::abs(p[z] - last(z));
    };
    // The other branch's θx and θz lie π − |Δx| and π − |Δz| from the last angles where this
    // branch's lie |Δx| and |Δz|: its distance is at least 2π less this one's, so below π this
    // branch is the nearer and the other need not be unwrapped.
    const double same_distance = distance(same);
    if (same_distance < pi) return same;
    other[x] = unwrap(measured[x] + pi, x), other[y] = unwrap(pi - measured[y], y), other[z] = unwrap(measured[z] + pi, z);
    return distance(other) < same_distance ? other : same;
}

void PlasticJointLaw::track(const PerDof<double>& measured, const PerDof<double>& continuous_positions) {
    last_measured_ = rotations_of(measured);
    last_continuous_ = rotations_of(continuous_positions);
}

void PlasticJointLaw::start(const PerDof<double>& measured) {
    track(measured, measured);
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (plastic(i)) laws_[i].start(measured[i]);
    }
}

namespace {

// On the second Euler branch (continuous θy past ±90°, where cos θy < 0) the My dof runs against
// the engines' (θy = π − θy,engine), so its row's rate, force and command change sign; Mx and Mz
// do not (θx = θx,engine + π). Returns −1 there, else 1.
double twist_sign(double continuous_my) { return std::cos(continuous_my) < 0.0 ? -1.0 : 1.0; }
double twist_sign(const PerDof<double>& continuous_positions) { return twist_sign(continuous_positions[index(Dof::My)]); }

}  // namespace

PerDof<double> PlasticJointLaw::last_loads() const {
    PerDof<double> loads;
    for (std::size_t i = 0; i < kDofCount; ++i) loads[i] = -last_forces_[i];
    // On the second Euler branch the My dof runs against the engines' (twist_sign).
    if (euler_rows()) loads[index(Dof::My)] *= twist_sign(last_continuous_[angle_index(Dof::My)]);
    return loads;
}

PerDof<std::optional<RowCommand>> PlasticJointLaw::plan(const PerDof<double>& measured, double dt,
                                                        const PerDof<double>& effective_masses) {
    // The adapters measure at the end of a step what the next step starts from: unwrapped then.
    PerDof<double> positions = measured;
    if (rotations_of(measured) == last_measured_) {  // as last seen: unwrapped then
        for (Dof dof : {Dof::Mx, Dof::My, Dof::Mz}) positions[index(dof)] = last_continuous_[angle_index(dof)];
    } else {
        positions = continuous(measured);
    }
    const PerDof<double> loads = coupling_ ? last_loads() : PerDof<double>{};  // of the last settle, before track()
    track(measured, positions);
    PerDof<std::optional<RowCommand>> commands;
    PerDof<std::optional<double>> bounds;
    if (coupling_)
        bounds = detail::coupled_hold_bounds(coupling_->condition, coupling_->axes, coupling_->hint, loads,
                                             plastic_laws());
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (plastic(i)) commands[i] = laws_[i].plan(positions[i], dt, effective_masses[i], bounds[i]);
    }
    if (std::optional<RowCommand>& my = commands[index(Dof::My)]; my && euler_rows() && twist_sign(positions) < 0.0) {
        my->velocity = -my->velocity;
        my->force = -my->force;
    }
    return commands;
}

bool PlasticJointLaw::settle(const PerDof<double>& measured, const PerDof<double>& row_forces, double time,
                             const PerDof<double>& corrected_motion) {
    if (broken()) return false;
    const PerDof<double> positions = continuous(measured);
    last_forces_ = row_forces;
    // The rows' work on the step. Rotation rows act about the Euler row axes e_i (joint_frame.hpp),
    // the dofs are the Euler angles θ of R = Rz·Ry·Rx, and ω = Σ g_i·θ̇_i with g_x = b's x, g_y = e_y,
    // g_z = a's z. A row's moment λ_i·e_i does λ_i·(e_i·g_i)·Δθ_i of work (e_j·g_i = 0 for j ≠ i):
    // e_y·g_y = 1 and e_x·g_x = e_z·g_z = cos θ_y (the generalised force of a Lagrangian in Euler
    // angles, e.g. Goldstein, Classical Mechanics, §4.9). Booked as λ_i·Δθ_i, a twisted hinge's
    // bending rows would dissipate 1/cos θ_y too much — energy the ledger then shows as created.
    // The rows' axes follow the engines' branch (|θy| ≤ π/2, so cos θy ≥ 0), whatever branch the
    // continuous angles are on.
    // Swing–twist rows are the angles' exact gradients (swing_twist.hpp): their factor stays 1.
    if (euler_rows()) {
        const double cos_twist = std::cos(0.5 * (last_measured_[angle_index(Dof::My)] + measured[index(Dof::My)]));
        for (Dof dof : {Dof::Mx, Dof::Mz}) {
            if (plastic(index(dof))) laws_[index(dof)].set_work_factor(cos_twist);
        }
    }
    track(measured, positions);
    const PerDof<double> loads = last_loads();  // −forces, My's on the continuous angles' branch
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (plastic(i)) laws_[i].settle(positions[i], -loads[i], corrected_motion[i]);
    }
    if (coupling_)
        detail::coupled_return_mapping(coupling_->condition, coupling_->axes, coupling_->hint, positions, loads,
                                       plastic_laws());
    summarise();
    if (plastic_displacement() > max_plastic_displacement_ || plastic_rotation() > max_plastic_rotation_) {
        broken_at_ = time;
        return true;
    }
    return false;
}

void PlasticJointLaw::summarise() {
    bool moved = false;
    summary_.at_capacity = summary_.near_capacity = false;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!plastic(i)) continue;
        const ElasticPlasticLaw& law = laws_[i];
        moved = moved || law.moved();
        summary_.at_capacity = summary_.at_capacity || law.at_capacity();
        summary_.near_capacity = summary_.near_capacity || law.near_capacity();
    }
    // The totals change only when a plastic offset moved: only then are the laws' books read (a
    // step that reads them all waits on memory for them, issue 16).
    if (!moved) return;
    summary_.plastic_displacement = summary_.plastic_rotation = 0.0;
    for (Dof dof : kAllDofs) {
        if (!plastic(index(dof))) continue;
        (is_rotation(dof) ? summary_.plastic_rotation : summary_.plastic_displacement) += laws_[index(dof)].accumulated_plastic();
    }
}

template <class OfLaw>
double PlasticJointLaw::sum_over_plastic(OfLaw of_law) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (plastic(i)) sum += of_law(laws_[i], i);
    }
    return sum;
}

double PlasticJointLaw::dissipated() const {
    return sum_over_plastic([](const ElasticPlasticLaw& law, std::size_t) { return law.dissipated(); });
}

double PlasticJointLaw::dissipated_by_corrections() const {
    return sum_over_plastic([](const ElasticPlasticLaw& law, std::size_t) { return law.dissipated_by_corrections(); });
}

double PlasticJointLaw::utilisation() const {
    const PerDof<double> loads = last_loads();
    if (coupling_) {
        // Well inside, the inscribed cross-polytope's share bounds U from above and costs no solve
        // (a report of a thousand joints would otherwise solve for each one's U).
        const double share = detail::cross_polytope_share(coupling_->axes, loads);
        if (share <= detail::kFarInside) return share;
        YieldHint hint = coupling_->hint;  // a copy: a report must not move the law's own starting point
        return coupling_->condition.evaluate(loads, hint).utilisation;
    }
    double u = 0.0;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!plastic(i)) continue;
        const DofLaw law = laws_[i].law();
        const double load = loads[i];
        u = std::max(u, std::abs(load) / (load >= 0.0 ? law.capacity_positive : law.capacity_negative));
    }
    return u;
}

double PlasticJointLaw::elastic_energy(const PerDof<double>& measured) const {
    const PerDof<double> positions = continuous(measured);
    return sum_over_plastic([&](const ElasticPlasticLaw& law, std::size_t i) { return law.elastic_energy(positions[i]); });
}

}  // namespace plascap
