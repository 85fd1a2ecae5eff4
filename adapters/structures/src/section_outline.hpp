#pragma once
// A section as a replay or a game draws it on its member's line.
#include "plascap/adapters/structure_model.hpp"
#include "plascap/sections/elastic_properties.hpp"

namespace plascap::detail {

// The section's extent across x and z [m].
std::pair<double, double> section_extent(const ValidSection& section);

// The section on the member's line, which passes through its joint point (the reference point,
// else the centroid), its rings simplified to 1 % of its size.
SectionOutline section_outline(const ValidSection& section, const ElasticProperties& elastic);

}  // namespace plascap::detail
