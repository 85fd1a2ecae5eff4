#include "plascap/sections/shapes.hpp"

#include <cmath>

namespace plascap {

Ring rectangle_ring(double b, double h) {
    return {{-0.5 * b, -0.5 * h}, {0.5 * b, -0.5 * h}, {0.5 * b, 0.5 * h}, {-0.5 * b, 0.5 * h}};
}

Ring regular_polygon_ring(std::size_t n, double R, double start_angle) {
    const double pi = std::acos(-1.0);
    Ring ring;
    ring.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double angle = start_angle + 2.0 * pi * static_cast<double>(i) / static_cast<double>(n);
        ring.push_back({R * std::cos(angle), R * std::sin(angle)});
    }
    return ring;
}

Section rectangle_section(double b, double h, double fy, std::optional<ShearCriterion> shear) {
    Section section;
    section.shear = shear;
    section.parts.push_back({rectangle_ring(b, h), {}, Material{"", fy}});
    return section;
}

}  // namespace plascap
