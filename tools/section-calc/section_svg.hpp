#pragma once
// section-calc --svg: a drawing of the section for a person to check — parts and holes, the mesh
// of the cubature route (conforming to the axes and the joint point), both plastic neutral axes,
// the centroid, the joint point, and a scale bar. Section z points up, as in the paper's figures.
#include <string>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap::tools {

// SVG elements of `width` × `height` px, drawn from (0, 0).
struct SvgPanel {
    std::string body;
    double width = 0.0, height = 0.0;
};

// The drawing as SVG text.
std::string section_svg(const ValidSection& section, const Capacities& capacities, double max_area, const std::string& title,
                        const SvgPanel* below = nullptr);

// Throws InputError when the file cannot be written. `below`, if given, is drawn under the section.
void write_section_svg(const std::string& path, const ValidSection& section, const Capacities& capacities,
                       double max_area, const std::string& title, const SvgPanel* below = nullptr);

}  // namespace plascap::tools
