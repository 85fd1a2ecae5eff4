#pragma once
// How a joint's plastic dofs share one yield condition U(loads) = 1 (docs/yield-surface.md, "The
// joint scheme"). Sequential-impulse solvers bound every row separately, so:
//   rigid-plastic rows: before each step, each row's bound is the component of the surface point on
//     the ray of the last step's loads, b_i = |s_i|/U(s) — the rows saturate together exactly where
//     the ray leaves the surface — but never less than what the dof could take alone with the others
//     held, on the inscribed cross-polytope Σ|s_j|/C_j ≤ 1 (C_j where the surface meets dof j's
//     axis, over all six dofs, rigid ones too, their loads at most kRigidShare of it — below): a
//     dof the last load did not use keeps a share of its strength; inside the surface, a row that
//     moves U may also grow to U's tangent plane, |s_i| + (1 − U)/|∂U/∂s_i| (capped at C_i), so
//     that the steps' noise does not flow it early;
//   elastic-plastic dofs: after each step, an explicit return mapping of the spring loads onto the
//     surface by cutting planes (Ortiz & Simo, Int. J. Numer. Meth. Eng. 23, 1986), Δx_p = Δλ·∇U:
//     associated flow, and the work load·Δx_p ≥ 0 (U is homogeneous: s·∇U = U > 0).
// The cross-polytope of the axis capacities lies inside the convex surface, so U ≤ Σ|s_j|/C_j:
// below 1/2 (bounds) or 1 (return mapping) that sum answers without solving for U.
#include <optional>

#include "plascap/adapters/elastic_plastic_law.hpp"
#include "plascap/adapters/yield_condition.hpp"

namespace plascap::detail {

// Where the condition meets each dof axis, both ways (YieldCondition::axis_capacity), kept by the
// joint so that no step recomputes them.
struct AxisCapacities {
    PerDof<double> positive{}, negative{};
    double at(std::size_t dof, double load) const { return load >= 0.0 ? positive[dof] : negative[dof]; }
};

// A rigid dof cannot yield, yet the solver lets its load grow past where the surface meets its axis
// (a fixed–fixed beam's axial force in its catenary stage past N_pl): the rows that share the surface
// would then get no strength at all, and their bounds swing with every step's change of the rigid
// load — a chain of free hinges whose rigid rows' corrections put energy in (docs/yield-surface.md,
// "Rigid dofs on the surface"). So a rigid dof's load counts on the surface up to this share of its
// axis capacity, and the plastic dofs keep what the surface leaves them there.
inline constexpr double kRigidShare = 0.9;

// The loads as the surface sees them: the rigid dofs' (no law in `laws`) capped at kRigidShare of
// their axis capacity on their side; the plastic dofs' as they are.
PerDof<double> surface_loads(const AxisCapacities& axes, const PerDof<double>& loads,
                             const PerDof<ElasticPlasticLaw*>& laws);

// Σ |s_j|/C_j over the dofs that carry load: the gauge of the inscribed cross-polytope, so U ≤ it.
double cross_polytope_share(const AxisCapacities& axes, const PerDof<double>& loads);

// Below this share the load is certainly well inside (U ≤ share), and the bounds need no exact U.
inline constexpr double kFarInside = 0.5;

// The Hold bounds of the rigid-plastic dofs for the next step; nothing for the others. `laws`
// holds each plastic dof's law (nullptr for free and rigid dofs), loads the last step's six loads.
PerDof<std::optional<double>> coupled_hold_bounds(const YieldCondition& condition, const AxisCapacities& axes,
                                                  YieldHint& hint, const PerDof<double>& loads,
                                                  const PerDof<ElasticPlasticLaw*>& laws);

// Returns the elastic-plastic dofs' spring loads to the surface after a step (the others' loads
// held at what they applied), moving their plastic offsets along the normal.
void coupled_return_mapping(const YieldCondition& condition, const AxisCapacities& axes, YieldHint& hint,
                            const PerDof<double>& positions, const PerDof<double>& applied_loads,
                            const PerDof<ElasticPlasticLaw*>& laws);

}  // namespace plascap::detail
