// One test per validation rule: each bad section is refused with a message that names the
// problem and where it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "plascap/input_error.hpp"
#include "plascap/sections/shapes.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;
using plascap::test::part;
using plascap::test::section_of;

namespace {

// The InputError message of validate_section, or "" when the section is accepted.
std::string refusal(const Section& s) {
    try {
        validate_section(s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

#define EXPECT_REFUSED(section, text) EXPECT_EQ(refusal(section), text)

TEST(Validation, AcceptsAGoodSection) { EXPECT_EQ(refusal(rectangle_section(0.1, 0.2, 1e8)), ""); }

TEST(Validation, NoParts) { EXPECT_REFUSED(Section{}, "section: has no parts; give at least one part with an outer ring"); }

TEST(Validation, TooFewVertices) {
    EXPECT_REFUSED(section_of({part({{0, 0}, {1, 0}}, 1e8)}),
                   "part 0, outer ring: has 2 distinct vertices; a ring needs at least 3");
    // A closing vertex does not count.
    EXPECT_REFUSED(section_of({part({{0, 0}, {1, 0}, {0, 0}}, 1e8)}),
                   "part 0, outer ring: has 2 distinct vertices; a ring needs at least 3");
}

TEST(Validation, NonFiniteCoordinate) {
    EXPECT_REFUSED(section_of({part({{0, 0}, {1, 0}, {1, kNaN}, {0, 1}}, 1e8)}),
                   "part 0, outer ring, vertex 2: coordinate z is not a finite number (nan)");
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {{{0.2, 0.2}, {INFINITY, 0.2}, {0.5, 0.5}}})}),
                   "part 0, hole 0, vertex 1: coordinate x is not a finite number (inf)");
}

TEST(Validation, CoordinateOutOfRange) {
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 2e7), 1e8)}),
                   "part 0, outer ring, vertex 2: coordinate z = 20000000 m is outside the supported range ±1e6 m");
}

TEST(Validation, RepeatedVertex) {
    EXPECT_REFUSED(section_of({part({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}, 1e8)}),
                   "part 0, outer ring, vertex 2: repeats vertex 1");
}

TEST(Validation, ZeroArea) {
    EXPECT_REFUSED(section_of({part({{0, 0}, {1, 1}, {2, 2}}, 1e8)}),
                   "part 0, outer ring: has zero area: its vertices are collinear");
}

TEST(Validation, VanishingArea) {
    // Collinear up to the round-off of the coordinates.
    const std::string nearly = refusal(section_of({part({{0, 0}, {1, 1e-14}, {2, 0}}, 1e8)}));
    EXPECT_EQ(nearly.rfind("part 0, outer ring: has vanishing area (", 0), 0u) << nearly;
    // Sides of 1e-300 m.
    EXPECT_REFUSED(section_of({part(box(0, 0, 1e-300, 1e-300), 1e8)}),
                   "part 0, outer ring: is only 1e-300 m across; the smallest supported ring is 1e-9 m across");
}

TEST(Validation, SelfIntersectingRingNamesTheEdges) {
    EXPECT_REFUSED(section_of({part({{0, 0}, {2, 2}, {2, 0}, {0, 1}}, 1e8)}),
                   "part 0, outer ring, vertex 0: is self-intersecting: edge 0-1 meets edge 2-3");
    // A symmetric bow tie, whose lobes cancel to zero area, is still called self-intersecting.
    EXPECT_REFUSED(section_of({part({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 1e8)}),
                   "part 0, outer ring, vertex 0: is self-intersecting: edge 0-1 meets edge 2-3");
    // Touching itself at a vertex (figure of eight through (1, 1)).
    const std::string touch =
        refusal(section_of({part({{0, 0}, {1, 1}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}, 1e8)}));
    EXPECT_NE(touch.find("is self-intersecting"), std::string::npos) << touch;
}

TEST(Validation, RingsThatTurnOneWayButWindTwiceAreSelfIntersecting) {
    // Every turn of a pentagram, and of a spiral twice round, is a left turn — locally convex — yet
    // they cross themselves: the convex fast path of the simplicity test must not take them.
    plascap::Ring star, spiral;
    for (int i = 0; i < 5; ++i) {
        const double a = 4.0 * M_PI * i / 5.0;
        star.push_back({std::cos(a), std::sin(a)});
    }
    for (int i = 0; i < 10; ++i) {
        const double a = 4.0 * M_PI * i / 10.0 + 0.1, r = 1.0 + 0.01 * i;
        spiral.push_back({r * std::cos(a), r * std::sin(a)});
    }
    for (const auto& ring : {star, spiral}) {
        const std::string message = refusal(section_of({part(ring, 1e8)}));
        EXPECT_NE(message.find("is self-intersecting"), std::string::npos) << message;
    }
}

TEST(Validation, HoleOutsideItsOuterRing) {
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {box(2, 2, 3, 3)})}),
                   "part 0, hole 0, vertex 0: lies outside its outer ring; holes must lie strictly inside it");
}

// Touching rings are named with the two edges that meet, counted as the user gave them.
TEST(Validation, HoleTouchingOrCrossingItsOuterRing) {
    auto message = [](int hole_edge, int outer_edge) {
        return "part 0, hole 0, vertex " + std::to_string(hole_edge) + ": touches or crosses its outer ring (its edge " +
               std::to_string(hole_edge) + "-" + std::to_string(hole_edge + 1) + " meets edge " +
               std::to_string(outer_edge) + "-" + std::to_string(outer_edge + 1) +
               " of the outer ring); holes must lie strictly inside it";
    };
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {box(0.5, 0.5, 1.5, 0.8)})}), message(0, 1));  // crosses
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {box(0.2, 0.0, 0.4, 0.5)})}), message(0, 0));  // shares an edge
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {{{0.3, 0.3}, {0.5, 0.0}, {0.7, 0.3}}})}), message(0, 0));  // vertex on edge
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {{{0.2, 0.5}, {0.0, 0.0}, {0.5, 0.2}}})}), message(0, 0));  // shared vertex
    // A clockwise hole is named in the order given, too: reversed, the crossing edge is 2-3.
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {{{0.5, 0.5}, {0.5, 0.8}, {1.5, 0.8}, {1.5, 0.5}}})}),
                   message(1, 1));
}

