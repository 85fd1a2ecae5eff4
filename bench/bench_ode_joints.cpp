// The ODE adapter's cost (issue 16): one dWorldQuickStep with n plastic joints against the same
// scene with n dJointTypeFixed, timed interleaved with it (counter vs_rigid; goal ≤ 1.3 for hinges and
// for all six dofs plastic), and the cost per joint from 100 to 10,000 joints (ns_per_joint). PlasticAxis:
// one plastic rotation, five rigid dofs. Sleeping: rigid-plastic joints whose bodies all sleep.
// Run: build/bench/bench_ode_joints (docs/adapters.md, "Cost").
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "plascap/adapters/ode_plastic_joints.hpp"
#include "hanging_box_springs.hpp"
#include "joint_yield_settings.hpp"
#include "vs_rigid.hpp"

namespace {

constexpr double kDt = 1.0 / 60;

// n boxes of 10 kg, each held from the world at its top (no collision detection: none touch).
struct HangingBoxes {
    dWorldID world;
    std::vector<dBodyID> boxes;
    explicit HangingBoxes(int n) {
        [[maybe_unused]] static const bool initialised = dInitODE2(0) != 0;  // once: a variant's scene and its baseline's live together
        world = dWorldCreate();
        dWorldSetGravity(world, 0, -9.81, 0);
        dWorldSetQuickStepNumIterations(world, 10);
        for (int i = 0; i < n; ++i) {
            dBodyID b = dBodyCreate(world);
            dMass m;
            dMassSetBoxTotal(&m, 10.0, 0.4, 1.0, 0.4);
            dBodySetMass(b, &m);
            dBodySetPosition(b, 3.0 * (i % 100), -0.5, 3.0 * (i / 100));
            boxes.push_back(b);
        }
    }
    ~HangingBoxes() { dWorldDestroy(world); }
    plascap::Pose anchor(int i) const {
        plascap::Pose p;
        p.origin = {3.0 * (i % 100), 0, 3.0 * (i / 100)};
        return p;
    }
};

// `feedback`, if given: one per box, for ODE to report each joint's forces in.
void fix_all(HangingBoxes& scene, dJointFeedback* feedback = nullptr) {
    for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
        dJointID j = dJointCreateFixed(scene.world, nullptr);
        dJointAttach(j, scene.boxes[i], nullptr);
        dJointSetFixed(j);
        if (feedback) dJointSetFeedback(j, &feedback[i]);
    }
}

// Argument: joints.
void Fixed(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    HangingBoxes scene(n);
    fix_all(scene);
    bench::time_baseline(state, [&] { dWorldQuickStep(scene.world, kDt); }, n);
}
BENCHMARK(Fixed)->ArgName("joints")->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// ODE's fixed joints again, each with a dJointFeedback, as any joint whose forces a program reads:
// what ODE's reporting of the forces alone costs (QuickStep keeps a copy of those joints' Jacobians
// and sums each row's force into the feedback after the solve). plascap's rows read their forces
// this way, so this is a floor under their vs_rigid that no change in plascap can lower.
void FixedWithFeedback(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    HangingBoxes rigid(n);
    fix_all(rigid);
    HangingBoxes scene(n);
    std::vector<dJointFeedback> feedback(static_cast<std::size_t>(n));
    fix_all(scene, feedback.data());
    bench::time_steps(state, [&] { dWorldQuickStep(scene.world, kDt); }, [&] { dWorldQuickStep(rigid.world, kDt); }, n);
}
BENCHMARK(FixedWithFeedback)->ArgName("joints")->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// One plastic joint per box with `settings`, stepped as a user steps them: OdePlasticJoints::step,
// which plans every joint's rows, steps the world and settles every joint (loading each joint's state
// a few joints ahead: prefetch.hpp).
void step_with_joints(benchmark::State& state, int n, const plascap::PlasticJointSettings& settings) {
    HangingBoxes rigid(n);
    fix_all(rigid);
    HangingBoxes scene(n);
    auto joints = std::make_unique<plascap::OdePlasticJoints>(scene.world);
    for (int i = 0; i < n; ++i) joints->add(nullptr, scene.boxes[i], scene.anchor(i), settings);
    bench::time_steps(state, [&] { joints->step(kDt); }, [&] { dWorldQuickStep(rigid.world, kDt); }, n);
    bench::count_springs(state, joints->size(), [&](std::size_t i) -> const plascap::PlasticJointLaw& { return (*joints)[i].law(); });
    joints.reset();  // before the world goes
}

