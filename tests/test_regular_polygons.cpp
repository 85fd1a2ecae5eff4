// Regular n-gons against their own closed forms, and their convergence to the circle's.
#include <gtest/gtest.h>

#include <cmath>

#include "plascap/sections/shapes.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::relative_error;

namespace {

const double kPi = std::acos(-1.0);

Capacities ngon(std::size_t n, double R, double fy, double start = 0.0) {
    return test::capacities_of(test::section_of({test::part(regular_polygon_ring(n, R, start), fy)}));
}

// n fan triangles of apothem a = R·cos(π/n): ∫∫ r dA = n·∫_{−π/n}^{π/n} (a·sec φ)³/3 dφ and
// ∫ sec³ = ½(sec·tan + ln(sec + tan)) (integral tables), so ∫ d dA = (n·a³/3)·[sec·tan + ln(sec + tan)] at π/n.
double ngon_distance_integral(std::size_t n, double R) {
    const double phi = kPi / static_cast<double>(n);
    const double a = R * std::cos(phi);
    const double sec = 1.0 / std::cos(phi), tan = std::tan(phi);
    return static_cast<double>(n) * a * a * a / 3.0 * (sec * tan + std::log(sec + tan));
}

}  // namespace

TEST(RegularPolygon, AreaAndTorsionMatchClosedForms) {
    const double R = 0.2, fy = 300e6;
    for (std::size_t n : {3u, 4u, 5u, 6u, 7u, 12u, 100u, 1000u}) {
        const Capacities c = ngon(n, R, fy, 0.3);
        const double area = 0.5 * static_cast<double>(n) * R * R * std::sin(2.0 * kPi / static_cast<double>(n));
        EXPECT_LT(relative_error(c.area, area), 1e-12) << n;
        EXPECT_LT(relative_error(*c.N, fy * area), 1e-12) << n;
        EXPECT_LT(relative_error(*c.My, fy / 2.0 * ngon_distance_integral(n, R)), 1e-12) << n;
        EXPECT_NEAR(c.centroid.x, 0.0, 1e-14);
        EXPECT_NEAR(c.centroid.z, 0.0, 1e-14);
    }
}

// Diamond (square on its corner, half-diagonal R): each half is a triangle of area R² with its
// centroid R/3 from the axis, so Mx = Mz = 2·fy·R³/3.
TEST(RegularPolygon, DiamondPlasticMoments) {
    const double R = 0.05, fy = 235e6;
    const Capacities c = ngon(4, R, fy);
    EXPECT_LT(relative_error(*c.Mx, 2.0 * fy * R * R * R / 3.0), 1e-12);
    EXPECT_LT(relative_error(*c.Mz, 2.0 * fy * R * R * R / 3.0), 1e-12);
}

// Hexagon with a vertex on +x (flats at z = ±R√3/2): the upper half is a trapezoid of first moment
// R³/2 about the axis, so Mx = fy·R³; the right half has first moment (7/12)·h·R² with h = R√3/2,
// so Mz = (7√3/12)·fy·R³ (hand computation by strips).
TEST(RegularPolygon, HexagonPlasticMoments) {
    const double R = 0.1, fy = 355e6;
    const Capacities c = ngon(6, R, fy);
    EXPECT_LT(relative_error(*c.Mx, fy * R * R * R), 1e-12);
    EXPECT_LT(relative_error(*c.Mz, 7.0 * std::sqrt(3.0) / 12.0 * fy * R * R * R), 1e-12);
}

// Circle (reference/values.md): Mx = Mz = (4/3)·R³·fy, ∫ d dA = (2/3)·π·R³. Inscribed n-gons
// converge at second order: the error falls about 4x per doubling of n.
TEST(RegularPolygon, ConvergesToTheCircleAtSecondOrder) {
    const double R = 0.15, fy = 250e6;
    const double circle_M = 4.0 / 3.0 * R * R * R * fy;
    const double circle_My = fy / 2.0 * 2.0 / 3.0 * kPi * R * R * R;
    double previous_M = 0.0, previous_My = 0.0;
    for (std::size_t n = 64; n <= 4096; n *= 2) {
        const Capacities c = ngon(n, R, fy);
        const double error_M = relative_error(*c.Mx, circle_M);
        const double error_My = relative_error(*c.My, circle_My);
        if (previous_M > 0.0) {
            EXPECT_NEAR(previous_M / error_M, 4.0, 0.3) << n;
            EXPECT_NEAR(previous_My / error_My, 4.0, 0.3) << n;
        }
        previous_M = error_M;
        previous_My = error_My;
    }
    EXPECT_LT(previous_M, 2e-6);   // n = 4096
    EXPECT_LT(previous_My, 2e-6);
}
