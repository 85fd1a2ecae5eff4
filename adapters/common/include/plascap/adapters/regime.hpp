#pragma once
// How a plastic dof is stepped. A spring is integrated explicitly (symplectic Euler, as the engines
// integrate bodies), which is accurate while ω·dt is small, ω = √(k/m). Past the paper's eq. 3.2
// limit, √(k/m)·dt > 0.25, the spring is too stiff to sample: the dof falls back to rigid-plastic
// (as the paper's "elastic-plastic constraint 2" does, Table 3.6).
#include <cmath>
#include <cstdint>
#include <optional>

namespace plascap {

enum class Regime : std::uint8_t {  // one byte: the law stores one per dof (issue 16)
    RigidPlastic,       // no stiffness given: rigid below capacity, flows at it
    ElasticPlastic,     // explicit spring capped at capacity; ω·dt ≤ kStiffSpringLimit
    StiffRigidPlastic,  // stiffness given but ω·dt > kStiffSpringLimit: treated as rigid-plastic
};

inline constexpr double kStiffSpringLimit = 0.25;  // paper eq. 3.2

const char* regime_name(Regime regime);

// ω·dt of a spring k [N/m or N·m/rad] on effective mass m [kg or kg·m²]; 0 without a spring.
// Inline, as regime_for: the law asks for both for every plastic dof every step (issue 16).
inline double spring_omega_dt(std::optional<double> stiffness, double effective_mass, double dt) {
    if (!stiffness) return 0.0;
    if (!(effective_mass > 0.0)) return INFINITY;
    return std::sqrt(*stiffness / effective_mass) * dt;  // ω·dt, ω = √(k/m); 0 for an immovable row
}

// The regime of a dof with (or without) a stiffness whose spring_omega_dt is `omega_dt` (eq. 3.2).
inline Regime regime_for(bool has_stiffness, double omega_dt) {
    if (!has_stiffness) return Regime::RigidPlastic;
    return omega_dt > kStiffSpringLimit ? Regime::StiffRigidPlastic : Regime::ElasticPlastic;
}

// The regime of a dof for this step (eq. 3.2 with m the row's effective mass).
inline Regime choose_regime(std::optional<double> stiffness, double effective_mass, double dt) {
    return regime_for(stiffness.has_value(), spring_omega_dt(stiffness, effective_mass, dt));
}

}  // namespace plascap
