// Sections of several materials, and materials with different tension and compression strengths:
// both routes against hand calculations (plastic equal-force axis, stress blocks).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/cubature.hpp"
#include "plascap/sections/section_json.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;
using plascap::test::relative_error;
using plascap::test::section_of;

namespace {

constexpr double mm = 1e-3;

Part part_of(Ring ring, const Material& material) { return Part{std::move(ring), {}, material}; }

const Material& grade(const char* name) { return MaterialCatalogue::built_in().get(name, "test"); }

// Both routes give `reference` for capacity k: the exact one to 1e-12, the cubature one within its
// estimate and 1e-9.
void expect_both_routes(const ValidSection& s, Capacity k, double reference) {
    const Capacities exact = compute_capacities(s);
    EXPECT_LT(relative_error(*exact.get(k), reference), 1e-12) << to_string(k) << " exact " << *exact.get(k);
    CubatureOptions options;
    options.tolerance = 1e-10;
    const CubatureResult cubature = cubature_capacities(s, CapacitySet::all(), options);
    const double error = std::abs(*cubature.capacities.get(k) - reference);
    EXPECT_LT(error, 1e-9 * reference + 1e-300) << to_string(k) << " cubature " << *cubature.capacities.get(k);
    EXPECT_LE(error, *cubature.estimated_error(k) + 1e-14 * reference) << to_string(k);
}

}  // namespace

// C24 timber b × h = 100 × 200 mm: ft = 14.5, fc = 21 MPa (EN 338). With the tension zone below,
// ft·b·d_t = fc·b·d_c and d_t + d_c = h, so d_t = h·fc/(ft + fc); the stress blocks give
// M = b·(ft·d_t² + fc·d_c²)/2. A rectangle is its own mirror image: Mx_neg = Mx.
TEST(CompositeSections, TimberRectangleStressBlocks) {
    const double b = 0.1, h = 0.2, ft = 14.5e6, fc = 21e6;
    const ValidSection s = validate_section(section_of({part_of(box(-b / 2, -h / 2, b / 2, h / 2), grade("C24"))}));
    const double d_t = h * fc / (ft + fc), d_c = h * ft / (ft + fc);
    const double moment = b * (ft * d_t * d_t + fc * d_c * d_c) / 2.0;
    const Capacities c = compute_capacities(s);
    EXPECT_NEAR(*c.z_pna, -h / 2 + d_t, 1e-15);
    EXPECT_NEAR(*c.z_pna_neg, h / 2 - d_t, 1e-15);
    expect_both_routes(s, Capacity::Mx, moment);
    expect_both_routes(s, Capacity::Mx_neg, moment);
    const double moment_z = h * (ft * std::pow(b * fc / (ft + fc), 2) + fc * std::pow(b * ft / (ft + fc), 2)) / 2.0;
    expect_both_routes(s, Capacity::Mz, moment_z);
    expect_both_routes(s, Capacity::Mz_neg, moment_z);
    expect_both_routes(s, Capacity::N, ft * b * h);
    expect_both_routes(s, Capacity::N_neg, fc * b * h);
}

// The T of the core tests (web 10 × 200, flange 100 × 10 mm on top) in C24. Tension below:
// 14.5·a = 21·(3000 − a) → a = 1774.65 mm² of web, axis 177.465 mm up. Tension above:
// 21·a = 14.5·(3000 − a) → axis 122.535 mm up. Moments from the stress blocks about each axis.
TEST(CompositeSections, TimberTeeDiffersBySign) {
    const Ring tee = {{-5 * mm, 0}, {5 * mm, 0}, {5 * mm, 200 * mm}, {50 * mm, 200 * mm},
                      {50 * mm, 210 * mm}, {-50 * mm, 210 * mm}, {-50 * mm, 200 * mm}, {-5 * mm, 200 * mm}};
    const ValidSection s = validate_section(section_of({part_of(tee, grade("C24"))}));
    const double ft = 14.5e6, fc = 21e6, w = 10 * mm;
    const double t = 3000e-6 * fc / (ft + fc) / w;  // tension below: web depth in tension
    const double mx = ft * w * t * t / 2 + fc * (w * (200 * mm - t) * (200 * mm - t) / 2 + 1000e-6 * (205 * mm - t));
    const double u = 3000e-6 * ft / (ft + fc) / w;  // tension above: web depth in compression
    const double mx_neg = fc * w * u * u / 2 + ft * (w * (200 * mm - u) * (200 * mm - u) / 2 + 1000e-6 * (205 * mm - u));
    const Capacities c = compute_capacities(s);
    EXPECT_NEAR(*c.z_pna, t, 1e-15);
    EXPECT_NEAR(*c.z_pna_neg, u, 1e-15);
    expect_both_routes(s, Capacity::Mx, mx);
    expect_both_routes(s, Capacity::Mx_neg, mx_neg);
    EXPECT_GT(mx_neg, 1.09 * mx);  // the strong side is worth 10 %
}

