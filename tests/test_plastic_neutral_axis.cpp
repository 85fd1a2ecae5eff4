// Unsymmetric, hollow and multi-part sections against hand-computed plastic moduli about the
// equal-force axis (not the centroidal one).
#include <gtest/gtest.h>

#include <cmath>

#include "plascap/sections/section_json.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;
using plascap::test::part;
using plascap::test::relative_error;
using plascap::test::section_of;

namespace {
constexpr double mm = 1e-3;
const Ring kTee = {{-5 * mm, 0}, {5 * mm, 0}, {5 * mm, 200 * mm}, {50 * mm, 200 * mm},
                   {50 * mm, 210 * mm}, {-50 * mm, 210 * mm}, {-50 * mm, 200 * mm}, {-5 * mm, 200 * mm}};
}  // namespace

// T: flange 100 x 10 on web 10 x 200 (mm). A = 3000 mm², half = 1500 → the axis is 150 mm up the
// web. About it: web below 1500·75 = 112,500; web above 500·25 = 12,500; flange 1000·55 = 55,000;
// Z = 180,000 mm³. Centroid (1000·205 + 2000·100)/3000 = 135 mm. About z (symmetric): flange
// halves 50 x 10 at 25 mm give 2·500·25 = 25,000, web halves 5 x 200 at 2.5 mm give 2·1000·2.5
// = 5,000 → Z = 30,000 mm³.
TEST(PlasticNeutralAxis, TeeSectionUsesTheEqualForceAxis) {
    const double fy = 235e6;
    const Capacities c = test::capacities_of(section_of({part(kTee, fy)}));
    EXPECT_NEAR(*c.z_pna, 150 * mm, 1e-15);
    EXPECT_NEAR(c.centroid.z, 135 * mm, 1e-15);
    EXPECT_LT(relative_error(*c.Mx, fy * 180000e-9), 1e-12);
    EXPECT_NEAR(*c.x_pna, 0.0, 1e-16);
    EXPECT_LT(relative_error(*c.Mz, fy * 30000e-9), 1e-12);
}

// The same T built as two parts sharing the flange-web edge gives the same capacities.
TEST(PlasticNeutralAxis, TeeAsTwoPartsEqualsTeeAsOnePolygon) {
    const double fy = 235e6;
    const Capacities one = test::capacities_of(section_of({part(kTee, fy)}));
    const Capacities two = test::capacities_of(section_of(
        {part(box(-5 * mm, 0, 5 * mm, 200 * mm), fy), part(box(-50 * mm, 200 * mm, 50 * mm, 210 * mm), fy)}));
    for (Capacity k : kAllCapacities) EXPECT_LT(relative_error(*two.get(k), *one.get(k)), 1e-12) << to_string(k);
}

// Kink case: when the flange area equals the web area the axis sits exactly on the junction.
// Flange 100 x 20 on web 20 x 100 (mm): axis at z = 100 mm; Z = 2000·50 + 2000·10 = 120,000 mm³.
TEST(PlasticNeutralAxis, TeeWithAxisOnTheFlangeWebJunction) {
    const double fy = 355e6;
    const Ring tee = {{-10 * mm, 0}, {10 * mm, 0}, {10 * mm, 100 * mm}, {50 * mm, 100 * mm},
                      {50 * mm, 120 * mm}, {-50 * mm, 120 * mm}, {-50 * mm, 100 * mm}, {-10 * mm, 100 * mm}};
    const Capacities c = test::capacities_of(section_of({part(tee, fy)}));
    EXPECT_NEAR(*c.z_pna, 100 * mm, 1e-15);
    EXPECT_LT(relative_error(*c.Mx, fy * 120000e-9), 1e-12);
}

// Equal angle 100 x 100 x 10 (mm), heel at the origin. A = 1900 mm², half = 950 → the horizontal
// axis is 9.5 mm up (inside the horizontal leg). Z = 100·9.5·4.75 + 100·0.5·0.25 + 900·45.5
// = 45,475 mm³; by symmetry about the diagonal, the same about z with x_pna = 9.5 mm.
TEST(PlasticNeutralAxis, EqualAngle) {
    const double fy = 275e6;
    const Ring angle = {{0, 0}, {100 * mm, 0}, {100 * mm, 10 * mm}, {10 * mm, 10 * mm}, {10 * mm, 100 * mm}, {0, 100 * mm}};
    const Capacities c = test::capacities_of(section_of({part(angle, fy)}));
    EXPECT_NEAR(*c.z_pna, 9.5 * mm, 1e-16);
    EXPECT_NEAR(*c.x_pna, 9.5 * mm, 1e-16);
    EXPECT_LT(relative_error(*c.Mx, fy * 45475e-9), 1e-12);
    EXPECT_LT(relative_error(*c.Mz, fy * 45475e-9), 1e-12);
}