// Capacities well above the load; `springs` their stiffnesses (hanging_box_springs.hpp, as
// bench_bullet_joints: none; stiff, where only Mx and Mz are sampled springs — explicit pushes,
// forces on the box, not ODE rows — and the other dofs are past eq. 3.2's limit and hold as
// rigid-plastic rows; sampled, every plastic dof a spring); six = 1: all six dofs plastic, 0:
// translations rigid (a plastic hinge). Includes the adapter's planning and settling.
plascap::PlasticJointSettings plastic_settings(bench::Springs springs, bool six) {
    plascap::PlasticJointSettings settings;
    for (plascap::Dof dof : plascap::kAllDofs) {
        const bool plastic = six || plascap::is_rotation(dof);
        settings.modes[plascap::index(dof)] = plastic ? plascap::DofMode::Plastic : plascap::DofMode::Rigid;
        settings.laws[plascap::index(dof)] = plascap::DofLaw{1e5, 1e5, bench::spring_stiffness(springs, dof)};
    }
    return settings;
}

void PlasticJoints(benchmark::State& state) {
    step_with_joints(state, static_cast<int>(state.range(2)), plastic_settings(static_cast<bench::Springs>(state.range(0)), state.range(1) == 1));
}
BENCHMARK(PlasticJoints)
    ->ArgNames({"elastic", "six", "joints"})
    ->ArgsProduct({{0, 1, 2}, {0, 1}, {100, 1000, 10000}})
    ->Unit(benchmark::kMicrosecond);

bool any_awake(const HangingBoxes& scene) {
    for (dBodyID box : scene.boxes)
        if (dBodyIsEnabled(box)) return true;
    return false;
}

// Every box asleep: ODE's auto-disable on in both worlds, each stepped until no body is enabled
// (rigid-plastic joints, which hold the boxes still; springs would swing on). ODE then skips every
// island — the rigid world's step is little more than its search for them — and a plastic joint
// whose bodies sleep costs a glance, no settle and no plan (OdePlasticJoint::solved; counter
// `solved`: joints the last timed step solved, 0 here). six = 1: all six dofs plastic, 0: hinges.
void Sleeping(benchmark::State& state) {
    const int n = static_cast<int>(state.range(1));
    HangingBoxes rigid(n);
    fix_all(rigid);
    HangingBoxes scene(n);
    auto joints = std::make_unique<plascap::OdePlasticJoints>(scene.world);
    const plascap::PlasticJointSettings settings = plastic_settings(bench::Springs::None, state.range(0) == 1);
    for (int i = 0; i < n; ++i) joints->add(nullptr, scene.boxes[i], scene.anchor(i), settings);
    for (HangingBoxes* boxes : {&rigid, &scene}) {
        dWorldSetAutoDisableFlag(boxes->world, 1);
        for (dBodyID box : boxes->boxes) dBodySetAutoDisableDefaults(box);  // a body takes the world's when made
    }
    for (int i = 0; i < 300 && (any_awake(rigid) || any_awake(scene)); ++i) {
        dWorldQuickStep(rigid.world, kDt);
        joints->step(kDt);
    }
    if (any_awake(rigid) || any_awake(scene)) {
        state.SkipWithError("the hanging boxes did not fall asleep in 300 steps");
    } else {
        bench::time_steps(state, [&] { joints->step(kDt); }, [&] { dWorldQuickStep(rigid.world, kDt); }, n);
        state.counters["solved"] = static_cast<double>(joints->solved_joints());
    }
    joints.reset();  // before the world goes
}
BENCHMARK(Sleeping)
    ->ArgNames({"six", "joints"})
    ->ArgsProduct({{0, 1}, {100, 1000, 10000}})
    ->Unit(benchmark::kMicrosecond);

// A one-axis plastic hinge: Mz plastic, the other five dofs rigid: six rows in one joint, as a
// fixed joint has; elastic = 1 gives Mz a stiffness of 100 N·m/rad (five rows and a push). The
// hanging box's weight puts no moment on it.
void PlasticAxis(benchmark::State& state) {
    plascap::PlasticJointSettings settings;
    for (plascap::Dof dof : plascap::kAllDofs) {
        const bool plastic = dof == plascap::Dof::Mz;
        settings.modes[plascap::index(dof)] = plastic ? plascap::DofMode::Plastic : plascap::DofMode::Rigid;
        settings.laws[plascap::index(dof)] = plascap::DofLaw{1e5, 1e5, std::nullopt};
        if (plastic && state.range(0) == 1) settings.laws[plascap::index(dof)].stiffness = 100.0;
    }
    step_with_joints(state, static_cast<int>(state.range(1)), settings);
}
BENCHMARK(PlasticAxis)
    ->ArgNames({"elastic", "joints"})
    ->ArgsProduct({{0, 1}, {100, 1000, 10000}})
    ->Unit(benchmark::kMicrosecond);

// Box against coupled yield: the cases of joint_yield_settings.hpp.
void YieldSurfaces(benchmark::State& state) {
    step_with_joints(state, 1000, bench::yield_surface_settings(state));
}
BENCHMARK(YieldSurfaces)->Apply(bench::yield_surface_cases);

}  // namespace
