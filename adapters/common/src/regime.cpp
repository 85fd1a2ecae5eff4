#include "plascap/adapters/regime.hpp"

#include <cmath>

namespace plascap {

const char* regime_name(Regime regime) {
    switch (regime) {
        case Regime::RigidPlastic: return "rigid-plastic";
        case Regime::ElasticPlastic: return "elastic-plastic";
        case Regime::StiffRigidPlastic: return "stiff: rigid-plastic";
    }
    return "?";
}

double spring_omega_dt(std::optional<double> stiffness, double effective_mass, double dt) {
    if (!stiffness) return 0.0;
    if (!(effective_mass > 0.0)) return INFINITY;
    return std::sqrt(*stiffness / effective_mass) * dt;  // ω·dt, ω = √(k/m); 0 for an immovable row
}

Regime choose_regime(std::optional<double> stiffness, double effective_mass, double dt) {
    if (!stiffness) return Regime::RigidPlastic;
    return spring_omega_dt(stiffness, effective_mass, dt) > kStiffSpringLimit ? Regime::StiffRigidPlastic
                                                                             : Regime::ElasticPlastic;  // eq. 3.2
}

}  // namespace plascap