// Plain concrete has no tensile strength: no tension, no bending; its compression is fc·A.
TEST(CompositeSections, PlainConcreteCarriesOnlyCompression) {
    const ValidSection s = validate_section(section_of({part_of(box(-0.5, -0.5, 0.5, 0.5), grade("C25/30"))}));
    const Capacities c = compute_capacities(s);
    EXPECT_EQ(*c.N, 0.0);
    EXPECT_EQ(*c.N_neg, 25e6);
    EXPECT_EQ(*c.Mx, 0.0);
    EXPECT_EQ(*c.Mx_neg, 0.0);
    const CubatureResult r = cubature_capacities(s);
    EXPECT_EQ(*r.capacities.N, 0.0);
    EXPECT_NEAR(*r.capacities.N_neg, 25e6, 1e-14 * 25e6);
    EXPECT_LT(*r.capacities.Mx, 1e-9 * 25e6);
}

// Steel–aluminium bimaterial plate, 100 mm wide: S355 10 mm below, EN-AW-6061-T6 10 mm on top.
// Forces 355 kN and 240 kN; half of 595 kN lies below z = 297.5/355·10 mm, inside the steel.
// Mx = fy_s·b·(t² + (h_s − t)²)/2 + fy_a·b·h_a·(h_s + h_a/2 − t).
TEST(CompositeSections, SteelAluminiumPlate) {
    const double b = 0.1, h = 0.01, fs = 355e6, fa = 240e6;
    const ValidSection s = validate_section(section_of(
        {part_of(box(-b / 2, 0, b / 2, h), grade("S355")), part_of(box(-b / 2, h, b / 2, 2 * h), grade("EN-AW-6061-T6"))}));
    const double t = 0.5 * (fs + fa) * b * h / (fs * b);
    const double mx = fs * b * (t * t + (h - t) * (h - t)) / 2 + fa * b * h * (h + h / 2 - t);
    EXPECT_NEAR(*compute_capacities(s).z_pna, t, 1e-16);
    expect_both_routes(s, Capacity::Mx, mx);
    expect_both_routes(s, Capacity::Mx_neg, mx);  // fc = fy in both: the same
    expect_both_routes(s, Capacity::Mz, (fs + fa) * h * b * b / 4);
}

// Random star sections with fc ≠ fy: the two routes agree on every capacity within the estimate.
TEST(CompositeSections, RoutesAgreeWithDifferentStrengths) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> strength(50e6, 500e6);
    int tested = 0;
    for (int trial = 0; trial < 30; ++trial) {
        std::vector<Part> parts;
        for (int k = 0; k < 1 + trial % 3; ++k) {
            Material m{"", strength(rng)};
            m.fc = trial % 5 == 0 ? 0.0 : strength(rng);  // some without compression strength
            parts.push_back(part_of(test::random_star(rng, {3.0 * k, 0.4 * k}, 1.0, false), m));
        }
        const ValidSection s = validate_section(section_of(parts));
        const Capacities exact = compute_capacities(s);
        CubatureOptions options;
        options.tolerance = 1e-9;
        const CubatureResult r = cubature_capacities(s, CapacitySet::all(), options);
        // A capacity that is 0 (no compression strength) is round-off in both routes: measure
        // against the section's force times its size (about 1 m) there.
        const double floor = 1e-14 * (*exact.N + *exact.N_neg);
        for (Capacity k : kAllCapacities) {
            const double reference = *exact.get(k), error = std::abs(*r.capacities.get(k) - reference);
            EXPECT_LE(error, 1e-9 * reference + floor) << trial << " " << to_string(k);
            EXPECT_LE(error, *r.estimated_error(k) + 1e-14 * reference + floor) << trial << " " << to_string(k);
        }
        ++tested;
    }
    EXPECT_EQ(tested, 30);
}

// A C25/30 beam 300 × 500 mm with three 314 mm² B500B bars 50 mm above the bottom (rc-beam.json).
// Sagging: bars 3·314e-6·500 MPa = 471 kN against a concrete block x = 471 kN/(25 MPa·0.3 m) deep,
// Mx = 471 kN·(0.45 m − x/2). Hogging: concrete has no tension, so the axis sits on the bars, which
// carry what the concrete below them (0.3 × 0.05 m at 25 MPa = 375 kN) needs: Mx_neg = 375 kN·0.025 m.
// The bars displace concrete: N_neg = 25 MPa·(0.15 m² − 3·314e-6) + 471 kN.
TEST(CompositeSections, ReinforcedConcreteBeamWithBars) {
    const ValidSection s = validate_section(read_section_file(std::string(PLASCAP_SOURCE_DIR) + "/sections/examples/rc-beam.json"));
    const double steel = 3 * 314e-6, tension = steel * 500e6, x = tension / (25e6 * 0.3);
    expect_both_routes(s, Capacity::Mx, tension * (0.45 - x / 2));
    expect_both_routes(s, Capacity::Mx_neg, 25e6 * 0.3 * 0.05 * 0.025);
    expect_both_routes(s, Capacity::N, tension);
    expect_both_routes(s, Capacity::N_neg, 25e6 * (0.15 - steel) + tension);
    const Capacities c = compute_capacities(s);
    EXPECT_NEAR(*c.z_pna, 0.25 - x, 1e-15);
    EXPECT_EQ(*c.z_pna_neg, -0.2);  // on the bars' level: the force steps there
}

