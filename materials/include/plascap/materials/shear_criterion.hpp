#pragma once
// Shear yield stress from the uniaxial yield stress (paper, text after eq. 2.14):
// Tresca tau_y = fy/2, von Mises tau_y = fy/sqrt(3).
#include <string>
#include <string_view>

namespace plascap {

enum class ShearCriterion { Tresca, VonMises };

double shear_yield_stress(double fy, ShearCriterion criterion);

// "tresca" or "von-mises" (also "von_mises", "vonmises", any case); throws InputError otherwise.
ShearCriterion parse_shear_criterion(std::string_view name);

// The canonical name: "tresca" or "von-mises".
std::string to_string(ShearCriterion criterion);

}  // namespace plascap
