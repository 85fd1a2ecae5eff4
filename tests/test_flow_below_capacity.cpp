// Issue 20: a rigid-plastic joint must not creep under a load below its capacity, however the
// engine's iterative solver leaves its rows (flow_criterion.hpp). A compact 960 kg block (0.2 m cube)
// hangs 1 m from its anchor on a joint with Mx and Mz rigid-plastic (capacities C each, no
// stiffness) and every other dof rigid; the joint's x axis is turned by 0°, 22.5° or 45° about the
// block's axis, so gravity loads one row or both. The larger row load is a share of C; rigid-plastic
// theory: below 1 the joint holds (no plastic rotation), above it the block accelerates and the
// joint breaks at its limit. Run as a user runs it (plastic-sim JSON), dt = 1/240 s, 2.5 s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "engine_test_names.hpp"
#include "scene.hpp"
#include "scene_engine.hpp"
#include "simulation.hpp"

namespace plascap {
namespace {

constexpr double kMass = 960.0, kG = 9.81, kLever = 1.0;  // [kg, m/s², m]
constexpr double kHolds = 1e-3;                          // [rad] accumulated over 2.5 s (the issue)

struct Outcome {
    double plastic_rotation = 0.0;  // [rad]
    bool broken = false;
    double sag = 0.0;               // how far the block's centre has dropped at the end [m]
};

// `share`: the larger row's static load over its capacity; `rigid`: every dof locked instead (the
// engine's own joint, for the sag a locked joint shows in the same place).
std::string scene_json(double share, double turn_deg, int iterations, bool rigid = false) {
    const double turn = turn_deg * M_PI / 180.0;
    const double moment = kMass * kG * kLever;
    const double capacity = moment * std::max(std::cos(turn), std::sin(turn)) / share;
    const std::string plastic = rigid ? "rigid" : "plastic";
    char json[1400];
    std::snprintf(json, sizeof json,
                  R"({"dt": %.17g, "duration": 2.5, "iterations": %d, "gravity": [0, %.17g, 0],
      "bodies": [{"name": "block", "box": [0.2, 0.2, 0.2], "mass": %.17g, "position": [%.17g, 0, 0]}],
      "joints": [{"name": "root", "a": "world", "b": "block", "anchor": [0, 0, 0], "axis": [1, 0, 0],
                  "x_axis": [0, %.17g, %.17g], "capacities": {"Mx": %.17g, "Mz": %.17g},
                  "dofs": {"N": "rigid", "Qx": "rigid", "Qz": "rigid", "Mx": "%s", "My": "rigid", "Mz": "%s"},
                  "max_plastic_rotation": 0.5}]})",
                  1.0 / 240, iterations, -kG, kMass, kLever, std::cos(turn), std::sin(turn), capacity, capacity,
                  plastic.c_str(), plastic.c_str());
    return json;
}

Outcome run(const std::string& engine, const std::string& json) {
    const Scene scene = parse_scene_json(json);
    const std::unique_ptr<SceneEngine> e = make_engine(engine, scene);
    const SimulationResult r = run_simulation(scene, *e, {});
    return {r.joints.at(0).plastic_rotation, r.joints.at(0).broken_at.has_value(), -r.bodies.at(0).position[1]};
}

// The fewest iterations at which each engine holds every case (docs/adapters.md has the sweep):
// plascap's Bullet constraint with its warm-starting solver 30, ODE's QuickStep 50, Bullet's 6-dof
// springs driven from outside (cold rows, Euler motors) 100; ODE's direct dWorldStep at any count.
int fewest_iterations_that_hold(const std::string& engine) {
    if (engine == "bullet") return 30;
    if (engine == "ode") return 50;
    if (engine == "ode-step") return 10;
    return 100;  // bullet-spring2, bullet-6dof-spring
}

class FlowBelowCapacity : public ::testing::TestWithParam<std::string> {};

