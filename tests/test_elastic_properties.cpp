// Elastic section properties against textbook closed forms, the published I section of
// docs/references.md, hand calculations for an angle, and transformed-section stiffness.
#include <gtest/gtest.h>

#include <cmath>

#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/section_json.hpp"
#include "plascap/sections/shapes.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;
using plascap::test::part;
using plascap::test::relative_error;
using plascap::test::section_of;

namespace {

constexpr double mm = 1e-3;
const double kPi = std::acos(-1.0);

}  // namespace

// b × h rectangle: Ixx = b·h³/12, Izz = h·b³/12, Wx = b·h²/6, rx = h/√12, no product moment.
TEST(ElasticProperties, Rectangle) {
    const double b = 0.1, h = 0.3;
    const ElasticProperties p = elastic_properties(validate_section(rectangle_section(b, h, 235e6)));
    EXPECT_LT(relative_error(p.Ixx, b * h * h * h / 12), 1e-14);
    EXPECT_LT(relative_error(p.Izz, h * b * b * b / 12), 1e-14);
    EXPECT_NEAR(p.Ixz, 0.0, 1e-20);
    EXPECT_LT(relative_error(p.Wx, b * h * h / 6), 1e-14);
    EXPECT_LT(relative_error(p.Wz, h * b * b / 6), 1e-14);
    EXPECT_LT(relative_error(p.rx, h / std::sqrt(12.0)), 1e-14);
    EXPECT_LT(relative_error(p.I1, p.Ixx), 1e-15);
    EXPECT_NEAR(p.principal_angle, 0.0, 1e-15);
    EXPECT_FALSE(p.stiffness);  // a bare fy gives no E
}

// The same rectangle turned by 30°: the principal values are the rectangle's, the angle is 30°, and
// Ixz = (I1 − I2)/2·sin(−2θ)... checked through Mohr: Ixx = mean + R·cos 2θ, Ixz = −R·sin 2θ.
TEST(ElasticProperties, RotatedRectangleHasItsPrincipalAxes) {
    const double b = 0.1, h = 0.3, theta = kPi / 6;
    Ring ring;
    for (Point q : rectangle_ring(h, b)) ring.push_back({q.x * std::cos(theta) - q.z * std::sin(theta), q.x * std::sin(theta) + q.z * std::cos(theta)});
    const ElasticProperties p = elastic_properties(validate_section(section_of({part(ring, 235e6)})));
    const double big = b * h * h * h / 12, small = h * b * b * b / 12;  // the long side h lies along the turned x axis
    EXPECT_LT(relative_error(p.I1, big), 1e-13);
    EXPECT_LT(relative_error(p.I2, small), 1e-13);
    EXPECT_NEAR(p.principal_angle, theta - kPi / 2, 1e-13);  // I1's axis is across the long side
    const double mean = 0.5 * (big + small), radius = 0.5 * (big - small);
    EXPECT_LT(relative_error(p.Ixx, mean + radius * std::cos(2 * p.principal_angle)), 1e-13);
    EXPECT_LT(relative_error(p.Ixz, -radius * std::sin(2 * p.principal_angle)), 1e-13);
}

// values.md: I section d = 304, b = 165, tf = 10.2, tw = 6.1 mm (no root radius): Ixx = 8.42611e7 mm⁴.
TEST(ElasticProperties, PublishedISection) {
    const double d = 304 * mm, b = 165 * mm, tf = 10.2 * mm, tw = 6.1 * mm;
    const Ring i_section = {{-b / 2, -d / 2}, {b / 2, -d / 2}, {b / 2, -d / 2 + tf}, {tw / 2, -d / 2 + tf},
                            {tw / 2, d / 2 - tf}, {b / 2, d / 2 - tf}, {b / 2, d / 2}, {-b / 2, d / 2},
                            {-b / 2, d / 2 - tf}, {-tw / 2, d / 2 - tf}, {-tw / 2, -d / 2 + tf}, {-b / 2, -d / 2 + tf}};
    const ElasticProperties p = elastic_properties(validate_section(section_of({part(i_section, 300e6)})));
    EXPECT_LT(relative_error(p.Ixx, 8.42611e7 * 1e-12), 1e-6);  // six published digits
    EXPECT_LT(relative_error(p.area, 5095.96e-6), 1e-9);
}

