#pragma once
// section-calc --svg: a drawing of the section for a person to check — parts and holes, the mesh
// of the cubature route (conforming to the axes and the joint point), both plastic neutral axes,
// the centroid, the joint point, and a scale bar. Section z points up, as in the paper's figures.
#include <string>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap::tools {

// Throws InputError when the file cannot be written.
void write_section_svg(const std::string& path, const ValidSection& section, const Capacities& capacities,
                       double max_area, const std::string& title);

}  // namespace plascap::tools
