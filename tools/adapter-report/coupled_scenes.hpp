#pragma once
// Static loads on one joint with a section's coupled yield condition (docs/yield-surface.md), as a
// user writes them (plastic-sim JSON): a 1 m cube on a joint to the world, loaded by its weight in
// axial force and bending, bending about a diagonal, or torsion. The engine tests
// (tests/test_coupled_joint_engines.cpp) and adapter-report --coupled run them.
#include <memory>
#include <string>

#include "plascap/adapters/dof.hpp"
#include "plascap/adapters/vec3.hpp"
#include "plascap/sections/geometry.hpp"
#include "scene_engine.hpp"

namespace plascap::coupled {

inline constexpr double kG = 10.0;  // [m/s²], the scenes' gravity

struct Case {
    std::string name;
    std::string axis, x_axis;      // JSON arrays: the joint's y and x axes in the world
    Vec3 centre{};                 // the block's centre [m]
    std::string section;           // JSON of the joint's "section"
    std::string dofs;              // JSON of the joint's "dofs"
    double fy = 0.0;               // [Pa]
    PerDof<double> load_per_kg{};  // the static section loads per kg of the block [N/kg, N·m/kg]
    Section cpp_section;           // the same section, for the exact onset
};

Case axial_and_bending();
Case diagonal_bending();
Case pure_torsion();

// The scene: `mass` kg, `extra_joint_keys` (JSON text starting with a comma) added to the joint.
std::string scene_json(const Case& c, double mass, const std::string& extra_joint_keys, double duration,
                       double dt = 1.0 / 240);

// The block's mass at which the static load reaches U = 1 on the exact condition.
double onset_mass(const Case& c);

struct SceneRun {
    double plastic = 0.0;       // accumulated plastic translation + rotation at the end [m + rad]
    bool broken = false;
    double worst_ledger = 0.0;  // max |KE + PE + elastic + dissipated| over the run [J]
    double handled = 0.0;       // max |PE − PE0| [J]
    // U of the loads the joint applied, over the steps in which it flowed (plastic grew).
    double flow_u_min = 0.0, flow_u_max = 0.0, flow_u_mean = 0.0;
    std::size_t flow_steps = 0;
};

SceneRun run_scene(const std::string& engine, const std::string& json);

}  // namespace plascap::coupled
