// Hollow sections (EN 10210-2, EN 10219-2), round bars and flat bars. A circle is a square whose
// corner radius is half its side: the four quarter arcs meet at the edge midpoints.
#include <algorithm>

#include "plascap/sections/shape_geometry.hpp"
#include "shape_checks.hpp"

namespace plascap {
namespace {

// A centred b × h rectangle with all four corners rounded by `radius`; clockwise for a hole.
RoundedRing rounded_rectangle(double b, double h, double radius, const char* name, bool clockwise) {
    const double x = 0.5 * b, z = 0.5 * h;
    RoundedRing ring{{{-x, -z}, radius, name}, {{x, -z}, radius, name}, {{x, z}, radius, name}, {{-x, z}, radius, name}};
    if (clockwise) std::reverse(ring.begin(), ring.end());
    return ring;
}

}  // namespace

RectangularHollowShape hot_finished_hollow(double h, double b, double t) { return {h, b, t, 1.5 * t, 1.0 * t}; }

RectangularHollowShape cold_formed_hollow(double h, double b, double t) {
    const double outer = t <= 6e-3 ? 2.0 * t : t <= 10e-3 ? 2.5 * t : 3.0 * t;
    return {h, b, t, outer, outer - t};
}

RoundedOutline rectangular_hollow_outline(const RectangularHollowShape& s) {
    detail::require_positive({"h", s.h});
    detail::require_positive({"b", s.b});
    detail::require_positive({"t", s.t});
    detail::require_non_negative({"outer radius", s.outer_radius});
    detail::require_non_negative({"inner radius", s.inner_radius});
    const double side = std::min(s.h, s.b);
    detail::require_less({"t", s.t}, 0.5 * side, "half the shorter side");
    detail::require_at_most({"outer radius", s.outer_radius}, 0.5 * side, "half the shorter side");
    detail::require_at_most({"inner radius", s.inner_radius}, 0.5 * side - s.t, "half the shorter inner side");
    return {rounded_rectangle(s.b, s.h, s.outer_radius, "outer radius", false),
            {rounded_rectangle(s.b - 2.0 * s.t, s.h - 2.0 * s.t, s.inner_radius, "inner radius", true)}};
}

RoundedOutline circular_hollow_outline(const CircularHollowShape& s) {
    detail::require_positive({"D", s.D});
    detail::require_positive({"t", s.t});
    detail::require_less({"t", s.t}, 0.5 * s.D, "D/2");
    const double inner = s.D - 2.0 * s.t;
    return {rounded_rectangle(s.D, s.D, 0.5 * s.D, "D/2", false),
            {rounded_rectangle(inner, inner, 0.5 * inner, "D/2 − t", true)}};
}

RoundedOutline round_bar_outline(const RoundBarShape& s) {
    detail::require_positive({"D", s.D});
    return {rounded_rectangle(s.D, s.D, 0.5 * s.D, "D/2", false), {}};
}

RoundedOutline flat_bar_outline(const FlatBarShape& s) {
    detail::require_positive({"b", s.b});
    detail::require_positive({"t", s.t});
    return {rounded_rectangle(s.b, s.t, 0.0, "", false), {}};
}

}  // namespace plascap
