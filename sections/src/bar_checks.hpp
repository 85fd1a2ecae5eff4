#pragma once
// The rules for reinforcement bars (point areas) of a part, used by validate_section().
#include <cstddef>

#include "plascap/sections/geometry.hpp"

namespace plascap::detail {

// Throws InputError naming "part P, bar B" unless every bar has a finite position, an area in
// (0, part area], a valid material, lies with its whole circle (radius √(area/π)) inside the part's
// material (not in a hole, not across an edge), and does not overlap another bar's circle.
void check_bars(const Part& part, std::size_t part_index);

}  // namespace plascap::detail