// The paper's column (Section 3; docs/references.md): 1 m² of concrete with 0.04 % steel
// of fy = 200 MPa carries 80 kN in tension; at dt = 1/60 s a joint row may pass 80 kN/60 = 1333 N·s
// per step (the paper rounds to 1330).
TEST(CompositeSections, PaperColumn) {
    const ValidSection s = validate_section(read_section_file(std::string(PLASCAP_SOURCE_DIR) + "/sections/examples/paper-column.json"));
    expect_both_routes(s, Capacity::N, 80e3);
    const double impulse = *compute_capacities(s).N / 60.0;
    EXPECT_NEAR(impulse, 1333.3333, 1e-3);
    EXPECT_NEAR(impulse, 1330.0, 0.003 * 1330.0);
    EXPECT_EQ(s.parts()[0].material.name, "C25/30 + 0.04 % paper-steel");
    EXPECT_EQ(*s.parts()[0].material.density, 0.9996 * 2400 + 0.0004 * 7800);
}

// The shear criterion: the file's if given, else the one all materials name (steels: von Mises,
// EN 1993-1-1 6.2.6), else Tresca (the paper's).
TEST(CompositeSections, ShearCriterionFromTheMaterials) {
    const auto criterion = [](const char* json) { return validate_section(parse_section_json(json)).shear(); };
    EXPECT_EQ(criterion(R"({"material": "S355", "parts": [{"outer": [[0, 0], [1, 0], [1, 1]]}]})"), ShearCriterion::VonMises);
    EXPECT_EQ(criterion(R"({"shear": "tresca", "material": "S355", "parts": [{"outer": [[0, 0], [1, 0], [1, 1]]}]})"),
              ShearCriterion::Tresca);
    EXPECT_EQ(criterion(R"({"material": "S355", "parts": [{"outer": [[0, 0], [1, 0], [1, 1]]},
                                                          {"outer": [[2, 0], [3, 0], [3, 1]], "material": "C24"}]})"),
              ShearCriterion::Tresca);
    EXPECT_EQ(criterion(R"({"material": {"fy": 1e8}, "parts": [{"outer": [[0, 0], [1, 0], [1, 1]]}]})"), ShearCriterion::Tresca);
}

// A steel I (S355: flanges 150 × 10, web 10 × 280 mm, depth 300) under a GL24h slab 600 × 100 mm.
// Either way the slab alone is weaker than the steel, so it works whole (compression fc = 24 MPa
// sagging, tension ft = 19.2 MPa hogging) and the axis falls into the top flange where the steel
// balances: 355·(A_below − A_above) = F_slab, A_below + A_above = 5800 mm². Moments from the blocks.
TEST(CompositeSections, SteelBeamUnderTimberSlab) {
    const Ring i_beam = {{-75 * mm, 0}, {75 * mm, 0}, {75 * mm, 10 * mm}, {5 * mm, 10 * mm}, {5 * mm, 290 * mm},
                         {75 * mm, 290 * mm}, {75 * mm, 300 * mm}, {-75 * mm, 300 * mm}, {-75 * mm, 290 * mm},
                         {-5 * mm, 290 * mm}, {-5 * mm, 10 * mm}, {-75 * mm, 10 * mm}};
    const ValidSection s = validate_section(section_of(
        {part_of(i_beam, grade("S355")), part_of(box(-300 * mm, 300 * mm, 300 * mm, 400 * mm), grade("GL24h"))}));
    const double fs = 355e6, steel = 5800e-6;
    const auto moment = [&](double slab_strength, double& depth) {
        const double slab = slab_strength * 0.06;                 // whole slab [N]
        const double above = 0.5 * (steel - slab / fs);           // steel area above the axis [m²]
        depth = above / 0.15;                                     // into the top flange
        const double d = depth, rest = 10 * mm - d;
        return slab * (d + 50 * mm) + fs * (0.15 * d * d / 2 + 0.15 * rest * rest / 2 + 2800e-6 * (rest + 140 * mm) +
                                            1500e-6 * (rest + 285 * mm));
    };
    double sag_depth = 0.0, hog_depth = 0.0;
    const double mx = moment(24e6, sag_depth), mx_neg = moment(19.2e6, hog_depth);
    ASSERT_LT(sag_depth, 10 * mm);  // the premise: the axis is in the flange
    ASSERT_LT(hog_depth, 10 * mm);
    const Capacities c = compute_capacities(s);
    EXPECT_NEAR(*c.z_pna, 300 * mm - sag_depth, 1e-15);
    EXPECT_NEAR(*c.z_pna_neg, 300 * mm - hog_depth, 1e-15);
    expect_both_routes(s, Capacity::Mx, mx);
    expect_both_routes(s, Capacity::Mx_neg, mx_neg);
}