TEST(Validation, HolesOverlapping) {
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {box(0.1, 0.1, 0.5, 0.5), box(0.4, 0.4, 0.8, 0.8)})}),
                   "part 0, hole 1, vertex 0: overlaps or touches hole 0 of the same part (its edge 0-1 meets edge 1-2 of hole 0)");
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {box(0.1, 0.1, 0.9, 0.9), box(0.3, 0.3, 0.6, 0.6)})}),
                   "part 0, hole 1, vertex 0: overlaps or touches hole 0 of the same part");  // inside the other
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8, {box(0.3, 0.3, 0.6, 0.6), box(0.1, 0.1, 0.9, 0.9)})}),
                   "part 0, hole 1: overlaps or touches hole 0 of the same part (which lies inside it)");
}

TEST(Validation, PartsOverlapping) {
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8), part(box(2, 0, 3, 1), 1e8), part(box(0.5, 0.5, 1.5, 1.5), 1e8)}),
                   "part 2: overlaps part 0 by 0.25 m² (parts may share edges, not area)");
    // A part inside another's hole does not overlap it; parts sharing an edge or a corner are fine.
    EXPECT_EQ(refusal(section_of({part(box(0, 0, 3, 3), 1e8, {box(1, 1, 2, 2)}), part(box(1.2, 1.2, 1.8, 1.8), 1e8)})), "");
    EXPECT_EQ(refusal(section_of({part(box(0, 0, 1, 1), 1e8), part(box(1, 0, 2, 1), 1e8), part(box(2, 1, 3, 2), 1e8)})), "");
}

// A shared edge written twice with round-off (70·0.01 + 0.01 lies one ulp above 71·0.01) overlaps by
// ~1e-19 m²: that is the same edge, not an overlap. An overlap of 1e-6 of the part is refused.
TEST(Validation, RoundOffOverlapOfASharedEdgeIsAccepted) {
    const double top_of_lower = 70 * 0.01 + 0.01, bottom_of_upper = 71 * 0.01;
    ASSERT_GT(top_of_lower, bottom_of_upper);  // the premise: the parts really overlap, by round-off
    EXPECT_EQ(refusal(section_of({part(box(0, 0.7, 0.01, top_of_lower), 1e8), part(box(0, bottom_of_upper, 0.01, 0.72), 1e8)})), "");
    const std::string real = refusal(section_of({part(box(0, 0, 1, 1), 1e8), part(box(0, 1 - 1e-6, 1, 2), 1e8)}));
    EXPECT_EQ(real.rfind("part 1: overlaps part 0 by 1.0000000", 0), 0u) << real;
}

TEST(Validation, YieldStressMustBeFiniteAndNonNegative) {
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), 1e8), part(box(1, 0, 2, 1), -2e8)}),
                   "part 1, material: yield stress fy must be a finite number >= 0 in Pa (got -200000000)");
    EXPECT_REFUSED(section_of({part(box(0, 0, 1, 1), kNaN)}),
                   "part 0, material: yield stress fy must be a finite number >= 0 in Pa (got nan)");
}

TEST(Validation, JointPointMustBeFinite) {
    Section s = rectangle_section(0.1, 0.1, 1e8);
    s.reference = Point{kNaN, 0.0};
    EXPECT_REFUSED(s, "reference: the joint point (nan, 0) must be finite and within ±1e6 m");
}

// The bending axes search each part's level range from these boxes (plastic_bending.cpp): each must
// be exactly the outer ring's extent in local coordinates, also for a section far from the origin.
TEST(Validation, KeepsEachPartsBoxInLocalCoordinates) {
    const Ring triangle{{1e4 + 0.3, 2e4}, {1e4 + 0.5, 2e4 + 0.05}, {1e4 + 0.3, 2e4 + 0.2}};
    const ValidSection valid = validate_section(section_of({part(box(1e4, 2e4, 1e4 + 0.3, 2e4 + 0.1), 1e8), part(triangle, 1e8)}));
    ASSERT_EQ(valid.part_extents().size(), 2u);
    for (std::size_t p = 0; p < 2; ++p) {
        const Ring& ring = valid.parts()[p].outer;
        const RingExtent& e = valid.part_extents()[p];
        double min_x = ring[0].x, max_x = ring[0].x, min_z = ring[0].z, max_z = ring[0].z;
        for (Point q : ring) {
            min_x = std::min(min_x, q.x), max_x = std::max(max_x, q.x);
            min_z = std::min(min_z, q.z), max_z = std::max(max_z, q.z);
        }
        EXPECT_EQ(e.min_x, min_x) << "part " << p;
        EXPECT_EQ(e.max_x, max_x) << "part " << p;
        EXPECT_EQ(e.min_z, min_z) << "part " << p;
        EXPECT_EQ(e.max_z, max_z) << "part " << p;
    }
    // Local coordinates are centred on the whole section's box: x from 1e4 to 1e4 + 0.5.
    EXPECT_NEAR(valid.part_extents()[1].max_x, 0.25, 1e-9);
    EXPECT_NEAR(valid.part_extents()[0].min_z, -0.1, 1e-9);
}