// Hollow rectangle 200 x 100 outer, 180 x 80 hole (mm): Mx = fy·(B·H² − b·h²)/4, Mz likewise;
// N = fy·(B·H − b·h).
TEST(PlasticNeutralAxis, HollowRectangle) {
    const double fy = 355e6;
    const Capacities c = test::capacities_of(
        section_of({part(box(-0.1, -0.05, 0.1, 0.05), fy, {box(-0.09, -0.04, 0.09, 0.04)})}));
    EXPECT_LT(relative_error(*c.N, fy * (0.2 * 0.1 - 0.18 * 0.08)), 1e-12);
    EXPECT_LT(relative_error(*c.Mx, fy * (0.2 * 0.01 - 0.18 * 0.0064) / 4.0), 1e-12);
    EXPECT_LT(relative_error(*c.Mz, fy * (0.1 * 0.04 - 0.08 * 0.0324) / 4.0), 1e-12);
}

// Two equal flanges 200 x 20 mm, 260 mm apart (centre to centre), no web: the equal-force axis is
// anywhere in the gap (plascap reports its middle, z = 0), and Mx = fy·2·A·d = fy·2·4000·130 mm³.
TEST(PlasticNeutralAxis, TwoSeparatePartsAxisInTheGap) {
    const double fy = 355e6;
    const Capacities c = test::capacities_of(section_of(
        {part(box(-0.1, -0.14, 0.1, -0.12), fy), part(box(-0.1, 0.12, 0.1, 0.14), fy)}));
    EXPECT_NEAR(*c.z_pna, 0.0, 1e-15);
    EXPECT_LT(relative_error(*c.Mx, fy * 2.0 * 4000e-6 * 0.13), 1e-12);
    EXPECT_LT(relative_error(*c.Mz, fy * 2.0 * 0.02 * 0.2 * 0.2 / 4.0), 1e-12);
}

// Two 100 x 100 mm parts sharing an edge, fy = 2f below and f above: total 3f·A, half 1.5f·A lies
// 75 mm up the stronger part. Mx = 2f·(0.1·0.075·0.0375 + 0.1·0.025·0.0125) + f·0.01·0.075
// = 1.375e-3·f [N·m with f in Pa].
TEST(PlasticNeutralAxis, TwoMaterialsShiftTheAxisIntoTheStrongerPart) {
    const double f = 230e6;
    const Capacities c = test::capacities_of(section_of({part(box(0, 0, 0.1, 0.1), 2 * f), part(box(0, 0.1, 0.1, 0.2), f)}));
    EXPECT_NEAR(*c.z_pna, 0.075, 1e-16);
    EXPECT_NEAR(c.centroid.z, 0.1, 1e-16);  // the area centroid ignores fy
    EXPECT_LT(relative_error(*c.Mx, 1.375e-3 * f), 1e-12);
    EXPECT_LT(relative_error(*c.N, 3.0 * f * 0.01), 1e-12);
}

// docs/references.md: I section without root radius, d = 304, b = 165, tf = 10.2,
// tw = 6.1 mm: A = 5095.96 mm², Sxx = 617,119.6 mm³, Syy = 141,485.7 mm³ (published to 0.1 mm³).
TEST(PublishedValues, ISection310UB) {
    const Section s = read_section_file(std::string(PLASCAP_SOURCE_DIR) + "/sections/examples/i-section.json");
    const double fy = s.parts[0].material.fy;
    const Capacities c = test::capacities_of(s);
    EXPECT_LT(relative_error(c.area, 5095.96e-6), 1e-12);
    EXPECT_LT(relative_error(*c.Mx / fy, 617119.6e-9), 2e-7);
    EXPECT_LT(relative_error(*c.Mz / fy, 141485.7e-9), 2e-7);
}
