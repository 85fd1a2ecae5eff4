#pragma once
// Reads the section file format of docs/section-format.md:
//   {"shear": "tresca" | "von-mises", "reference": [x, z], "material": "S355" | {"fy": Pa, ...},
//    "parts": [{"outer": [[x, z], ...], "holes": [[[x, z], ...], ...], "material": ...}],
//    "name": "...", "description": "..."}
// A material is a catalogue name or an object (plascap/materials/material_json.hpp).
// Every problem throws InputError naming the JSON location, e.g. "parts[0].outer[3]: ...".
// Geometry rules are checked afterwards by validate_section().
#include <string>
#include <string_view>

#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/geometry.hpp"

namespace plascap {

Section parse_section_json(std::string_view text, const MaterialCatalogue& catalogue = MaterialCatalogue::built_in());

// `path` is named in every message; an unreadable file is an InputError too.
Section read_section_file(const std::string& path,
                          const MaterialCatalogue& catalogue = MaterialCatalogue::built_in());

}  // namespace plascap
