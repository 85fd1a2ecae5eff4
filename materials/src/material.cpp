#include "plascap/materials/material.hpp"

#include <cmath>
#include <sstream>

#include "plascap/input_error.hpp"

namespace plascap {
namespace {

std::string number(double value) {
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
}

void check_strength(double value, const std::string& where, const std::string& what) {
    if (!std::isfinite(value) || value < 0.0)
        throw InputError(where + ": " + what + " must be a finite number >= 0 in Pa (got " + number(value) + ")");
    if (value != 0.0 && (value < kMinYieldStress || value > kMaxYieldStress))
        throw InputError(where + ": " + what + " = " + number(value) +
                         " Pa is outside the supported range 1 Pa to 1e12 Pa (a unit mistake?)");
}

void check_range(const std::optional<double>& value, double lo, double hi, bool lo_open, const std::string& where,
                 const std::string& what, const std::string& unit) {
    if (!value) return;
    const double v = *value;
    const bool ok = std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi;
    if (!ok)
        throw InputError(where + ": " + what + " must be within " + (lo_open ? "(" : "[") + number(lo) + ", " +
                         number(hi) + "]" + unit + " (got " + number(v) + ")");
}

}  // namespace

std::optional<double> Material::shear_modulus() const {
    if (G) return G;
    if (E && nu) return *E / (2.0 * (1.0 + *nu));  // isotropic elasticity
    return std::nullopt;
}

void validate_material(const Material& material, const std::string& where) {
    check_strength(material.fy, where, "yield stress fy");
    if (material.fc) check_strength(*material.fc, where, "compressive strength fc");
    if (material.fy == 0.0 && material.compression_strength() == 0.0)
        throw InputError(where + ": the material has no strength: fy and fc are both 0");
    check_range(material.E, 1e3, 1e13, false, where, "Young's modulus E", " Pa");
    check_range(material.G, 1e3, 1e13, false, where, "shear modulus G", " Pa");
    check_range(material.nu, -1.0, 0.5, true, where, "Poisson's ratio nu", "");
    check_range(material.density, 1.0, 1e5, false, where, "density", " kg/m^3");
    check_range(material.ultimate_strain, 0.0, 10.0, true, where, "ultimate_strain", "");
    check_range(material.max_plastic_rotation, 0.0, 2.0 * 3.141592653589793, true, where, "max_plastic_rotation", " rad");
}

}  // namespace plascap
