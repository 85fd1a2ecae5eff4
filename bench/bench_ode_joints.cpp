// The ODE adapter's cost (issue 7): one dWorldQuickStep with 1,000 plastic joints against the same
// scene with 1,000 dJointTypeFixed. Target: ≤ 1.3×. Run: build/bench/bench_ode_joints
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "plascap/adapters/ode_plastic_joint.hpp"
#include "joint_yield_settings.hpp"

namespace {

constexpr int kJoints = 1000;
constexpr double kDt = 1.0 / 60;

// 1,000 boxes of 10 kg, each held from the world at its top (no collision detection: none touch).
struct HangingBoxes {
    dWorldID world;
    std::vector<dBodyID> boxes;
    HangingBoxes() {
        dInitODE2(0);
        world = dWorldCreate();
        dWorldSetGravity(world, 0, -9.81, 0);
        dWorldSetQuickStepNumIterations(world, 10);
        for (int i = 0; i < kJoints; ++i) {
            dBodyID b = dBodyCreate(world);
            dMass m;
            dMassSetBoxTotal(&m, 10.0, 0.4, 1.0, 0.4);
            dBodySetMass(b, &m);
            dBodySetPosition(b, 3.0 * (i % 40), -0.5, 3.0 * (i / 40));
            boxes.push_back(b);
        }
    }
    ~HangingBoxes() {
        dWorldDestroy(world);
        dCloseODE();
    }
    plascap::Pose anchor(int i) const {
        plascap::Pose p;
        p.origin = {3.0 * (i % 40), 0, 3.0 * (i / 40)};
        return p;
    }
};

void FixedJoints(benchmark::State& state) {
    HangingBoxes scene;
    for (dBodyID b : scene.boxes) {
        dJointID j = dJointCreateFixed(scene.world, nullptr);
        dJointAttach(j, b, nullptr);
        dJointSetFixed(j);
    }
    for (auto _ : state) dWorldQuickStep(scene.world, kDt);
}
BENCHMARK(FixedJoints)->Unit(benchmark::kMicrosecond);

// One plastic joint per box with `settings`; times the steps, the adapter's before_step and after_step included.
void step_with_joints(benchmark::State& state, HangingBoxes& scene, const plascap::PlasticJointSettings& settings) {
    std::vector<std::unique_ptr<plascap::OdePlasticJoint>> joints;
    for (int i = 0; i < kJoints; ++i) {
        joints.push_back(std::make_unique<plascap::OdePlasticJoint>(scene.world, nullptr, scene.boxes[i], scene.anchor(i), settings));
        joints.back()->engage(0.0);
    }
    for (auto _ : state) {
        for (auto& j : joints) j->before_step(kDt);
        dWorldQuickStep(scene.world, kDt);
        for (auto& j : joints) j->after_step(kDt);
    }
    joints.clear();
}

// Capacities well above the load; state.range(0) = 1 gives every plastic dof a stiffness (explicit
// spring rows); state.range(1) = 1: all six dofs plastic, 0: translations rigid (a plastic hinge).
// Includes the adapter's before_step and after_step.
void PlasticJoints(benchmark::State& state) {
    HangingBoxes scene;
    plascap::PlasticJointSettings settings;
    for (plascap::Dof dof : plascap::kAllDofs) {
        const bool plastic = state.range(1) == 1 || plascap::is_rotation(dof);
        settings.modes[plascap::index(dof)] = plastic ? plascap::DofMode::Plastic : plascap::DofMode::Rigid;
        settings.laws[plascap::index(dof)] = plascap::DofLaw{1e5, 1e5, std::nullopt};
        if (state.range(0) == 1) settings.laws[plascap::index(dof)].stiffness = 100.0;
    }
    step_with_joints(state, scene, settings);
}
BENCHMARK(PlasticJoints)->Args({0, 1})->Args({1, 1})->Args({0, 0})->Args({1, 0})->Unit(benchmark::kMicrosecond);

// Box against coupled yield: the cases of joint_yield_settings.hpp.
void YieldSurfaces(benchmark::State& state) {
    HangingBoxes scene;
    step_with_joints(state, scene, bench::yield_surface_settings(state));
}
BENCHMARK(YieldSurfaces)->Apply(bench::yield_surface_cases);

}  // namespace
