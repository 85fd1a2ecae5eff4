#include "plascap/adapters/plastic_joint_settings.hpp"

#include <cmath>

#include "plascap/input_error.hpp"

namespace plascap {

void validate_joint_settings(const PlasticJointSettings& settings, const std::string& where) {
    for (Dof dof : kAllDofs) {
        if (settings.modes[index(dof)] != DofMode::Plastic) continue;
        validate_dof_law(settings.laws[index(dof)], (where + ", dof " + dof_name(dof)).c_str());
    }
    if (!(settings.max_plastic_displacement > 0.0)) {
        throw InputError(where + ": max_plastic_displacement must be positive");
    }
    if (!(settings.max_plastic_rotation > 0.0)) {
        throw InputError(where + ": max_plastic_rotation must be positive");
    }
}

}  // namespace plascap
