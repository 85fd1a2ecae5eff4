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

namespace {

double required(const std::optional<double>& capacity, const char* name) {
    if (!capacity || !(*capacity > 0.0)) {
        throw InputError(std::string("the section has no positive ") + name + " capacity");
    }
    return *capacity;
}

}  // namespace

DofLaw dof_law_from_section(Dof dof, const Capacities& c) {
    DofLaw law;
    switch (dof) {
        case Dof::Qx: law.capacity_positive = law.capacity_negative = required(c.Qx, "Qx"); break;
        case Dof::Qz: law.capacity_positive = law.capacity_negative = required(c.Qz, "Qz"); break;
        case Dof::My: law.capacity_positive = law.capacity_negative = required(c.My, "My"); break;
        case Dof::N:
            law.capacity_positive = required(c.N, "N");
            law.capacity_negative = required(c.N_neg, "N_neg");
            break;
        case Dof::Mx:
            law.capacity_positive = required(c.Mx, "Mx");
            law.capacity_negative = required(c.Mx_neg, "Mx_neg");
            break;
        case Dof::Mz:
            law.capacity_positive = required(c.Mz, "Mz");
            law.capacity_negative = required(c.Mz_neg, "Mz_neg");
            break;
    }
    return law;  // rigid-plastic: a stiffness, where wanted, comes from the beam segment (joint_stiffness.hpp)
}

}  // namespace plascap
