#pragma once
// Standard structural shapes by their dimensions, as rounded polygons and as Sections.
//
// Axes (every shape): depth h along z, width b along x, so Mx is the strong-axis (EN y–y)
// plastic moment and Mz the weak-axis (EN z–z) one. Every outline is placed with its bounding
// box centred on the origin. Dimensions in metres; radii 0 give sharp corners.
//
//   IShape          I/H with root radius r (EN 10365: IPE, HE); flange_slope > 0 tapers the inner
//                   flange faces (IPN/UPN style; tf is the thickness at the middle of the outstand)
//                   and toe_radius rounds the flange tips' inner corners
//   ChannelShape    U/C: web on the −x side, flanges towards +x; same options as IShape
//   AngleShape      L: leg h along z and leg b along x meeting at the heel (−b/2, −h/2); thickness
//                   t, root radius r, toe radius at both leg tips
//   TeeShape        T: flange b × tf at the top, stem of thickness tw down to z = −h/2, root radius
//   RectangularHollowShape  RHS/SHS: outer h × b, wall t, outer and inner corner radii
//   CircularHollowShape     CHS: outer diameter D, wall t
//   RoundBarShape   solid circle of diameter D
//   FlatBarShape    plate b (along x) × t (along z)
//
// Arcs become inscribed chords (rounded_polygon.hpp): the area missed by all arcs together is at
// most ShapeOptions::area_tolerance times the section's exact area.
#include <string>
#include <variant>
#include <vector>

#include "plascap/materials/material.hpp"
#include "plascap/sections/geometry.hpp"
#include "plascap/sections/rounded_polygon.hpp"

namespace plascap {

struct IShape {
    double h = 0, b = 0, tw = 0, tf = 0, r = 0;
    double flange_slope = 0;  // tan of the inner flange face's slope (0.14 for 14 %)
    double toe_radius = 0;
};

struct ChannelShape {
    double h = 0, b = 0, tw = 0, tf = 0, r = 0;
    double flange_slope = 0;
    double toe_radius = 0;
};

struct AngleShape {
    double h = 0, b = 0, t = 0, r = 0;
    double toe_radius = 0;
};

struct TeeShape {
    double h = 0, b = 0, tw = 0, tf = 0, r = 0;
};

struct RectangularHollowShape {
    double h = 0, b = 0, t = 0;
    double outer_radius = 0, inner_radius = 0;
};

struct CircularHollowShape {
    double D = 0, t = 0;
};

struct RoundBarShape {
    double D = 0;
};

struct FlatBarShape {
    double b = 0, t = 0;
};

using ShapeGeometry = std::variant<IShape, ChannelShape, AngleShape, TeeShape, RectangularHollowShape,
                                   CircularHollowShape, RoundBarShape, FlatBarShape>;

// Corner radii of rectangular hollow sections used for their tabulated properties.
// EN 10210-2:2006 (hot finished), 6.2 / Annex B: outer 1.5·t, inner 1.0·t.
RectangularHollowShape hot_finished_hollow(double h, double b, double t);
// EN 10219-2:2006 (cold formed), Annex B: outer 2.0·t (t ≤ 6 mm), 2.5·t (6 < t ≤ 10 mm),
// 3.0·t (t > 10 mm); inner = outer − t.
RectangularHollowShape cold_formed_hollow(double h, double b, double t);

// One part: its outer ring counter-clockwise, holes clockwise, each a rounded polygon.
struct RoundedOutline {
    RoundedRing outer;
    std::vector<RoundedRing> holes;
};

// The shape's outline. Throws InputError naming the dimension at fault ("tw = 160 mm must be less
// than b = 150 mm") when the dimensions do not make the shape.
RoundedOutline shape_outline(const ShapeGeometry& shape);

// Exact area of the rounded outline [m²] (arcs exact, not their chords).
double exact_area(const RoundedOutline& outline);

struct ShapeOptions {
    // Largest area the chords of all arcs together may miss, relative to the exact area.
    double area_tolerance = 1e-6;
};

// Throws InputError unless 1e-12 <= area_tolerance <= 1e-2.
void validate_shape_options(const ShapeOptions& options);

// The shape as a one-part Section of `material`.
Section shape_section(const ShapeGeometry& shape, const Material& material, const ShapeOptions& options = {});

// The rings the section gets, and the area they miss against the exact outline [m²] (>= 0
// for outer arcs cut off, the sum of |missing| over every arc).
struct DiscretisedOutline {
    Ring outer;
    std::vector<Ring> holes;
    double area_error_bound = 0.0;  // Σ over arcs of the exact chord-segment area [m²]
};
DiscretisedOutline discretise(const RoundedOutline& outline, const ShapeOptions& options = {});

// The parametric designation of the shape (docs/shapes.md), e.g. "I 300x150x7.1x10.7 r15".
std::string parametric_name(const ShapeGeometry& shape);

}  // namespace plascap
