#pragma once
// One material as a JSON object, the form section files and catalogue files share:
//   {"name": "S355", "description": "...", "fy": Pa, "fc": Pa, "E": Pa, "nu": 0.3, "G": Pa,
//    "density": kg/m³, "ultimate_strain": 0.22, "max_plastic_rotation": rad,
//    "shear": "tresca" | "von-mises", "sources": {"fy": "EN ...", ...}}
// Only "fy" is required. Unknown keys, wrong types and values out of range (validate_material)
// throw InputError naming `where` and the key.
#include <string>
#include <string_view>

#include "plascap/materials/material.hpp"

namespace plascap {

Material parse_material_json(std::string_view object_text, const std::string& where);

}  // namespace plascap
