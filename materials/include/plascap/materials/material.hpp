#pragma once
// A structural material as the capacity integrals see it. The catalogue of named grades,
// E, nu, density and ductility limits arrive with the materials issue.
#include <string>

namespace plascap {

struct Material {
    std::string name;     // free text, for reports
    double fy = 0.0;      // yield stress [Pa], tension = compression for now
};

// Throws InputError naming `where` (e.g. "part 2 material") unless fy is finite and > 0.
void validate_material(const Material& material, const std::string& where);

}  // namespace plascap
