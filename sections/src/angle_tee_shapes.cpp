// Angle (EN 10056-1 notation: legs h and b, thickness t, root radius r1, toe radius r2) and tee
// outlines.
#include "plascap/sections/shape_geometry.hpp"
#include "shape_checks.hpp"

namespace plascap {
namespace {

RoundedCorner corner(double x, double z, double radius = 0.0, const char* name = "") { return {{x, z}, radius, name}; }

}  // namespace

RoundedOutline angle_outline(const AngleShape& s) {
    detail::require_positive({"h", s.h});
    detail::require_positive({"b", s.b});
    detail::require_positive({"t", s.t});
    detail::require_non_negative({"r", s.r});
    detail::require_non_negative({"toe radius", s.toe_radius});
    detail::require_less({"t", s.t}, std::min(s.h, s.b), "the shorter leg");
    detail::require_at_most({"toe radius", s.toe_radius}, s.t, "t");
    const double x = 0.5 * s.b, z = 0.5 * s.h, inner_x = -x + s.t, inner_z = -z + s.t;
    return {{corner(-x, -z), corner(x, -z), corner(x, inner_z, s.toe_radius, "toe radius"),
             corner(inner_x, inner_z, s.r, "root radius r"), corner(inner_x, z, s.toe_radius, "toe radius"),
             corner(-x, z)},
            {}};
}

RoundedOutline tee_outline(const TeeShape& s) {
    detail::require_positive({"h", s.h});
    detail::require_positive({"b", s.b});
    detail::require_positive({"tw", s.tw});
    detail::require_positive({"tf", s.tf});
    detail::require_non_negative({"r", s.r});
    detail::require_less({"tw", s.tw}, s.b, "b");
    detail::require_less({"tf", s.tf}, s.h, "h");
    const double x = 0.5 * s.b, w = 0.5 * s.tw, z = 0.5 * s.h, under = z - s.tf;
    return {{corner(-w, -z), corner(w, -z), corner(w, under, s.r, "root radius r"), corner(x, under), corner(x, z),
             corner(-x, z), corner(-x, under), corner(-w, under, s.r, "root radius r")},
            {}};
}

}  // namespace plascap
