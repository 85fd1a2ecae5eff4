#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "plascap/sections/ring_integrals.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;

// Rectangle [x0, x1] x [z0, z1]: A = (x1−x0)(z1−z0), ∫x dA = A·(x0+x1)/2, ∫z dA = A·(z0+z1)/2.
TEST(RingMoments, RectangleAreaAndFirstMoments) {
    const RingMoments m = ring_moments(box(1.0, 2.0, 4.0, 7.0));
    EXPECT_NEAR(m.area, 15.0, 1e-13);
    EXPECT_NEAR(m.Sx, 15.0 * 2.5, 1e-12);
    EXPECT_NEAR(m.Sz, 15.0 * 4.5, 1e-12);
}

TEST(RingMoments, ClockwiseRingIsNegative) {
    Ring r = box(0, 0, 2, 3);
    std::reverse(r.begin(), r.end());
    EXPECT_NEAR(ring_moments(r).area, -6.0, 1e-14);
}

// Square [0,2]²: the part below z = 0.5 has area 1 and ∫(z − 0.5) dA = 2·∫_0^0.5 (z − 0.5) dz = −0.25;
// above: area 3, ∫(z − 0.5) dA = 2·∫_0.5^2 (z − 0.5) dz = 2.25.
TEST(HalfPlaneMoments, SquareCutHorizontally) {
    const Ring r = box(0, 0, 2, 2);
    const HalfPlaneMoments below = half_plane_moments(r, BendingAxis::X, 0.5, Side::Below);
    const HalfPlaneMoments above = half_plane_moments(r, BendingAxis::X, 0.5, Side::Above);
    EXPECT_NEAR(below.area, 1.0, 1e-14);
    EXPECT_NEAR(below.first_moment, -0.25, 1e-14);
    EXPECT_NEAR(above.area, 3.0, 1e-14);
    EXPECT_NEAR(above.first_moment, 2.25, 1e-14);
}

// Right triangle (0,0), (2,0), (0,2) cut at x = 1 (BendingAxis::Z): left of it a trapezoid of area
// ∫_0^1 (2 − x) dx = 1.5 and ∫_0^1 (x − 1)(2 − x) dx = −5/6; right: area 0.5, ∫_1^2 (x−1)(2−x) dx = 1/6.
TEST(HalfPlaneMoments, TriangleCutVertically) {
    const Ring r = {{0, 0}, {2, 0}, {0, 2}};
    const HalfPlaneMoments left = half_plane_moments(r, BendingAxis::Z, 1.0, Side::Below);
    const HalfPlaneMoments right = half_plane_moments(r, BendingAxis::Z, 1.0, Side::Above);
    EXPECT_NEAR(left.area, 1.5, 1e-14);
    EXPECT_NEAR(left.first_moment, -5.0 / 6.0, 1e-14);
    EXPECT_NEAR(right.area, 0.5, 1e-14);
    EXPECT_NEAR(right.first_moment, 1.0 / 6.0, 1e-14);
}

// Chord of the same triangle on the line z = t is 2 − t; on x = t it is 2 − t too.
TEST(ChordLengths, TriangleChordsAreLinear) {
    const Ring r = {{0, 0}, {2, 0}, {0, 2}};
    const Chords horizontal = chord_lengths(r, BendingAxis::X, 0.0, 2.0);
    EXPECT_NEAR(horizontal.at_a, 2.0, 1e-14);
    EXPECT_NEAR(horizontal.at_b, 0.0, 1e-14);
    const Chords vertical = chord_lengths(r, BendingAxis::Z, 0.0, 2.0);
    EXPECT_NEAR(vertical.at_a, 2.0, 1e-14);
    EXPECT_NEAR(vertical.at_b, 0.0, 1e-14);
}

// A clockwise hole subtracts its chord: square [0,4]² with hole [1,3]², on the piece z ∈ [1, 3]
// the chord is 4 − 2 = 2 at both ends.
TEST(ChordLengths, HoleSubtracts) {
    Ring hole = box(1, 1, 3, 3);
    std::reverse(hole.begin(), hole.end());
    const Chords outer = chord_lengths(box(0, 0, 4, 4), BendingAxis::X, 1.0, 3.0);
    const Chords inner = chord_lengths(hole, BendingAxis::X, 1.0, 3.0);
    EXPECT_NEAR(outer.at_a + inner.at_a, 2.0, 1e-14);
    EXPECT_NEAR(outer.at_b + inner.at_b, 2.0, 1e-14);
}