TEST_P(FlowBelowCapacity, HoldsBelowCapacityAndBreaksAbove) {
    const std::string engine = GetParam();
    const int fewest = fewest_iterations_that_hold(engine);
    for (int iterations : {fewest, std::max(fewest, 50)}) {
        for (double turn : {0.0, 22.5, 45.0}) {
            // The sag the engine's own locked rows show here, and the joint's own at half its
            // capacity, where no row reaches its bound: the plastic joint may sag as much (its rows
            // are as unconverged), in proportion to its load, but no more, or it let load through
            // unbooked.
            const Outcome locked = run(engine, scene_json(0.9, turn, iterations, true));
            const Outcome half = run(engine, scene_json(0.5, turn, iterations));
            for (double share : {0.5, 0.8, 0.9, 0.95}) {
                const Outcome r = run(engine, scene_json(share, turn, iterations));
                const std::string where = engine + ", " + std::to_string(iterations) + " iterations, x axis turned " +
                                          std::to_string(turn) + " deg, load " + std::to_string(share) + " C";
                EXPECT_LT(r.plastic_rotation, kHolds) << where;
                EXPECT_FALSE(r.broken) << where;
                const double slack = std::max(locked.sag, half.sag * share / 0.5);
                EXPECT_LT(r.sag, 1.5 * slack + 1e-4) << where << ": locked rows sag " << locked.sag << " m, the joint at 0.5 C " << half.sag << " m";
            }
            const Outcome above = run(engine, scene_json(1.05, turn, iterations));
            EXPECT_TRUE(above.broken) << engine << ", " << iterations << " it, " << turn << " deg, 1.05 C: "
                                      << above.plastic_rotation << " rad";
        }
    }
}

// The same block on a joint built from a section, whose Mx and Mz yield together on its exact
// surface (docs/yield-surface.md): a 0.1 m square bent about its diagonal (x axis turned 45°) first
// yields at M = a³·fy/(3√2) (the plastic moment about a square's diagonal; the shear m·g through
// the rigid rows lowers it by under 0.3 %), so fy = 3√2·m·g·L/(a³·share).
std::string coupled_json(double share, int iterations) {
    const double a = 0.1, fy = 3 * std::sqrt(2.0) * kMass * kG * kLever / (a * a * a * share);
    char json[1400];
    std::snprintf(json, sizeof json,
                  R"({"dt": %.17g, "duration": 2.5, "iterations": %d, "gravity": [0, %.17g, 0],
      "bodies": [{"name": "block", "box": [0.2, 0.2, 0.2], "mass": %.17g, "position": [%.17g, 0, 0]}],
      "joints": [{"name": "root", "a": "world", "b": "block", "anchor": [0, 0, 0], "axis": [1, 0, 0],
                  "x_axis": [0, 0.7071067811865476, 0.7071067811865476],
                  "section": {"parts": [{"outer": [[-0.05, -0.05], [0.05, -0.05], [0.05, 0.05], [-0.05, 0.05]]}]},
                  "material": {"fy": %.17g, "E": 2e11, "nu": 0.3, "density": 7850},
                  "dofs": {"N": "rigid", "Qx": "rigid", "Qz": "rigid", "Mx": "plastic", "My": "rigid", "Mz": "plastic"},
                  "max_plastic_rotation": 0.5}]})",
                  1.0 / 240, iterations, -kG, kMass, kLever, fy);
    return json;
}

TEST_P(FlowBelowCapacity, HoldsBelowTheCoupledSurfaceAndBreaksAbove) {
    const std::string engine = GetParam();
    const int iterations = fewest_iterations_that_hold(engine);
    for (double share : {0.5, 0.8, 0.9, 0.95}) {
        const Outcome r = run(engine, coupled_json(share, iterations));
        EXPECT_LT(r.plastic_rotation, kHolds) << engine << ", " << iterations << " iterations, " << share << " of the onset";
        EXPECT_FALSE(r.broken);
    }
    const Outcome above = run(engine, coupled_json(1.05, iterations));
    EXPECT_TRUE(above.broken) << engine << ", 1.05 of the onset: " << above.plastic_rotation << " rad";
}

// At 10 iterations every engine still yields and breaks above capacity; below it only ODE's direct
// solver holds every case (the others' rows are too far off: docs/adapters.md).
TEST_P(FlowBelowCapacity, TenIterationsStillBreakAboveCapacity) {
    for (double turn : {0.0, 22.5, 45.0}) {
        const Outcome above = run(GetParam(), scene_json(1.05, turn, 10));
        EXPECT_TRUE(above.broken) << GetParam() << ", " << turn << " deg";
        const Outcome half = run(GetParam(), scene_json(0.5, turn, 10));
        EXPECT_LT(half.plastic_rotation, kHolds) << GetParam() << ", " << turn << " deg, 0.5 C";
    }
}

INSTANTIATE_TEST_SUITE_P(Engines, FlowBelowCapacity, ::testing::ValuesIn(available_engines()), test::engine_test_name);

}  // namespace
}  // namespace plascap
