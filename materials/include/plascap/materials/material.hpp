#pragma once
// A structural material: strengths for the capacity integrals, elastic constants and density for
// the adapters, ductility limits for breaking. Named grades come from the catalogue
// (catalogue.hpp, materials/data/materials.json).
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "plascap/materials/shear_criterion.hpp"

namespace plascap {

struct Material {
    Material() = default;
    // A material known by its yield stress alone (fc = fy), as in the paper.
    Material(std::string material_name, double yield_stress) : name(std::move(material_name)), fy(yield_stress) {}

    std::string name;                            // catalogue name or free text, for reports
    double fy = 0.0;                             // yield stress in tension [Pa]; 0: no tensile strength
    std::optional<double> fc;                    // strength in compression [Pa]; default fy
    std::optional<double> E;                     // Young's modulus [Pa]
    std::optional<double> nu;                    // Poisson's ratio [-]
    std::optional<double> G;                     // shear modulus [Pa]; default E/(2(1 + nu))
    std::optional<double> density;               // [kg/m³]
    std::optional<double> ultimate_strain;       // plastic strain at fracture [-]: a breaking limit
    std::optional<double> max_plastic_rotation;  // largest plastic joint rotation [rad]: a breaking limit
    std::optional<ShearCriterion> shear;         // the criterion usually used for this material
    std::string description;
    std::map<std::string, std::string> sources;  // property name → where its number comes from

    double compression_strength() const { return fc.value_or(fy); }
    // G if given, else E/(2(1 + ν)) (isotropic linear elasticity), else nothing.
    std::optional<double> shear_modulus() const;
};

// Supported strengths: every real material lies well inside; outside is a unit mistake, and a
// subnormal strength would make every capacity underflow to zero. 0 means "no strength" (concrete
// in tension).
inline constexpr double kMinYieldStress = 1.0;    // [Pa]
inline constexpr double kMaxYieldStress = 1e12;   // [Pa]

// Throws InputError naming `where` (e.g. "part 2, material") and the property unless: fy and fc
// are 0 or within [kMinYieldStress, kMaxYieldStress], not both 0; E and G within 1e3–1e13 Pa;
// -1 < nu <= 0.5; density within 1–1e5 kg/m³; ultimate_strain within (0, 10];
// max_plastic_rotation within (0, 2π].
void validate_material(const Material& material, const std::string& where);

}  // namespace plascap
