// Joints that yield on a section's coupled surface (docs/yield-surface.md), on every engine and
// both Bullet constraints: a rigid-plastic joint under a static load at 0.95 and 1.05 of the onset
// the exact condition gives holds and yields; the box of independent limits yields only at its own
// limit; the energy ledger balances. Scenes are written as a user writes them (plastic-sim JSON).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "coupled_scenes.hpp"
#include "engine_test_names.hpp"

namespace plascap::test {
namespace {

using namespace plascap::coupled;

class CoupledJoint : public ::testing::TestWithParam<std::string> {};

constexpr double kHolds = 1e-3;  // [rad or m] accumulated over 2 s

TEST_P(CoupledJoint, HoldsBelowAndYieldsAboveTheExactOnset) {
    for (const Case& c : {axial_and_bending(), diagonal_bending(), pure_torsion()}) {
        const double m = onset_mass(c);
        const SceneRun below = run_scene(GetParam(), scene_json(c, 0.95 * m, R"(, "max_plastic_rotation": 0.2, "max_plastic_displacement": 0.2)", 2.0));
        const SceneRun above = run_scene(GetParam(), scene_json(c, 1.05 * m, R"(, "max_plastic_rotation": 0.2, "max_plastic_displacement": 0.2)", 2.0));
        EXPECT_LT(below.plastic, kHolds) << c.name << " at 0.95 of the onset (" << 0.95 * m << " kg)";
        EXPECT_FALSE(below.broken) << c.name;
        EXPECT_GT(above.plastic, 0.01) << c.name << " at 1.05 of the onset (" << 1.05 * m << " kg)";
        EXPECT_TRUE(above.broken) << c.name;
        // Sharper than the issue asks: within 1 % of the onset.
        const SceneRun near_below = run_scene(GetParam(), scene_json(c, 0.99 * m, "", 2.0));
        const SceneRun near_above = run_scene(GetParam(), scene_json(c, 1.01 * m, "", 2.0));
        EXPECT_LT(near_below.plastic, kHolds) << c.name << " at 0.99 of the onset";
        EXPECT_GT(near_above.plastic, 0.01) << c.name << " at 1.01 of the onset";
        std::printf("%s %s: onset %.4f kg; plastic over 2 s: %.1e at 0.99, %.2f at 1.01\n", GetParam().c_str(),
                    c.name.c_str(), m, near_below.plastic, near_above.plastic);
    }
}

// The box of independent limits: at 1.05 of the coupled onset the axial-and-bending joint holds
// (N at 0.53 Np, Mz at 0.79 Mzp, each inside its own limit), and it yields only past its Mz limit.
TEST_P(CoupledJoint, TheBoxYieldsOnlyAtItsOwnLimit) {
    const Case c = axial_and_bending();
    const double m = onset_mass(c), box_limit = 100.0 / (kG * 0.075);  // Mzp = 100 N·m
    const std::string box = R"(, "yield_surface": "box", "max_plastic_rotation": 0.2, "max_plastic_displacement": 0.2)";
    EXPECT_LT(run_scene(GetParam(), scene_json(c, 1.05 * m, box, 2.0)).plastic, kHolds);
    EXPECT_LT(run_scene(GetParam(), scene_json(c, 0.95 * box_limit, box, 2.0)).plastic, kHolds);
    EXPECT_GT(run_scene(GetParam(), scene_json(c, 1.05 * box_limit, box, 2.0)).plastic, 0.01);
}

// KE + PE + elastic + dissipated stays within 1 % of the energy handled (the largest change of PE),
// rigid-plastic and elastic-plastic (stiffness from a 0.5 m segment), through yielding and flow.
TEST_P(CoupledJoint, EnergyBalances) {
    for (const Case& c : {axial_and_bending(), diagonal_bending()}) {
        const double m = onset_mass(c);
        for (const std::string& stiffness : {std::string(), std::string(R"(, "length": 0.5)")}) {
            const SceneRun r = run_scene(GetParam(), scene_json(c, 1.05 * m, stiffness, 1.0));
            EXPECT_GT(r.plastic, 0.01) << c.name << stiffness;
            EXPECT_LT(r.worst_ledger, 0.01 * r.handled) << c.name << stiffness << ": handled " << r.handled << " J";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(PlasticJoints, CoupledJoint, ::testing::ValuesIn(available_engines()), engine_test_name);

}  // namespace
}  // namespace plascap::test
