#include "plascap/sections/section_yield.hpp"

#include <cmath>
#include <string>

#include "plascap/input_error.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/plastic_torsion.hpp"

namespace plascap {

SectionYield::SectionYield(YieldSurface surface, const ShearTorsionCapacities& c)
    : surface_(std::move(surface)), capacities_(c) {
    for (const auto& [name, value] : {std::pair{"Qx", c.Qx}, std::pair{"Qz", c.Qz}, std::pair{"torsion", c.T}}) {
        if (!(value > 0.0) || !std::isfinite(value))
            throw InputError(std::string("section yield condition: the ") + name + " capacity must be positive and finite (got " +
                             std::to_string(value) + ")");
    }
}

SectionYield section_yield(const ValidSection& section, TorsionCapacity torsion) {
    const Capacities c = compute_capacities(section, CapacitySet::parse(torsion == TorsionCapacity::Paper ? "Qx,Qz,My" : "Qx,Qz"));
    const double T = torsion == TorsionCapacity::Paper ? *c.My : plastic_torsion(section).T;
    return SectionYield(YieldSurface(section), {*c.Qx, *c.Qz, T});
}

const char* torsion_capacity_name(TorsionCapacity torsion) {
    return torsion == TorsionCapacity::Paper ? "paper" : "fully-plastic";
}

TorsionCapacity torsion_capacity_from_name(const std::string& name, const std::string& where) {
    if (name == "fully-plastic") return TorsionCapacity::FullyPlastic;
    if (name == "paper") return TorsionCapacity::Paper;
    throw InputError(where + ": unknown torsion capacity \"" + name + "\" (available: fully-plastic, paper)");
}

double shear_torsion_share(const SectionLoads& load, const ShearTorsionCapacities& c) {
    return std::hypot(load.Qx / c.Qx, load.Qz / c.Qz) + std::abs(load.T) / c.T;
}

SectionYieldState SectionYield::evaluate(const SectionLoads& load, const std::optional<SectionResultant>& warm) const {
    SectionYieldState state;
    const SurfaceHit hit = surface_.along({load.N, load.Mx, load.Mz}, warm);
    const double u = hit.utilisation;
    const double shear = std::hypot(load.Qx / capacities_.Qx, load.Qz / capacities_.Qz);
    const double eta = shear + std::abs(load.T) / capacities_.T;
    state.utilisation = std::hypot(u, eta);  // U = √(u_NM² + η²)
    state.nm_utilisation = u;
    state.shear_torsion_share = eta;
    if (!(state.utilisation > 0.0) || !std::isfinite(state.utilisation)) return state;
    if (u > 0.0) state.nm_normal = hit.normal;
    // ∂U = (u·∂u + η·∂η)/U; ∂u is the surface's normal at the hit (the gauge's gradient).
    const double wu = u / state.utilisation, we = eta / state.utilisation;
    if (u > 0.0) {
        state.gradient.N = wu * hit.normal.N;
        state.gradient.Mx = wu * hit.normal.Mx;
        state.gradient.Mz = wu * hit.normal.Mz;
    }
    if (shear > 0.0) {
        state.gradient.Qx = we * load.Qx / (capacities_.Qx * capacities_.Qx * shear);
        state.gradient.Qz = we * load.Qz / (capacities_.Qz * capacities_.Qz * shear);
    }
    if (load.T != 0.0) state.gradient.T = we * (load.T > 0.0 ? 1.0 : -1.0) / capacities_.T;
    return state;
}

}  // namespace plascap
