#include "plascap/materials/material.hpp"

#include <cmath>
#include <sstream>

#include "plascap/input_error.hpp"

namespace plascap {

void validate_material(const Material& material, const std::string& where) {
    if (!std::isfinite(material.fy) || material.fy <= 0.0) {
        std::ostringstream message;
        message.precision(17);
        message << where << ": yield stress fy must be a positive finite number in Pa (got "
                << material.fy << ")";
        throw InputError(message.str());
    }
}

}  // namespace plascap
