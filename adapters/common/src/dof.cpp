#include "plascap/adapters/dof.hpp"

#include "plascap/input_error.hpp"

namespace plascap {

const char* dof_name(Dof dof) {
    static constexpr PerDof<const char*> names = {"Qx", "N", "Qz", "Mx", "My", "Mz"};
    return names[index(dof)];
}

Dof dof_from_name(const std::string& name, const std::string& where) {
    for (Dof dof : kAllDofs) {
        if (name == dof_name(dof)) return dof;
    }
    throw InputError(where + ": unknown dof \"" + name + "\" (expected N, Qx, Qz, Mx, My or Mz)");
}

const char* dof_mode_name(DofMode mode) {
    switch (mode) {
        case DofMode::Free: return "free";
        case DofMode::Rigid: return "rigid";
        case DofMode::Plastic: return "plastic";
    }
    return "?";
}

DofMode dof_mode_from_name(const std::string& name, const std::string& where) {
    for (DofMode mode : {DofMode::Free, DofMode::Rigid, DofMode::Plastic}) {
        if (name == dof_mode_name(mode)) return mode;
    }
    throw InputError(where + ": unknown dof mode \"" + name + "\" (expected plastic, rigid or free)");
}

}  // namespace plascap
