// The fully plastic torque T_p (Nadai's sand heap) against the closed forms of
// docs/references.md; the estimate must bound the error where the reference is exact.
#include <gtest/gtest.h>

#include <cmath>

#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/shapes.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::part;
using plascap::test::relative_error;
using plascap::test::section_of;

namespace {

constexpr double kFy = 200e6, kTau = 100e6;  // Tresca
const double kPi = std::acos(-1.0);

void expect_torque(const Section& s, double reference, double allowed, const char* what, bool exact_reference = true) {
    const PlasticTorsion t = plastic_torsion(validate_section(s));
    EXPECT_TRUE(t.converged) << what;
    EXPECT_LT(relative_error(t.T, reference), allowed) << what << ": T_p = " << t.T;
    if (exact_reference) {
        EXPECT_LE(std::abs(t.T - reference), t.error) << what << ": the estimate is below the error";
    }
}

}  // namespace

// Rectangle b ≤ h: τy·b²(3h − b)/6; square a: τy·a³/3.
TEST(PlasticTorsion, RectangleAndSquare) {
    expect_torque(rectangle_section(0.1, 0.05, kFy), kTau * 0.05 * 0.05 * (3 * 0.1 - 0.05) / 6, 1e-4, "rectangle");
    expect_torque(rectangle_section(0.05, 0.5, kFy), kTau * 0.05 * 0.05 * (3 * 0.5 - 0.05) / 6, 1e-4, "1:10 rectangle");
    expect_torque(rectangle_section(0.1, 0.1, kFy), kTau * 1e-3 / 3, 1e-4, "square");
}

// Equilateral triangle of side a: τy·a³/12. A regular polygon has an inscribed circle of radius
// r = R·cos(π/n): T_p = (2/3)·A·r·τy exactly; as n grows, the circle's (2/3)πR³τy.
TEST(PlasticTorsion, TriangleAndRegularPolygons) {
    const double a = 0.1;
    expect_torque(section_of({part({{0, 0}, {a, 0}, {a / 2, a * std::sqrt(3.0) / 2}}, kFy)}), kTau * a * a * a / 12, 1e-4, "triangle");
    for (int n : {6, 24}) {
        const double R = 0.05, area = 0.5 * n * R * R * std::sin(2 * kPi / n), r = R * std::cos(kPi / n);
        expect_torque(section_of({part(regular_polygon_ring(n, R), kFy)}), 2.0 / 3 * area * r * kTau, 1e-4, "regular polygon");
    }
    expect_torque(section_of({part(regular_polygon_ring(64, 0.05), kFy)}), 2.0 / 3 * kPi * std::pow(0.05, 3) * kTau, 3e-3,
                  "circle as a 64-gon (whose own T_p is 1.6e-3 below)", false);
}

// Square tube 200 × 200 outside, 190 × 190 hole (t = 5 mm): the heap rises 1:1 across the wall to a
// plateau c = t over the hole, so V = 4·0.19·t·t/2 + 4·t³/3 + t·0.19² exactly, T_p = 2·τy·V; the
// thin-wall formula 2·A_m·t·τy (A_m = 0.195²) is 2.3e-4 below it.
TEST(PlasticTorsion, ThinSquareTube) {
    const double t = 0.005;
    const Section tube = section_of({part(rectangle_ring(0.2, 0.2), kFy, {rectangle_ring(0.19, 0.19)})});
    const double volume = 4 * 0.19 * t * t / 2 + 4 * t * t * t / 3 + t * 0.19 * 0.19;
    expect_torque(tube, 2 * kTau * volume, 1e-4, "square tube");
    expect_torque(tube, 2 * 0.195 * 0.195 * t * kTau, 3e-4, "square tube, thin-wall formula", false);
}

// Equal angle 100 × 100 × 5 mm against the thin open-section formula Σ b·t²·τy/2 over its two legs
// (100 and 95 mm): that formula ignores the ends and the corner, about t/b = 5 % here.
TEST(PlasticTorsion, AngleAgainstThinWalledFormula) {
    const double mm = 1e-3, t = 5 * mm;
    const Section angle =
        section_of({part({{0, 0}, {100 * mm, 0}, {100 * mm, t}, {t, t}, {t, 100 * mm}, {0, 100 * mm}}, kFy)});
    expect_torque(angle, (100 * mm + 95 * mm) * t * t * kTau / 2, 0.08, "angle, thin-wall formula", false);
}