// docs/references.md: ∫∫ d dA over [−a, a] x [−c, c] about its centre, r = √(a²+c²):
// (2/3)[2acr + a³ ln((c+r)/a) + c³ ln((a+r)/c)].
double rectangle_distance_integral(double a, double c) {
    const double r = std::hypot(a, c);
    return 2.0 / 3.0 * (2.0 * a * c * r + a * a * a * std::log((c + r) / a) + c * c * c * std::log((a + r) / c));
}

TEST(DistanceIntegral, RectangleAboutItsCentreMatchesClosedForm) {
    for (auto [a, c] : {std::pair{0.5, 0.5}, {1.0, 0.25}, {0.01, 3.0}, {2.0, 1e-3}}) {
        const double value = distance_integral(box(-a, -c, a, c), Point{0, 0});
        EXPECT_LT(test::relative_error(value, rectangle_distance_integral(a, c)), 1e-13) << a << " x " << c;
    }
}

// About a corner: the rectangle [0, 2a] x [0, 2c] seen from (0,0) is a quarter of the
// [−2a, 2a] x [−2c, 2c] rectangle seen from its centre.
TEST(DistanceIntegral, AboutACornerIsAQuarterOfTheDoubledRectangle) {
    const double a = 0.3, c = 0.7;
    const double value = distance_integral(box(0, 0, 2 * a, 2 * c), Point{0, 0});
    EXPECT_LT(test::relative_error(value, rectangle_distance_integral(2 * a, 2 * c) / 4.0), 1e-13);
}

// About a point outside: ∫ d dA over the unit square [1,2] x [0,1] about (0,0) equals the
// quarter-of-doubled-rectangle for [0,2] x [0,1] minus that for [0,1] x [0,1].
TEST(DistanceIntegral, AboutAnOutsidePointBySubtraction) {
    const double whole = rectangle_distance_integral(2.0, 1.0) / 4.0;
    const double left = rectangle_distance_integral(1.0, 1.0) / 4.0;
    const double value = distance_integral(box(1, 0, 2, 1), Point{0, 0});
    EXPECT_LT(test::relative_error(value, whole - left), 1e-13);
}

// The same rectangles with every side cut into m collinear pieces: the integral cannot change. Rings
// of 4m vertices cross distance_integral's batches of 64 edges at other places for each m; seen from
// the centre, short pieces take the series for ln(g1/g0) and long ones std::log; seen from a corner,
// the pieces of the two sides through it lie on lines through the point and add nothing.
Ring subdivided_box(double x0, double z0, double x1, double z1, int m) {
    const Ring corners = box(x0, z0, x1, z1);
    Ring ring;
    for (std::size_t side = 0; side < corners.size(); ++side) {
        const Point p = corners[side], q = corners[(side + 1) % corners.size()];
        for (int k = 0; k < m; ++k) {
            const double s = static_cast<double>(k) / m;
            ring.push_back({p.x + s * (q.x - p.x), p.z + s * (q.z - p.z)});
        }
    }
    return ring;
}

TEST(DistanceIntegral, CollinearPiecesAcrossBatchesChangeNothing) {
    const double a = 0.3, c = 0.7;
    for (int m : {1, 15, 16, 17, 33, 250}) {
        const double centre = distance_integral(subdivided_box(-a, -c, a, c, m), Point{0, 0});
        EXPECT_LT(test::relative_error(centre, rectangle_distance_integral(a, c)), 1e-13) << m << " pieces a side";
        const double corner = distance_integral(subdivided_box(0, 0, 2 * a, 2 * c, m), Point{0, 0});
        EXPECT_LT(test::relative_error(corner, rectangle_distance_integral(2 * a, 2 * c) / 4.0), 1e-13) << m << " pieces a side";
    }
}
