// Results must not depend on where the section sits or how its rings are written down.
#include <gtest/gtest.h>

#include <algorithm>

#include "plascap/sections/shapes.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;
using plascap::test::part;
using plascap::test::relative_error;
using plascap::test::section_of;

namespace {

// An unsymmetric section with a hole and a second part: every integral is exercised.
Section sample_section() {
    const Ring angle = {{0, 0}, {0.12, 0}, {0.12, 0.012}, {0.015, 0.012}, {0.015, 0.08}, {0, 0.08}};
    const Ring tube_outer = regular_polygon_ring(64, 0.03, 0.1);
    const Ring tube_hole = regular_polygon_ring(48, 0.022, 0.0);
    Section s = section_of({part(angle, 355e6), part(tube_outer, 235e6, {tube_hole})});
    for (Point& p : s.parts[1].outer) p = {p.x + 0.2, p.z + 0.05};
    for (Point& p : s.parts[1].holes[0]) p = {p.x + 0.2, p.z + 0.05};
    return s;
}

Section moved(Section s, double dx, double dz) {
    auto shift = [&](Ring& r) {
        for (Point& p : r) p = {p.x + dx, p.z + dz};
    };
    for (Part& p : s.parts) {
        shift(p.outer);
        for (Ring& h : p.holes) shift(h);
    }
    return s;
}

void expect_same_capacities(const Capacities& a, const Capacities& b, double tolerance) {
    for (Capacity k : kAllCapacities) EXPECT_LT(relative_error(*a.get(k), *b.get(k)), tolerance) << to_string(k);
}

}  // namespace

// Moved 10⁴ m away: the coordinates themselves round at 10⁴·2⁻⁵³ ≈ 2e-12 m, so 1e-9 relative.
TEST(Invariance, TranslationByTenKilometres) {
    const Capacities here = test::capacities_of(sample_section());
    for (auto [dx, dz] : {std::pair{1e4, 0.0}, {0.0, -1e4}, {7071.0, 7071.0}}) {
        const Capacities there = test::capacities_of(moved(sample_section(), dx, dz));
        expect_same_capacities(there, here, 1e-9);
        EXPECT_NEAR(there.centroid.x - dx, here.centroid.x, 1e-9);
        EXPECT_NEAR(*there.z_pna - dz, *here.z_pna, 1e-9);
    }
}

TEST(Invariance, ReversedVertexOrder) {
    Section s = sample_section();
    for (Part& p : s.parts) {
        std::reverse(p.outer.begin(), p.outer.end());
        for (Ring& h : p.holes) std::reverse(h.begin(), h.end());
    }
    expect_same_capacities(test::capacities_of(s), test::capacities_of(sample_section()), 1e-12);
}

TEST(Invariance, RotatedStartVertexAndClosingVertex) {
    Section s = sample_section();
    for (Part& p : s.parts) {
        std::rotate(p.outer.begin(), p.outer.begin() + 2, p.outer.end());
        p.outer.push_back(p.outer.front());  // explicit closing vertex
    }
    expect_same_capacities(test::capacities_of(s), test::capacities_of(sample_section()), 1e-12);
}

TEST(Invariance, PartOrder) {
    Section s = sample_section();
    std::swap(s.parts[0], s.parts[1]);
    expect_same_capacities(test::capacities_of(s), test::capacities_of(sample_section()), 1e-12);
}

// Swapping x and z turns Mx into Mz and leaves the rest alone.
TEST(Invariance, SwappingAxesSwapsMxAndMz) {
    Section s = sample_section();
    for (Part& p : s.parts) {
        for (Point& q : p.outer) q = {q.z, q.x};
        for (Ring& h : p.holes)
            for (Point& q : h) q = {q.z, q.x};
    }
    const Capacities swapped = test::capacities_of(s);
    const Capacities original = test::capacities_of(sample_section());
    EXPECT_LT(relative_error(*swapped.Mx, *original.Mz), 1e-12);
    EXPECT_LT(relative_error(*swapped.Mz, *original.Mx), 1e-12);
    EXPECT_LT(relative_error(*swapped.My, *original.My), 1e-12);
    EXPECT_LT(relative_error(*swapped.N, *original.N), 1e-12);
}

// The joint point may be given; ∫d dA about a corner of a rectangle is a quarter of the doubled
// rectangle's about its centre (the closed form of reference/values.md).
TEST(Invariance, GivenJointPoint) {
    Section s = rectangle_section(0.2, 0.1, 200e6);
    s.reference = Point{0.1, 0.05};
    const double a = 0.2, c = 0.1, r = std::hypot(a, c);
    const double quarter = (2.0 / 3.0 * (2 * a * c * r + a * a * a * std::log((c + r) / a) + c * c * c * std::log((a + r) / c))) / 4.0;
    const Capacities k = test::capacities_of(s);
    EXPECT_LT(relative_error(*k.My, 100e6 * quarter), 1e-12);
    EXPECT_EQ(k.reference->x, 0.1);
    EXPECT_EQ(k.reference->z, 0.05);
}
