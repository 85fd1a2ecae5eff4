// The cubature route (CGAL mesh + GSL cubature) against the exact route (closed forms), which is
// itself tested against hand values and published tables: on every example and test section of
// the core, the cubature value must agree within the requested tolerance, and its own error
// estimate must bound the actual error. Both routes carry round-off of a few ε per operation;
// kRoundoff (1e-14 relative) allows for it on either side.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "plascap/input_error.hpp"
#include "plascap/sections/cubature.hpp"
#include "plascap/sections/section_json.hpp"
#include "plascap/sections/shapes.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;
using plascap::test::part;
using plascap::test::section_of;

namespace {

constexpr double mm = 1e-3;
constexpr double kRoundoff = 1e-14;

struct NamedSection {
    std::string name;
    Section section;
};

Section with_reference(Section s, Point reference) {
    s.reference = reference;
    return s;
}

// Flange 100 x 10 on web 10 x 200 (mm), base at z = 0.
const Ring kTee = {{-5 * mm, 0}, {5 * mm, 0}, {5 * mm, 200 * mm}, {50 * mm, 200 * mm},
                   {50 * mm, 210 * mm}, {-50 * mm, 210 * mm}, {-50 * mm, 200 * mm}, {-5 * mm, 200 * mm}};

ValidSection tee_section() { return validate_section(section_of({part(kTee, 235e6)})); }

// Every example file, and the hand-checked sections of the core's tests.
std::vector<NamedSection> core_sections() {
    std::vector<NamedSection> cases;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(PLASCAP_SOURCE_DIR) + "/sections/examples"))
        cases.push_back({entry.path().stem().string(), read_section_file(entry.path().string())});
    // Flange area = web area: the equal-force axis lies on the flange-web junction (the kink case).
    const Ring tee_on_junction = {{-10 * mm, 0}, {10 * mm, 0}, {10 * mm, 100 * mm}, {50 * mm, 100 * mm},
                                  {50 * mm, 120 * mm}, {-50 * mm, 120 * mm}, {-50 * mm, 100 * mm}, {-10 * mm, 100 * mm}};
    const Ring angle = {{0, 0}, {100 * mm, 0}, {100 * mm, 10 * mm}, {10 * mm, 10 * mm}, {10 * mm, 100 * mm}, {0, 100 * mm}};
    cases.push_back({"tee", section_of({part(kTee, 235e6)})});
    cases.push_back({"tee-axis-on-junction", section_of({part(tee_on_junction, 355e6)})});
    cases.push_back({"equal-angle", section_of({part(angle, 275e6)}, ShearCriterion::VonMises)});
    cases.push_back({"hollow-rectangle", section_of({part(box(-0.1, -0.05, 0.1, 0.05), 355e6, {box(-0.09, -0.04, 0.09, 0.04)})})});
    cases.push_back({"two-flanges-gap", section_of({part(box(-0.1, -0.14, 0.1, -0.12), 355e6), part(box(-0.1, 0.12, 0.1, 0.14), 355e6)})});
    cases.push_back({"two-materials", section_of({part(box(0, 0, 0.1, 0.1), 470e6), part(box(0, 0.1, 0.1, 0.2), 235e6)})});
    cases.push_back({"diamond", section_of({part({{0.1, 0}, {0, 0.15}, {-0.1, 0}, {0, -0.15}}, 235e6)})});
    cases.push_back({"hexagon", section_of({part(regular_polygon_ring(6, 0.05), 235e6)})});
    cases.push_back({"256-gon", section_of({part(regular_polygon_ring(256, 0.05, 0.3), 235e6)})});
    cases.push_back({"square-joint-at-corner",
                     with_reference(section_of({part(box(-0.005, -0.005, 0.005, 0.005), 200e6)}), {0.005, 0.005})});
    cases.push_back({"square-joint-outside",
                     with_reference(section_of({part(box(-0.005, -0.005, 0.005, 0.005), 200e6)}), {0.02, -0.01})});
    return cases;
}

// The cubature result agrees with the exact route to `allowed` (relative), and each error
// estimate bounds the actual error.
void expect_agrees(const std::string& name, const ValidSection& section, const CubatureOptions& options, double allowed) {
    const Capacities exact = compute_capacities(section);
    const CubatureResult cubature = cubature_capacities(section, CapacitySet::all(), options);
    for (Capacity c : kAllCapacities) {
        const double reference = *exact.get(c);
        const double error = std::abs(*cubature.capacities.get(c) - reference);
        EXPECT_LE(error, (allowed + kRoundoff) * std::abs(reference)) << name << " " << to_string(c);
        EXPECT_LE(error, *cubature.estimated_error(c) + kRoundoff * std::abs(reference))
            << name << " " << to_string(c) << ": the estimate " << *cubature.estimated_error(c)
            << " is below the actual error " << error;
    }
    EXPECT_NEAR(*cubature.capacities.z_pna, *exact.z_pna, 1e-12) << name;
    EXPECT_NEAR(*cubature.capacities.x_pna, *exact.x_pna, 1e-12) << name;
    EXPECT_GT(cubature.triangles, 0u);
}

