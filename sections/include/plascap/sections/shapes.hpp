#pragma once
// Rings of common shapes, centred on the origin, counter-clockwise.
#include <cstddef>
#include <optional>

#include "plascap/sections/geometry.hpp"

namespace plascap {

// b along x, h along z.
Ring rectangle_ring(double b, double h);

// n vertices on a circle of radius R, the first at angle `start_angle` [rad] from +x.
Ring regular_polygon_ring(std::size_t n, double R, double start_angle = 0.0);

// The section-calc --rect shortcut: one b x h rectangle part of yield stress fy.
// Unset shear: Tresca (the material has no criterion of its own).
Section rectangle_section(double b, double h, double fy, std::optional<ShearCriterion> shear = std::nullopt);

}  // namespace plascap
