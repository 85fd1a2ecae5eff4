#pragma once
// The description of one plastic joint, independent of any engine (a plain settings struct, in the
// manner of Jolt's SixDOFConstraintSettings): what each dof does, its law, and the breaking limits.
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "plascap/adapters/dof.hpp"
#include "plascap/adapters/elastic_plastic_law.hpp"
#include "plascap/adapters/yield_condition.hpp"

namespace plascap {

struct PlasticJointSettings {
    PerDof<DofMode> modes{};  // all Free: declare what the scene needs
    PerDof<DofLaw> laws{};    // read for Plastic dofs only
    // The joint breaks when the accumulated plastic translation (Σ over Qx, N, Qz of Σ|Δx_p|) or
    // rotation (Σ over Mx, My, Mz) exceeds its limit.
    double max_plastic_displacement = std::numeric_limits<double>::infinity();  // [m]
    double max_plastic_rotation = std::numeric_limits<double>::infinity();      // [rad]
    // With a condition, the plastic dofs yield together where U(loads) = 1 (plastic_joint_law.hpp);
    // without one, each at its own capacities (the paper's independent limits). Shared: joints of
    // one section may use one condition.
    std::shared_ptr<const YieldCondition> yield_condition;
};

// Throws InputError naming `where` and the dof for a bad law of a plastic dof or a non-positive limit.
void validate_joint_settings(const PlasticJointSettings& settings, const std::string& where);


}  // namespace plascap
