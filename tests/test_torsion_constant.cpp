// Saint-Venant torsion constant J by finite elements against the closed forms and the rectangle
// series of docs/references.md, and its O(h²) convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "plascap/sections/shapes.hpp"
#include "plascap/sections/torsion_constant.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::part;
using plascap::test::relative_error;
using plascap::test::section_of;

namespace {

const double kPi = std::acos(-1.0);

// J within `allowed` of `reference`; where the reference is the polygon's own J (not a curve's),
// also the check that the estimate bounds the error.
void expect_torsion(const ValidSection& s, double reference, double allowed, const char* what, bool same_shape = true,
                    double reference_rounding = 0.0) {
    const TorsionConstant t = saint_venant_torsion(s);
    EXPECT_TRUE(t.converged) << what;
    EXPECT_LT(relative_error(t.J, reference), allowed) << what << ": J = " << t.J;
    if (same_shape) {
        EXPECT_LE(std::abs(t.J - reference), t.error + reference_rounding + 1e-12 * reference)
            << what << ": the estimate is below the error";
    }
}

}  // namespace

// values.md: J = k1·h·b³ with k1 from the series, for h/b = 1, 2, 4, 10.
TEST(TorsionConstant, RectangleSeries) {
    const double b = 0.02;
    const std::vector<std::pair<double, double>> k1 = {{1, 0.14058}, {2, 0.22868}, {4, 0.28081}, {10, 0.31233}};
    for (const auto& [ratio, k] : k1) {
        const ValidSection s = validate_section(rectangle_section(ratio * b, b, 1e8));
        // k1 has 5 digits: the reference itself is good to ±0.5e-5·h·b³.
        expect_torsion(s, k * ratio * b * b * b * b, 1e-4 + 5e-6 / k, "rectangle", true, 0.5e-5 * ratio * b * b * b * b);
    }
}

// values.md: the 100 × 50 mm rectangle, J = 2,858,520.96 mm⁴ (to 1e-4, the default tolerance).
TEST(TorsionConstant, HundredByFiftyRectangle) {
    expect_torsion(validate_section(rectangle_section(0.1, 0.05, 1e8)), 2858520.96e-12, 1e-4, "100 x 50");
}

// Equilateral triangle of height h: J = h⁴/(15√3) (Timoshenko & Goodier §109).
TEST(TorsionConstant, EquilateralTriangle) {
    const double side = 0.1, h = side * std::sqrt(3.0) / 2;
    const ValidSection s = validate_section(section_of({part({{0, 0}, {side, 0}, {side / 2, h}}, 1e8)}));
    expect_torsion(s, h * h * h * h / (15 * std::sqrt(3.0)), 1e-4, "triangle");
}

// Circle πd⁴/32, ellipse πa³b³/(a² + b²), thick tube π(Ro⁴ − Ri⁴)/2 — as 1024-gons, whose own
// J lies about 5e-5 below the curve's: allowed 3e-4 against the closed form.
TEST(TorsionConstant, CircleEllipseAndTube) {
    const double r = 0.05;
    expect_torsion(validate_section(section_of({part(regular_polygon_ring(1024, r), 1e8)})), kPi * std::pow(2 * r, 4) / 32,
                   3e-4, "circle", false);
    Ring ellipse;
    for (Point p : regular_polygon_ring(1024, 1.0)) ellipse.push_back({0.06 * p.x, 0.03 * p.z});
    expect_torsion(validate_section(section_of({part(ellipse, 1e8)})),
                   kPi * std::pow(0.06, 3) * std::pow(0.03, 3) / (0.06 * 0.06 + 0.03 * 0.03), 3e-4, "ellipse", false);
    const Ring hole = regular_polygon_ring(1024, 0.03);
    expect_torsion(validate_section(section_of({part(regular_polygon_ring(1024, 0.05), 1e8, {hole})})),
                   kPi * (std::pow(0.05, 4) - std::pow(0.03, 4)) / 2, 3e-4, "thick tube", false);
}

// Quadratic triangles: the error of one mesh falls as h⁴, i.e. by 4 with each halving of the
// triangle area (the rectangle's corners leave it a little less), and J comes from below.
TEST(TorsionConstant, ConvergesAtFourthOrderFromBelow) {
    const ValidSection s = validate_section(rectangle_section(0.1, 0.05, 1e8));
    const double J = 2858520.96e-12;
    double previous = 0.0;
    for (double max_area : {5e-5, 2.5e-5, 1.25e-5, 6.25e-6}) {
        const double error = J - saint_venant_torsion_on_mesh(s, max_area);
        EXPECT_GT(error, 0.0);
        if (previous > 0.0) {
            EXPECT_GT(previous / error, 2.5) << max_area;
            EXPECT_LT(previous / error, 6.0) << max_area;
        }
        previous = error;
    }
}
