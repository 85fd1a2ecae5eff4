#include "coupled_yield.hpp"

#include <algorithm>
#include <cmath>

namespace plascap::detail {
namespace {

bool rigid_plastic(const ElasticPlasticLaw& law) { return law.regime() != Regime::ElasticPlastic; }

}  // namespace

PerDof<double> surface_loads(const AxisCapacities& axes, const PerDof<double>& loads,
                             const PerDof<ElasticPlasticLaw*>& laws) {
    PerDof<double> s = loads;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (laws[i] || s[i] == 0.0) continue;  // a plastic dof, or no load
        const double reach = axes.at(i, s[i]);  // where the surface meets the axis on this side
        if (reach > 0.0 && std::isfinite(reach))
            s[i] = std::copysign(std::min(std::abs(s[i]), kRigidShare * reach), s[i]);
    }
    return s;
}

double cross_polytope_share(const AxisCapacities& axes, const PerDof<double>& loads) {
    double share = 0.0;
    for (std::size_t j = 0; j < kDofCount; ++j)
        if (loads[j] != 0.0) share += std::abs(loads[j]) / axes.at(j, loads[j]);
    return share;
}

PerDof<std::optional<double>> coupled_hold_bounds(const YieldCondition& condition, const AxisCapacities& axes,
                                                  YieldHint& hint, const PerDof<double>& last_loads,
                                                  const PerDof<ElasticPlasticLaw*>& laws) {
    PerDof<std::optional<double>> bounds;
    // Springs take no bound (their last regime decides; a dof that turns stiff this step holds at its
    // own capacity for that step).
    if (std::none_of(laws.begin(), laws.end(), [](const ElasticPlasticLaw* l) { return l && rigid_plastic(*l); })) return bounds;
    const PerDof<double> loads = surface_loads(axes, last_loads, laws);
    const bool loaded = std::any_of(loads.begin(), loads.end(), [](double s) { return s != 0.0; });
    const double share = cross_polytope_share(axes, loads);
    // Far inside, the cross-polytope floors alone leave every row at least half its capacity above
    // its load; the exact U is needed only nearer the surface.
    YieldEvaluation e;
    if (loaded && share > kFarInside) e = condition.evaluate(loads, hint);
    const double U = e.utilisation;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!laws[i] || !rigid_plastic(*laws[i])) continue;
        if (!loaded) {  // nothing known yet: the dof's own capacity (the smaller side before any load)
            bounds[i] = std::min(laws[i]->law().capacity_positive, laws[i]->law().capacity_negative);
            continue;
        }
        const double own = axes.at(i, loads[i]);
        const double radial = U > 0.0 && std::isfinite(U) ? std::abs(loads[i]) / U : 0.0;
        const double others = share - std::abs(loads[i]) / own;
        double bound = std::max(radial, own * std::max(0.0, 1.0 - others));
        // Inside the surface, a row whose load moves U may also take what U's tangent plane leaves
        // it, |s_i| + (1 − U)/|∂U/∂s_i| (capped at its own capacity): the load can grow in that one
        // component to the surface, to first order, without the step's noise flowing it early.
        const double slope = std::abs(e.gradient[i]);
        if (U > 0.0 && U < 1.0 && slope > 0.0) bound = std::max(bound, std::min(own, std::abs(loads[i]) + (1.0 - U) / slope));
        bounds[i] = bound;
    }
    return bounds;
}

void coupled_return_mapping(const YieldCondition& condition, const AxisCapacities& axes, YieldHint& hint,
                            const PerDof<double>& positions, const PerDof<double>& applied_loads,
                            const PerDof<ElasticPlasticLaw*>& laws) {
    PerDof<double> s = surface_loads(axes, applied_loads, laws);
    PerDof<double> k{};
    bool any = false;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!laws[i] || rigid_plastic(*laws[i])) continue;
        k[i] = *laws[i]->law().stiffness;
        s[i] = k[i] * (positions[i] - laws[i]->plastic_offset());  // the spring's load, −f = k·(x − x_p)
        any = true;
    }
    if (!any || cross_polytope_share(axes, s) <= 1.0) return;  // U ≤ share ≤ 1: inside, nothing to return
    PerDof<double> moved{};
    constexpr int kMaxCuts = 50;
    constexpr double kOnSurface = 1e-12;
    for (int cut = 0; cut < kMaxCuts; ++cut) {
        const YieldEvaluation e = condition.evaluate(s, hint);
        if (!(e.utilisation > 1.0 + kOnSurface) || !std::isfinite(e.utilisation)) break;
        double stiffness_along = 0.0;  // ∇U·K·∇U over the springs
        for (std::size_t i = 0; i < kDofCount; ++i) stiffness_along += k[i] * e.gradient[i] * e.gradient[i];
        if (!(stiffness_along > 0.0)) break;  // the excess is in rigid rows: nothing a spring can give
        const double dlambda = (e.utilisation - 1.0) / stiffness_along;  // linearised U(s − Δλ·K·∇U) = 1
        for (std::size_t i = 0; i < kDofCount; ++i) {
            if (k[i] == 0.0) continue;
            const double dxp = dlambda * e.gradient[i];
            moved[i] += dxp;
            s[i] -= k[i] * dxp;
        }
    }
    for (std::size_t i = 0; i < kDofCount; ++i)
        if (k[i] != 0.0 && moved[i] != 0.0) laws[i]->flow(moved[i], s[i]);
}

}  // namespace plascap::detail
