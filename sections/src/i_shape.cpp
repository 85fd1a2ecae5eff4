// I/H and channel outlines (EN 10365 notation: h, b, tw, tf, r).
#include <cmath>

#include "plascap/sections/shape_geometry.hpp"
#include "shape_checks.hpp"

namespace plascap {
namespace detail {

// Flange thickness at the web face and at the toe for a flange of outstand `outstand` whose
// inner face slopes by `slope` (tan), tf being the thickness at the middle of the outstand.
struct FlangeThickness {
    double at_root, at_toe;
};

FlangeThickness flange_thickness(double tf, double slope, double outstand) {
    return {tf + 0.5 * slope * outstand, tf - 0.5 * slope * outstand};
}

void check_flanged(double h, double b, double tw, double tf, double r, double slope, double toe, double outstand,
                   double web_limit, const char* web_limit_name) {
    require_positive({"h", h});
    require_positive({"b", b});
    require_positive({"tw", tw});
    require_positive({"tf", tf});
    require_non_negative({"r", r});
    require_non_negative({"toe radius", toe});
    if (!std::isfinite(slope) || slope < 0.0 || slope > 1.0)
        throw InputError("flange slope must be between 0 and 100 % (got " + std::to_string(slope * 100.0) + " %)");
    require_less({"tw", tw}, web_limit, web_limit_name);
    require_less({"tf", tf}, 0.5 * h, "h/2");
    const FlangeThickness t = flange_thickness(tf, slope, outstand);
    if (t.at_toe <= 0.0) throw InputError("the flange slope leaves no thickness at the toe (tf = " + mm(tf) + ")");
    require_less({"tf at the web", t.at_root}, 0.5 * h, "h/2");
    require_at_most({"r", r}, 0.5 * h - t.at_root, "(h − 2·tf)/2 at the web");
}

}  // namespace detail

RoundedOutline i_outline(const IShape& s) {
    const double outstand = 0.5 * (s.b - s.tw);
    detail::check_flanged(s.h, s.b, s.tw, s.tf, s.r, s.flange_slope, s.toe_radius, outstand, s.b, "b");
    const detail::FlangeThickness t = detail::flange_thickness(s.tf, s.flange_slope, outstand);
    const double x = 0.5 * s.b, w = 0.5 * s.tw, z = 0.5 * s.h;
    const RoundedCorner root{{}, s.r, "root radius r"};
    const auto at = [](RoundedCorner c, double px, double pz) { return c.at = {px, pz}, c; };
    const RoundedCorner toe{{}, s.toe_radius, "toe radius"};
    const RoundedCorner sharp{};
    return {{at(sharp, -x, -z), at(sharp, x, -z), at(toe, x, -z + t.at_toe), at(root, w, -z + t.at_root),
             at(root, w, z - t.at_root), at(toe, x, z - t.at_toe), at(sharp, x, z), at(sharp, -x, z),
             at(toe, -x, z - t.at_toe), at(root, -w, z - t.at_root), at(root, -w, -z + t.at_root),
             at(toe, -x, -z + t.at_toe)},
            {}};
}

RoundedOutline channel_outline(const ChannelShape& s) {
    const double outstand = s.b - s.tw;
    detail::check_flanged(s.h, s.b, s.tw, s.tf, s.r, s.flange_slope, s.toe_radius, outstand, s.b, "b");
    const detail::FlangeThickness t = detail::flange_thickness(s.tf, s.flange_slope, outstand);
    const double x = 0.5 * s.b, web = -0.5 * s.b + s.tw, z = 0.5 * s.h;
    const RoundedCorner root{{}, s.r, "root radius r"};
    const RoundedCorner toe{{}, s.toe_radius, "toe radius"};
    const RoundedCorner sharp{};
    const auto at = [](RoundedCorner c, double px, double pz) { return c.at = {px, pz}, c; };
    return {{at(sharp, -x, -z), at(sharp, x, -z), at(toe, x, -z + t.at_toe), at(root, web, -z + t.at_root),
             at(root, web, z - t.at_root), at(toe, x, z - t.at_toe), at(sharp, x, z), at(sharp, -x, z)},
            {}};
}

}  // namespace plascap
