#include "plascap/materials/shear_criterion.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "plascap/input_error.hpp"

namespace plascap {

double shear_yield_stress(double fy, ShearCriterion criterion) {
    switch (criterion) {
        case ShearCriterion::Tresca: return 0.5 * fy;             // Tresca: tau_y = fy/2
        case ShearCriterion::VonMises: return fy / std::sqrt(3.0);  // von Mises: tau_y = fy/sqrt(3)
    }
    return 0.5 * fy;
}

ShearCriterion parse_shear_criterion(std::string_view name) {
    std::string key(name);
    std::transform(key.begin(), key.end(), key.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (key == "tresca") return ShearCriterion::Tresca;
    if (key == "von-mises" || key == "von_mises" || key == "vonmises" || key == "von mises")
        return ShearCriterion::VonMises;
    throw InputError("unknown shear criterion '" + std::string(name) +
                     "' (choose \"tresca\" or \"von-mises\")");
}

std::string to_string(ShearCriterion criterion) {
    return criterion == ShearCriterion::Tresca ? "tresca" : "von-mises";
}

}  // namespace plascap
