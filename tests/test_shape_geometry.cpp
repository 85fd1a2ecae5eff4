// Shape generators against closed forms: the sharp-cornered limits (r = 0) to 1e-12, the exact
// area of the rounded outlines, the chord error's bound and its n⁻² convergence, circles and
// tubes, tapered flanges, and every kind of bad dimension refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plascap/input_error.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/shape_designation.hpp"
#include "plascap/sections/shape_geometry.hpp"
#include "plascap/sections/valid_section.hpp"
#include "test_support.hpp"

namespace {

using namespace plascap;
using plascap::test::relative_error;

const double kPi = std::acos(-1.0);
constexpr double kFy = 355e6;

struct Props {
    double A, Ixx, Izz, Wpl_x, Wpl_z;
    Point centroid;
};

Props props(const ShapeGeometry& shape, ShapeOptions options = {}) {
    const ValidSection v = validate_section(shape_section(shape, Material{"", kFy}, options));
    const ElasticProperties e = elastic_properties(v);
    const Capacities c = compute_capacities(v);
    return {e.area, e.Ixx, e.Izz, *c.Mx / kFy, *c.Mz / kFy, e.centroid};
}

double polygon_area(const DiscretisedOutline& d) {
    double area = ring_moments(d.outer).area;
    for (const Ring& hole : d.holes) area += ring_moments(hole).area;
    return area;
}

// Doubly symmetric I without fillets (textbook: e.g. Gere & Goodno, Mechanics of Materials,
// App. E; plastic moduli as sums of rectangles about the centroid).
TEST(ShapeGeometry, SharpIShapeMatchesClosedForms) {
    const double h = 0.304, b = 0.165, tw = 0.0061, tf = 0.0102, hw = h - 2 * tf;
    const Props p = props(IShape{h, b, tw, tf, 0.0});
    EXPECT_LT(relative_error(p.A, 2 * b * tf + hw * tw), 1e-12);
    EXPECT_LT(relative_error(p.Ixx, b * h * h * h / 12 - (b - tw) * hw * hw * hw / 12), 1e-12);
    EXPECT_LT(relative_error(p.Izz, 2 * tf * b * b * b / 12 + hw * tw * tw * tw / 12), 1e-12);
    EXPECT_LT(relative_error(p.Wpl_x, b * tf * (h - tf) + tw * hw * hw / 4), 1e-12);
    EXPECT_LT(relative_error(p.Wpl_z, tf * b * b / 2 + hw * tw * tw / 4), 1e-12);
    // The same section as published for a 310UB-type I without root radius: A = 5095.96 mm²,
    // Sxx = 617,119.6 mm³, Syy = 141,485.7 mm³, Ixx = 8.42611e7 mm⁴ (rectangle sums, 6-7 digits).
    EXPECT_LT(relative_error(p.A, 5095.96e-6), 1e-6);
    EXPECT_LT(relative_error(p.Wpl_x, 617119.6e-9), 1e-6);
    EXPECT_LT(relative_error(p.Wpl_z, 141485.7e-9), 1e-6);
    EXPECT_LT(relative_error(p.Ixx, 8.42611e7 * 1e-12), 1e-5);
}

TEST(ShapeGeometry, SharpChannelTeeAngleBoxAndFlatMatchClosedForms) {
    {  // channel: symmetric about x; Ixx and Wpl_x as the I's
        const double h = 0.2, b = 0.08, tw = 0.006, tf = 0.011, hw = h - 2 * tf;
        const Props p = props(ChannelShape{h, b, tw, tf, 0.0});
        EXPECT_LT(relative_error(p.A, 2 * b * tf + hw * tw), 1e-12);
        EXPECT_LT(relative_error(p.Ixx, b * h * h * h / 12 - (b - tw) * hw * hw * hw / 12), 1e-12);
        EXPECT_LT(relative_error(p.Wpl_x, b * tf * (h - tf) + tw * hw * hw / 4), 1e-12);
        // centroid from the web's back: (2·b·tf·b/2 + hw·tw·tw/2)/A
        const double e = (b * tf * b + hw * tw * tw / 2) / (2 * b * tf + hw * tw);
        EXPECT_NEAR(p.centroid.x - (-b / 2), e, 1e-15);
    }
    {  // tee: flange on top; centroid from the top, Ixx by parallel axes
        const double h = 0.2, b = 0.15, tw = 0.01, tf = 0.02, hs = h - tf;
        const Props p = props(TeeShape{h, b, tw, tf, 0.0});
        const double A = b * tf + hs * tw;
        const double zc = (b * tf * (h / 2 - tf / 2) + hs * tw * (-h / 2 + hs / 2)) / A;
        EXPECT_LT(relative_error(p.A, A), 1e-12);
        EXPECT_NEAR(p.centroid.z, zc, 1e-15);
        const double I = b * tf * tf * tf / 12 + b * tf * std::pow(h / 2 - tf / 2 - zc, 2) + tw * hs * hs * hs / 12 +
                         tw * hs * std::pow(-h / 2 + hs / 2 - zc, 2);
        EXPECT_LT(relative_error(p.Ixx, I), 1e-12);
    }
    {  // angle: area t(h + b − t), centroid from the heel
        const double h = 0.06, b = 0.04, t = 0.005;
        const Props p = props(AngleShape{h, b, t, 0.0, 0.0});
        const double A = t * (h + b - t);
        EXPECT_LT(relative_error(p.A, A), 1e-12);
        EXPECT_NEAR(p.centroid.z + h / 2, (h * t * h / 2 + (b - t) * t * t / 2) / A, 1e-15);
        EXPECT_NEAR(p.centroid.x + b / 2, (b * t * b / 2 + (h - t) * t * t / 2) / A, 1e-15);
    }
    {  // box without radii
        const double h = 0.3, b = 0.2, t = 0.01;
        const Props p = props(RectangularHollowShape{h, b, t, 0.0, 0.0});
        EXPECT_LT(relative_error(p.A, b * h - (b - 2 * t) * (h - 2 * t)), 1e-12);
        EXPECT_LT(relative_error(p.Ixx, (b * h * h * h - (b - 2 * t) * std::pow(h - 2 * t, 3)) / 12), 1e-12);
        EXPECT_LT(relative_error(p.Wpl_x, (b * h * h - (b - 2 * t) * std::pow(h - 2 * t, 2)) / 4), 1e-12);
    }
    {  // flat bar
        const Props p = props(FlatBarShape{0.1, 0.012});
        EXPECT_LT(relative_error(p.Wpl_x, 0.1 * 0.012 * 0.012 / 4), 1e-12);
        EXPECT_LT(relative_error(p.Wpl_z, 0.012 * 0.1 * 0.1 / 4), 1e-12);
    }
}

// Fillets: four quarter-circle fillets of radius r add 4·r²·(1 − π/4) to the sharp I; the chords
// miss at most the tolerance, and exactly what discretise() reports.
TEST(ShapeGeometry, RoundedAreaIsExactAndTheChordErrorBounded) {
    const double h = 0.3, b = 0.15, tw = 0.0071, tf = 0.0107, r = 0.015;
    const RoundedOutline outline = shape_outline(IShape{h, b, tw, tf, r});
    const double exact = 2 * b * tf + (h - 2 * tf) * tw + 4 * r * r * (1 - kPi / 4);
    EXPECT_LT(relative_error(exact_area(outline), exact), 1e-13);
    for (double tolerance : {1e-3, 1e-6, 1e-9}) {
        const DiscretisedOutline d = discretise(outline, ShapeOptions{tolerance});
        const double missing = polygon_area(d) - exact;  // concave fillets: the chords add material
        EXPECT_GT(missing, 0.0);
        EXPECT_LE(d.area_error_bound, tolerance * exact);
        EXPECT_NEAR(missing, d.area_error_bound, 1e-12 * exact) << tolerance;
    }
    // The section's own area: the exact one up to the chords (default tolerance 1e-6).
    EXPECT_LT(relative_error(props(IShape{h, b, tw, tf, r}).A, exact), 1e-6);
}

// A circle of n chords misses n·(R²/2)(θ − sin θ) ≈ (2π)³R²/(12 n²): second order.
TEST(ShapeGeometry, ArcDiscretisationConvergesAtSecondOrder) {
    const double D = 0.1, R = D / 2;
    double previous_error = 0.0;
    std::size_t previous_vertices = 0;
    for (double tolerance : {1e-3, 1e-5, 1e-7, 1e-9}) {
        const DiscretisedOutline d = discretise(shape_outline(RoundBarShape{D}), ShapeOptions{tolerance});
        const double error = kPi * R * R - polygon_area(d);
        EXPECT_GT(error, 0.0);
        EXPECT_LE(error, (tolerance + 1e-12) * kPi * R * R);  // + the shoelace's round-off
        if (previous_vertices != 0) {
            const double order = std::log(previous_error / error) / std::log(double(d.outer.size()) / previous_vertices);
            EXPECT_NEAR(order, 2.0, 0.05) << tolerance;
        }
        previous_error = error;
        previous_vertices = d.outer.size();
    }
}

// Circle and tube: A = πD²/4, Wpl = D³/6 (Mx = (4/3)R³fy), tube (D³ − d³)/6, I = π(D⁴ − d⁴)/64.
TEST(ShapeGeometry, CircleAndTubeMatchClosedForms) {
    const ShapeOptions fine{1e-9};
    const double D = 0.1683, t = 0.008, d = D - 2 * t;
    const Props bar = props(RoundBarShape{D}, fine);
    EXPECT_LT(relative_error(bar.A, kPi * D * D / 4), 1e-9);
    EXPECT_LT(relative_error(bar.Wpl_x, D * D * D / 6), 2e-9);
    const Props tube = props(CircularHollowShape{D, t}, fine);
    EXPECT_LT(relative_error(tube.A, kPi * (D * D - d * d) / 4), 1e-9);
    EXPECT_LT(relative_error(tube.Wpl_x, (D * D * D - d * d * d) / 6), 1e-8);
    EXPECT_LT(relative_error(tube.Ixx, kPi * (std::pow(D, 4) - std::pow(d, 4)) / 64), 1e-8);
    EXPECT_LT(relative_error(tube.Izz, tube.Ixx), 1e-12);
}

// A taper keeps tf as the mean thickness of the outstand: the area of the sharp shape is unchanged.
TEST(ShapeGeometry, TaperedFlangesKeepTheMeanThickness) {
    const Props parallel = props(IShape{0.2, 0.09, 0.0075, 0.0113, 0.0});
    const Props tapered = props(IShape{0.2, 0.09, 0.0075, 0.0113, 0.0, 0.14, 0.0});
    EXPECT_LT(relative_error(tapered.A, parallel.A), 1e-12);
    EXPECT_GT(tapered.Izz, 0.0);
    const Props channel = props(ChannelShape{0.2, 0.075, 0.0085, 0.0115, 0.0115, 0.08, 0.006});
    EXPECT_GT(channel.A, 0.0);
}

// EN 10210-2 hot finished: 1.5 t / 1.0 t; EN 10219-2 cold formed: 2 t, 2.5 t, 3 t outside.
TEST(ShapeGeometry, HollowSectionCornerRadii) {
    const RectangularHollowShape hot = hot_finished_hollow(0.2, 0.1, 0.008);
    EXPECT_DOUBLE_EQ(hot.outer_radius, 0.012);
    EXPECT_DOUBLE_EQ(hot.inner_radius, 0.008);
    EXPECT_DOUBLE_EQ(cold_formed_hollow(0.2, 0.1, 0.005).outer_radius, 0.010);
    EXPECT_DOUBLE_EQ(cold_formed_hollow(0.2, 0.1, 0.008).outer_radius, 0.020);
    EXPECT_DOUBLE_EQ(cold_formed_hollow(0.2, 0.1, 0.012).outer_radius, 0.036);
    EXPECT_DOUBLE_EQ(cold_formed_hollow(0.2, 0.1, 0.012).inner_radius, 0.024);
    // Rounded corners: A = b·h − (4 − π)ro² − [(b−2t)(h−2t) − (4 − π)ri²].
    const double h = 0.2, b = 0.1, t = 0.008, ro = 0.012, ri = 0.008;
    EXPECT_LT(relative_error(exact_area(shape_outline(hot)), b * h - (4 - kPi) * ro * ro - ((b - 2 * t) * (h - 2 * t) - (4 - kPi) * ri * ri)), 1e-13);
}

// Bad dimensions: one InputError naming the dimension.
TEST(ShapeGeometry, BadDimensionsAreRefusedByName) {
    const auto message = [](const ShapeGeometry& s) {
        try {
            shape_section(s, Material{"", kFy});
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message(IShape{-0.3, 0.15, 0.007, 0.01, 0.0}).find("h must be a positive length"), std::string::npos);
    EXPECT_NE(message(IShape{0.3, 0.0, 0.007, 0.01, 0.0}).find("b must be a positive length"), std::string::npos);
    EXPECT_NE(message(IShape{0.3, 0.15, 0.15, 0.01, 0.0}).find("tw = 150 mm must be less than b = 150 mm"), std::string::npos);
    EXPECT_NE(message(IShape{0.3, 0.15, 0.007, 0.15, 0.0}).find("tf = 150 mm must be less than h/2"), std::string::npos);
    EXPECT_NE(message(IShape{0.3, 0.15, 0.007, 0.01, 0.08}).find("root radius r 80 mm does not fit"), std::string::npos);
    EXPECT_NE(message(IShape{0.3, 0.15, 0.007, 0.01, 0.2}).find("r = 200 mm does not fit"), std::string::npos);
    EXPECT_NE(message(CircularHollowShape{0.1, 0.05}).find("t = 50 mm must be less than D/2"), std::string::npos);
    EXPECT_NE(message(RectangularHollowShape{0.1, 0.1, 0.05, 0.0, 0.0}).find("t = 50 mm must be less than half the shorter side"), std::string::npos);
    EXPECT_NE(message(AngleShape{0.06, 0.04, 0.04, 0.0, 0.0}).find("t = 40 mm must be less than the shorter leg"), std::string::npos);
    EXPECT_NE(message(FlatBarShape{0.1, std::nan("")}).find("t must be a positive length (got not a finite number)"), std::string::npos);
    EXPECT_NE(message(TeeShape{0.1, 0.1, 0.01, 0.1, 0.0}).find("tf = 100 mm must be less than h"), std::string::npos);
}

// Names: the same row however it is written; parametric strings parsed to the same dimensions.
TEST(ShapeDesignation, SpellingsAndParametricNames) {
    const ShapeCatalogue& catalogue = ShapeCatalogue::built_in();
    ASSERT_NE(catalogue.find("IPE 300"), nullptr);
    EXPECT_EQ(catalogue.find("ipe300"), catalogue.find("IPE 300"));
    EXPECT_EQ(catalogue.find("HE 200 B"), catalogue.find("HEB200"));
    EXPECT_EQ(catalogue.find("he200b")->designation, "HEB 200");
    EXPECT_EQ(catalogue.find("chs 168.3X8")->designation, "CHS 168.3x8");
    EXPECT_EQ(catalogue.find("SHS 200 x 200 x 10")->designation, "SHS 200x200x10");
    const IShape i = std::get<IShape>(parse_shape_designation("I 300x150x7.1x10.7 r15"));
    EXPECT_DOUBLE_EQ(i.h, 0.3);
    EXPECT_DOUBLE_EQ(i.tw, 0.0071);
    EXPECT_DOUBLE_EQ(i.r, 0.015);
    const IShape ipn = std::get<IShape>(parse_shape_designation("i 200x90x7.5x11.3 r7.5 toe4.5 slope14%"));
    EXPECT_DOUBLE_EQ(ipn.flange_slope, 0.14);
    EXPECT_DOUBLE_EQ(ipn.toe_radius, 0.0045);
    const RectangularHollowShape box = std::get<RectangularHollowShape>(parse_shape_designation("BOX 200x100x8 cold"));
    EXPECT_DOUBLE_EQ(box.outer_radius, 0.02);
    EXPECT_DOUBLE_EQ(std::get<CircularHollowShape>(parse_shape_designation("TUBE 168.3x8")).D, 0.1683);
    EXPECT_EQ(parametric_name(i), "I 300x150x7.1x10.7 r15");
}

TEST(ShapeDesignation, BadNamesAreRefusedWithTheReason) {
    const auto message = [](const char* name) {
        try {
            parse_shape_designation(name);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("IPE 310"), "shape \"IPE 310\": not a known designation; did you mean IPE 300, IPE 330 or IPE 360?");
    EXPECT_NE(message("HEB 210").find("did you mean HEB 200"), std::string::npos);
    EXPECT_NE(message("I 300x150x7.1").find("the I shape needs h x b x tw x tf (4 dimensions"), std::string::npos);
    EXPECT_NE(message("I 300x150x7.1x10.7 q15").find("unknown option \"Q15\""), std::string::npos);
    EXPECT_NE(message("TUBE 100x8 r5").find("option \"R\" does not apply to the TUBE shape"), std::string::npos);
    EXPECT_NE(message("I 300x150x7.1x10..7").find("dimension 4 [mm]: \"10..7\" is not a plain decimal number"), std::string::npos);
    EXPECT_NE(message("I 300x150x7.1x200").find("tf = 200 mm must be less than h/2 = 150 mm"), std::string::npos);
    EXPECT_NE(message("BOX 100x100x8 hot cold").find("give hot or cold, not both"), std::string::npos);
}

}  // namespace