// Equal angle 100 × 100 × 10 mm, heel at the origin, by parts: A = 1900 mm², centroid 28.684 mm;
// Ixx = Izz = 1,800,036.5 mm⁴, Ixz = −1,065,789.5 mm⁴, so I1,2 = Ixx ± |Ixz| with I1 on the 45° line.
TEST(ElasticProperties, EqualAngleByParts) {
    const Ring angle = {{0, 0}, {100 * mm, 0}, {100 * mm, 10 * mm}, {10 * mm, 10 * mm}, {10 * mm, 100 * mm}, {0, 100 * mm}};
    const ElasticProperties p = elastic_properties(validate_section(section_of({part(angle, 275e6)})));
    const double c = (1000.0 * 5 + 900.0 * 55) / 1900;  // mm
    const double ixx = 100.0 * 1000 / 12 + 1000.0 * (5 - c) * (5 - c) + 10.0 * 729000 / 12 + 900.0 * (55 - c) * (55 - c);
    const double ixz = 1000.0 * (50 - c) * (5 - c) + 900.0 * (5 - c) * (55 - c);
    EXPECT_NEAR(p.centroid.z, c * mm, 1e-15);
    EXPECT_LT(relative_error(p.Ixx, ixx * 1e-12), 1e-13);
    EXPECT_LT(relative_error(p.Izz, ixx * 1e-12), 1e-13);
    EXPECT_LT(relative_error(p.Ixz, ixz * 1e-12), 1e-13);
    EXPECT_LT(relative_error(p.I1, (ixx - ixz) * 1e-12), 1e-13);
    EXPECT_LT(relative_error(p.I2, (ixx + ixz) * 1e-12), 1e-13);
    EXPECT_NEAR(p.principal_angle, kPi / 4, 1e-13);
}

// Hollow circle-like 256-gon tube: Ixx → π(Ro⁴ − Ri⁴)/4 (second order in 1/n; 1e-3 at n = 256).
TEST(ElasticProperties, TubeApproachesTheCircle) {
    Ring hole = regular_polygon_ring(256, 0.04);
    const ElasticProperties p = elastic_properties(
        validate_section(section_of({part(regular_polygon_ring(256, 0.05), 235e6, {hole})})));
    EXPECT_LT(relative_error(p.Ixx, kPi * (std::pow(0.05, 4) - std::pow(0.04, 4)) / 4), 1e-3);
    EXPECT_LT(relative_error(p.Ixx, p.Izz), 1e-12);
}

// Transformed section: S355 (E 210 GPa) 100 × 10 mm under EN-AW-6061-T6 (E 70 GPa) 100 × 10 mm.
// EA = Σ E·A; centroid (210·5 + 70·15)/280 = 7.5 mm; EI = Σ E·(b·t³/12 + A·d²).
TEST(ElasticProperties, ModulusWeightedComposite) {
    const Material& steel = MaterialCatalogue::built_in().get("S355", "test");
    const Material& aluminium = MaterialCatalogue::built_in().get("EN-AW-6061-T6", "test");
    const ValidSection s = validate_section(
        section_of({Part{box(0, 0, 0.1, 0.01), {}, steel}, Part{box(0, 0.01, 0.1, 0.02), {}, aluminium}}));
    const ElasticProperties p = elastic_properties(s);
    ASSERT_TRUE(p.stiffness);
    const double a = 1e-3, zc = (210e9 * 0.005 + 70e9 * 0.015) / 280e9;
    EXPECT_LT(relative_error(p.stiffness->EA, 280e9 * a), 1e-14);
    EXPECT_NEAR(p.stiffness->centroid.z, zc, 1e-16);
    const double ei = 210e9 * (0.1 * 1e-6 / 12 + a * (0.005 - zc) * (0.005 - zc)) +
                      70e9 * (0.1 * 1e-6 / 12 + a * (0.015 - zc) * (0.015 - zc));
    EXPECT_LT(relative_error(p.stiffness->EIxx, ei), 1e-13);
    EXPECT_NEAR(p.centroid.z, 0.01, 1e-16);  // the geometric centroid stays the plain one
}

// Bars displace concrete: EA = Ec·A + (Es − Ec)·A_bars (rc-beam.json: C25/30, 3 × 314 mm² B500B).
TEST(ElasticProperties, BarsInTheTransformedSection) {
    const ValidSection s = validate_section(read_section_file(std::string(PLASCAP_SOURCE_DIR) + "/sections/examples/rc-beam.json"));
    const ElasticProperties p = elastic_properties(s);
    ASSERT_TRUE(p.stiffness);
    const double bars = 3 * 314e-6;
    EXPECT_LT(relative_error(p.stiffness->EA, 31e9 * 0.15 + (200e9 - 31e9) * bars), 1e-14);
    const double zc = (200e9 - 31e9) * bars * -0.2 / p.stiffness->EA;
    EXPECT_NEAR(p.stiffness->centroid.z, zc, 1e-15);
    EXPECT_LT(relative_error(p.stiffness->EIxx, 31e9 * (0.3 * 0.125 / 12 + 0.15 * zc * zc) +
                                                    (200e9 - 31e9) * bars * (-0.2 - zc) * (-0.2 - zc)),
              1e-13);
}
