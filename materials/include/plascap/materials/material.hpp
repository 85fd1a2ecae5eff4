#pragma once
// A structural material as the capacity integrals see it. The catalogue of named grades,
// E, nu, density and ductility limits arrive with the materials issue.
#include <string>

namespace plascap {

struct Material {
    std::string name;     // free text, for reports
    double fy = 0.0;      // yield stress [Pa], tension = compression for now
};

// Supported yield stresses: every real material lies well inside; outside is a unit mistake, and a
// subnormal fy would make every capacity underflow to zero.
inline constexpr double kMinYieldStress = 1.0;    // [Pa]
inline constexpr double kMaxYieldStress = 1e12;   // [Pa]

// Throws InputError naming `where` (e.g. "part 2, material") unless fy is finite, > 0 and within
// [kMinYieldStress, kMaxYieldStress].
void validate_material(const Material& material, const std::string& where);

}  // namespace plascap