class AdaptiveAgreesWithExact : public ::testing::TestWithParam<double> {};

TEST_P(AdaptiveAgreesWithExact, OnEveryCoreSection) {
    CubatureOptions options;
    options.tolerance = GetParam();
    for (const NamedSection& s : core_sections()) expect_agrees(s.name, validate_section(s.section), options, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Tolerances, AdaptiveAgreesWithExact, ::testing::Values(1e-4, 1e-7, 1e-10));

// The paper's Fig. 2.6 value: My = 38.2597858232 N·m (paper 38.2), to the requested 1e-10.
TEST(CubatureRoute, PaperSquareTorsion) {
    const ValidSection square = validate_section(read_section_file(std::string(PLASCAP_SOURCE_DIR) + "/sections/examples/paper-square.json"));
    const CubatureResult r = cubature_capacities(square, CapacitySet().insert(Capacity::My));
    EXPECT_NEAR(*r.capacities.My, 38.259785823210635, 38.26 * 1e-10);
    // The estimate adds the outer and the largest inner estimate, each up to the tolerance.
    EXPECT_LE(*r.estimated_error(Capacity::My), 2 * 38.26 * 1e-10);
    EXPECT_FALSE(r.capacities.N || r.capacities.Mx || r.capacities.Mz);  // only what was asked for
}

// The fixed Gauss–Legendre rule on a refined mesh: the estimate stays honest, and halving the
// triangle area reduces the My error (the only integrand that is not a polynomial per triangle).
TEST(CubatureRoute, FixedRuleIsHonestAndConvergesWithTheMesh) {
    for (const NamedSection& s : core_sections()) {
        const ValidSection section = validate_section(s.section);
        CubatureOptions options;
        options.rule = CubatureRule::Fixed;
        options.order = 3;
        options.max_area = compute_capacities(section).area / 50.0;
        expect_agrees(s.name, section, options, 1e-2);
    }
    const ValidSection tee = tee_section();
    double previous = 1.0;
    for (double area : {1e-4, 1e-5, 1e-6}) {
        CubatureOptions options;
        options.rule = CubatureRule::Fixed;
        options.order = 2;
        options.max_area = area;
        const double exact = *compute_capacities(tee).My;
        const double error = std::abs(*cubature_capacities(tee, CapacitySet::all(), options).capacities.My - exact) / exact;
        EXPECT_LT(error, previous) << "max area " << area;
        previous = error;
    }
}

// Random star polygons, some with several parts and snapped vertices (axes through vertices).
TEST(CubatureRoute, RandomPolygonsAgreeWithExact) {
    std::mt19937 rng(20261124);
    int tested = 0;
    for (int trial = 0; trial < 60; ++trial) {
        std::vector<Part> parts;
        const int count = 1 + trial % 3;
        for (int k = 0; k < count; ++k)
            parts.push_back(part(test::random_star(rng, {3.0 * k, 0.5 * k}, 1.0, trial % 2 == 0), 100e6 * (1 + k)));
        std::optional<ValidSection> section;
        try {
            section = validate_section(section_of(parts));
        } catch (const InputError&) {
            continue;  // snapping to the grid can make a star self-intersect
        }
        CubatureOptions options;
        options.tolerance = 1e-9;
        expect_agrees("random star " + std::to_string(trial), *section, options, 1e-9);
        ++tested;
    }
    EXPECT_GE(tested, 40);
}

// What the conforming mesh is worth: with neutral-axis edges, Mx and Mz of the equal angle (axes
// 9.5 mm into its 10 mm legs) are exact to round-off at order 4; a mesh that ignores the kinks
// leaves errors above 1e-6.
TEST(CubatureRoute, ConformingMeshRemovesTheKinkError) {
    const Ring angle = {{0, 0}, {100 * mm, 0}, {100 * mm, 10 * mm}, {10 * mm, 10 * mm}, {10 * mm, 100 * mm}, {0, 100 * mm}};
    const ValidSection section = validate_section(section_of({part(angle, 275e6)}));
    const Capacities exact = compute_capacities(section);
    CubatureOptions options;
    options.rule = CubatureRule::Fixed;
    options.order = 4;
    const CubatureResult conforming = cubature_capacities(section, CapacitySet::all(), options);
    options.conforming = false;
    const CubatureResult ignoring = cubature_capacities(section, CapacitySet::all(), options);
    EXPECT_LT(test::relative_error(*conforming.capacities.Mx, *exact.Mx), 1e-13);
    EXPECT_LT(test::relative_error(*conforming.capacities.Mz, *exact.Mz), 1e-13);
    EXPECT_GT(test::relative_error(*ignoring.capacities.Mx, *exact.Mx), 1e-6);
    EXPECT_GT(test::relative_error(*ignoring.capacities.Mz, *exact.Mz), 1e-6);
}

// Extreme shapes, sizes and places: no hang, no accuracy lost beyond what the estimate says.
TEST(CubatureExtremes, StripOneToTenThousand) {
    CubatureOptions options;
    expect_agrees("1 m x 0.1 mm strip", validate_section(section_of({part(box(-0.5, -5e-5, 0.5, 5e-5), 235e6)})), options, 1e-10);
}

TEST(CubatureExtremes, TinyAndHugeSections) {
    const Ring tee = {{-1, 0}, {1, 0}, {1, 40}, {10, 40}, {10, 42}, {-10, 42}, {-10, 40}, {-1, 40}};
    for (double scale : {1e-5 / 42, 1e2 / 42}) {
        Ring scaled;
        for (Point p : tee) scaled.push_back({p.x * scale, p.z * scale});
        CubatureOptions options;
        expect_agrees("tee " + std::to_string(scale * 42) + " m tall", validate_section(section_of({part(scaled, 355e6)})), options, 1e-10);
    }
}

TEST(CubatureExtremes, TenThousandMetresFromTheOrigin) {
    Ring far;
    for (Point p : kTee) far.push_back({p.x + 1e4, p.z - 1e4});
    CubatureOptions options;
    const ValidSection moved = validate_section(section_of({part(far, 235e6)}));
    expect_agrees("tee at (1e4, -1e4) m", moved, options, 1e-10);
    const CubatureResult here = cubature_capacities(tee_section());
    const CubatureResult there = cubature_capacities(moved);
    for (Capacity c : kAllCapacities)
        EXPECT_LT(test::relative_error(*there.capacities.get(c), *here.capacities.get(c)), 1e-9) << to_string(c);
}

TEST(CubatureExtremes, HundredThousandVertexPolygon) {
    const ValidSection circle = validate_section(section_of({part(regular_polygon_ring(100000, 0.1, 0.1), 235e6)}));
    CubatureOptions options;
    options.tolerance = 1e-8;
    expect_agrees("100000-gon", circle, options, 1e-8);
}

// A star with a 2.6e-10 m edge at a sharp angle, found by a random sweep: Delaunay refinement for
// shape kept splitting there (1.8 GB in 45 s). The vertex budget stops it; the route finishes, says
// so, and its estimates still hold here.
TEST(CubatureExtremes, RefinementBudgetStopsRunawayMeshing) {
    const Ring star = {{0.375, 0}, {0.37499999987500005, 2.25e-10}, {0.25, 0.125}, {0.5, 0.125}, {0.375, 0.25},
                       {0.375, 0.5}, {0.25, 0.25}, {0.25, 0.375}, {0.125, 0.625}, {0, 0.375}, {0, 0.875},
                       {-0.125, 0.375}, {-0.25, 0.625}, {-0.375, 0.5}, {-0.375, 0.375}, {-0.5, 0.375},
                       {-0.375, 0.25}, {-0.25, 0.125}, {-0.875, 0.25}, {-0.5, 0}, {-0.625, 0}, {-0.5, -0.125},
                       {-0.875, -0.375}, {-0.625, -0.375}, {-0.5, -0.375}, {-0.5, -0.5}, {-0.5, -0.75},
                       {-0.375, -0.875}, {-0.125, -0.5}, {-0.125, -0.75}, {0, -1}, {0, -0.5}, {0.125, -0.375},
                       {0.25, -0.5}, {0.625, -0.75}, {0.625, -0.625}, {0.375, -0.25}, {0.75, -0.5},
                       {0.375, -0.125}, {0.5, -0.125}, {0.75, -0.125}};
    const ValidSection section = validate_section(section_of({part(star, 1e8)}));
    CubatureOptions options;
    options.rule = CubatureRule::Fixed;
    options.order = 3;
    const CubatureResult result = cubature_capacities(section, CapacitySet::all(), options);
    EXPECT_TRUE(result.refinement_stopped);
    EXPECT_LT(result.triangles, 100000u);
    expect_agrees("star with a 2.6e-10 m edge", section, options, 1e-3);
    options.rule = CubatureRule::Adaptive;  // no refinement asked: nothing to stop
    EXPECT_FALSE(cubature_capacities(section, CapacitySet::all(), options).refinement_stopped);
}

TEST(CubatureOptionsCheck, OutOfRangeOptionsAreRefusedByName) {
    const ValidSection square = validate_section(section_of({part(box(0, 0, 1, 1), 235e6)}));
    const auto message = [&](CubatureOptions o) {
        try {
            cubature_capacities(square, CapacitySet::all(), o);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CubatureOptions o;
    o.tolerance = 0.0;
    EXPECT_NE(message(o).find("tolerance"), std::string::npos) << message(o);
    o = {};
    o.tolerance = std::nan("");
    EXPECT_NE(message(o).find("tolerance"), std::string::npos) << message(o);
    o = {};
    o.order = 0;
    EXPECT_NE(message(o).find("order"), std::string::npos) << message(o);
    o = {};
    o.max_area = -1.0;
    EXPECT_NE(message(o).find("area"), std::string::npos) << message(o);
    o = {};
    o.max_area = 1e-14;  // 1e14 triangles
    EXPECT_NE(message(o).find("triangles"), std::string::npos) << message(o);
}

}  // namespace
