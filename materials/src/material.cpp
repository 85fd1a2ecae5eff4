#include "plascap/materials/material.hpp"

#include <cmath>
#include <sstream>

#include "plascap/input_error.hpp"

namespace plascap {

void validate_material(const Material& material, const std::string& where) {
    std::ostringstream message;
    message.precision(17);
    if (!std::isfinite(material.fy) || material.fy <= 0.0) {
        message << where << ": yield stress fy must be a positive finite number in Pa (got " << material.fy << ")";
        throw InputError(message.str());
    }
    if (material.fy < kMinYieldStress || material.fy > kMaxYieldStress) {
        message << where << ": yield stress fy = " << material.fy
                << " Pa is outside the supported range 1 Pa to 1e12 Pa (a unit mistake?)";
        throw InputError(message.str());
    }
}

}  // namespace plascap
