#include <cmath>
#include <cstdio>
#include <string>

#include "plascap/input_error.hpp"
#include "plascap/sections/shape_geometry.hpp"
#include "shape_outlines.hpp"

namespace plascap {
namespace {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

std::size_t arcs_in(const RoundedOutline& outline) {
    std::size_t arcs = arc_count(outline.outer);
    for (const RoundedRing& hole : outline.holes) arcs += arc_count(hole);
    return arcs;
}

// A dimension in millimetres, as short as it reads in a table ("7.1", "10.7", "168.3").
std::string mm(double metres) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", metres * 1e3);
    return text;
}

}  // namespace

RoundedOutline shape_outline(const ShapeGeometry& shape) {
    return std::visit(Overloaded{[](const IShape& s) { return i_outline(s); },
                                 [](const ChannelShape& s) { return channel_outline(s); },
                                 [](const AngleShape& s) { return angle_outline(s); },
                                 [](const TeeShape& s) { return tee_outline(s); },
                                 [](const RectangularHollowShape& s) { return rectangular_hollow_outline(s); },
                                 [](const CircularHollowShape& s) { return circular_hollow_outline(s); },
                                 [](const RoundBarShape& s) { return round_bar_outline(s); },
                                 [](const FlatBarShape& s) { return flat_bar_outline(s); }},
                      shape);
}

double exact_area(const RoundedOutline& outline) {
    double area = rounded_signed_area(outline.outer);
    for (const RoundedRing& hole : outline.holes) area += rounded_signed_area(hole);  // clockwise: negative
    return area;
}

void validate_shape_options(const ShapeOptions& options) {
    if (!(options.area_tolerance >= 1e-12 && options.area_tolerance <= 1e-2))
        throw InputError("the arc area tolerance must be between 1e-12 and 1e-2 (relative to the section's area)");
}

DiscretisedOutline discretise(const RoundedOutline& outline, const ShapeOptions& options) {
    validate_shape_options(options);
    const std::size_t arcs = arcs_in(outline);
    // Every arc gets an equal share of the budget: the total missed area stays within it.
    const double budget = arcs == 0 ? 0.0 : options.area_tolerance * exact_area(outline) / static_cast<double>(arcs);
    DiscretisedOutline out;
    out.outer = discretise(outline.outer, budget);
    out.area_error_bound = discretisation_area_error(outline.outer, budget);
    for (const RoundedRing& hole : outline.holes) {
        out.holes.push_back(discretise(hole, budget));
        out.area_error_bound += discretisation_area_error(hole, budget);
    }
    return out;
}

Section shape_section(const ShapeGeometry& shape, const Material& material, const ShapeOptions& options) {
    DiscretisedOutline rings = discretise(shape_outline(shape), options);
    Section section;
    section.parts.push_back(Part{std::move(rings.outer), std::move(rings.holes), material});
    return section;
}

std::string parametric_name(const ShapeGeometry& shape) {
    const auto radius = [](const char* key, double value) { return value > 0.0 ? std::string(" ") + key + mm(value) : std::string(); };
    const auto slope = [](double value) {
        char text[32];
        std::snprintf(text, sizeof text, " slope%.6g%%", value * 100.0);
        return value > 0.0 ? std::string(text) : std::string();
    };
    return std::visit(
        Overloaded{
            [&](const IShape& s) {
                return "I " + mm(s.h) + "x" + mm(s.b) + "x" + mm(s.tw) + "x" + mm(s.tf) + radius("r", s.r) +
                       slope(s.flange_slope) + radius("toe", s.toe_radius);
            },
            [&](const ChannelShape& s) {
                return "U " + mm(s.h) + "x" + mm(s.b) + "x" + mm(s.tw) + "x" + mm(s.tf) + radius("r", s.r) +
                       slope(s.flange_slope) + radius("toe", s.toe_radius);
            },
            [&](const AngleShape& s) {
                return "L " + mm(s.h) + "x" + mm(s.b) + "x" + mm(s.t) + radius("r", s.r) + radius("toe", s.toe_radius);
            },
            [&](const TeeShape& s) {
                return "T " + mm(s.h) + "x" + mm(s.b) + "x" + mm(s.tw) + "x" + mm(s.tf) + radius("r", s.r);
            },
            [&](const RectangularHollowShape& s) {
                return "BOX " + mm(s.h) + "x" + mm(s.b) + "x" + mm(s.t) + " ro" + mm(s.outer_radius) + " ri" +
                       mm(s.inner_radius);
            },
            [&](const CircularHollowShape& s) { return "TUBE " + mm(s.D) + "x" + mm(s.t); },
            [&](const RoundBarShape& s) { return "ROUND " + mm(s.D); },
            [&](const FlatBarShape& s) { return "FLAT " + mm(s.b) + "x" + mm(s.t); }},
        shape);
}

}  // namespace plascap
