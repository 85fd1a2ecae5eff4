#pragma once
// How a plastic dof is stepped. A spring is integrated explicitly (symplectic Euler, as the engines
// integrate bodies), which is accurate while ω·dt is small, ω = √(k/m). Past the paper's eq. 3.2
// limit, √(k/m)·dt > 0.25, the spring is too stiff to sample: the dof falls back to rigid-plastic
// (as the paper's "elastic-plastic constraint 2" does, Table 3.6).
#include <optional>

namespace plascap {

enum class Regime {
    RigidPlastic,       // no stiffness given: rigid below capacity, flows at it
    ElasticPlastic,     // explicit spring capped at capacity; ω·dt ≤ kStiffSpringLimit
    StiffRigidPlastic,  // stiffness given but ω·dt > kStiffSpringLimit: treated as rigid-plastic
};

inline constexpr double kStiffSpringLimit = 0.25;  // paper eq. 3.2

const char* regime_name(Regime regime);

// ω·dt of a spring k [N/m or N·m/rad] on effective mass m [kg or kg·m²]; 0 without a spring.
double spring_omega_dt(std::optional<double> stiffness, double effective_mass, double dt);

// The regime of a dof for this step (eq. 3.2 with m the row's effective mass).
Regime choose_regime(std::optional<double> stiffness, double effective_mass, double dt);

}  // namespace plascap
