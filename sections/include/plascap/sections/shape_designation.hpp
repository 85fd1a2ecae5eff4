#pragma once
// A shape named by its designation, as users write it (docs/shapes.md, "Names"):
//   - a catalogue row: "IPE 300", "IPE300", "HE 200 B", "HEB200", "UPE 200", "CHS 168.3x8",
//     "SHS 200x200x10", "RHS 300x200x10", "L 60x40x5" (case and spaces do not matter);
//   - a parametric shape, dimensions in millimetres separated by 'x', options after a space:
//       I h x b x tw x tf [r R] [toe R] [slope S%]     U h x b x tw x tf [r R] [toe R] [slope S%]
//       L h x b x t [r R] [toe R]                        T h x b x tw x tf [r R]
//       BOX h x b x t [hot | cold | ro R ri R]           TUBE D x t      ROUND D      FLAT b x t
//     e.g. "I 300x150x7.1x10.7 r15", "BOX 200x100x8 cold", "TUBE 168.3x8". Radii default to 0
//     (sharp); BOX defaults to the EN 10210-2 hot-finished radii (1.5 t outside, t inside).
// A name that is a catalogue row is that row. A name in a catalogue family (IPE, HEA, HEB, HEM,
// UPE, CHS, SHS, RHS) that is not in the catalogue is refused with the closest designations.
#include <string>
#include <string_view>

#include "plascap/materials/material.hpp"
#include "plascap/sections/geometry.hpp"
#include "plascap/sections/shape_catalogue.hpp"
#include "plascap/sections/shape_geometry.hpp"

namespace plascap {

// Throws InputError naming the problem: an unknown designation (with suggestions), a malformed
// parametric string (which part), or dimensions that do not make the shape (which dimension).
ShapeGeometry parse_shape_designation(std::string_view text,
                                      const ShapeCatalogue& catalogue = ShapeCatalogue::built_in());

// parse_shape_designation + shape_section.
Section shape_section(std::string_view designation, const Material& material, const ShapeOptions& options = {},
                      const ShapeCatalogue& catalogue = ShapeCatalogue::built_in());

}  // namespace plascap
