#include "coupled_yield.hpp"

#include <algorithm>
#include <cmath>

namespace plascap::detail {
namespace {

bool rigid_plastic(const ElasticPlasticLaw& law) { return law.regime() != Regime::ElasticPlastic; }

}  // namespace

PerDof<std::optional<double>> coupled_hold_bounds(const YieldCondition& condition, const AxisCapacities& axes,
                                                  YieldHint& hint, const PerDof<double>& loads,
                                                  const PerDof<ElasticPlasticLaw*>& laws) {
    PerDof<std::optional<double>> bounds;
    const bool loaded = std::any_of(loads.begin(), loads.end(), [](double s) { return s != 0.0; });
    const double U = loaded ? condition.evaluate(loads, hint).utilisation : 0.0;
    double share = 0.0;  // Σ |s_j|/C_j over the dofs that carry load: the cross-polytope's gauge
    for (std::size_t j = 0; j < kDofCount; ++j)
        if (loads[j] != 0.0) share += std::abs(loads[j]) / axes.at(j, loads[j]);
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!laws[i]) continue;
        const double own = axes.at(i, loads[i]);
        if (!loaded) {  // nothing known yet: the dof's own capacity (the smaller side before any load)
            bounds[i] = std::min(laws[i]->law().capacity_positive, laws[i]->law().capacity_negative);
            continue;
        }
        const double radial = U > 0.0 && std::isfinite(U) ? std::abs(loads[i]) / U : 0.0;
        const double others = share - std::abs(loads[i]) / own;
        bounds[i] = std::max(radial, own * std::max(0.0, 1.0 - others));
    }
    return bounds;
}

void coupled_return_mapping(const YieldCondition& condition, YieldHint& hint, const PerDof<double>& positions,
                            const PerDof<double>& applied_loads, const PerDof<ElasticPlasticLaw*>& laws) {
    PerDof<double> s = applied_loads;
    PerDof<double> k{};
    bool any = false;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!laws[i] || rigid_plastic(*laws[i])) continue;
        k[i] = *laws[i]->law().stiffness;
        s[i] = k[i] * (positions[i] - laws[i]->plastic_offset());  // the spring's load, −f = k·(x − x_p)
        any = true;
    }
    if (!any) return;
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
