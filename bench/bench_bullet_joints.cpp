// The Bullet adapter's cost (issue 16): one world step with n plastic joints against the same scene
// with n btFixedConstraint, timed interleaved with it (counter vs_rigid; goal ≤ 1.15 for rigid-plastic
// and elastic-plastic joints, one solve and per island), and the cost per joint from 100 to 10,000
// joints (ns_per_joint); Sleeping: rigid-plastic joints whose bodies all sleep. Run:
// build/bench/bench_bullet_joints (docs/adapters.md, "Cost").
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "bullet_hanging_boxes.hpp"
#include "hanging_box_springs.hpp"
#include "joint_yield_settings.hpp"
#include "vs_rigid.hpp"

namespace {

using bench::all_six_plastic;
using bench::FixedJoints;
using bench::HangingBoxes;
using bench::kDt;

// Arguments: joints, split islands (1 = Bullet's default per-island solve, 0 = one solve).
void Fixed(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const bool split = state.range(1) == 1;
    HangingBoxes scene(n, split, plascap::BulletSolverKind::Bullet);  // the engine as it comes
    FixedJoints fixed(scene);
    bench::time_baseline(state, [&] { scene.world.step(kDt); }, n);
}

// One plastic joint of type Joint per box with `settings`; times the world's steps.
template <class Joint>
void step_with_joints(benchmark::State& state, int n, bool split, const plascap::PlasticJointSettings& settings,
                      plascap::BulletSolverKind solver = plascap::BulletSolverKind::Plascap) {
    HangingBoxes rigid(n, split, plascap::BulletSolverKind::Bullet);  // the baseline: the engine as it comes
    FixedJoints fixed(rigid);
    HangingBoxes scene(n, split, solver);
    std::vector<std::unique_ptr<Joint>> joints;
    for (int i = 0; i < n; ++i) {
        joints.push_back(std::make_unique<Joint>(nullptr, scene.boxes[i]->body(), scene.anchor(i), settings));
        joints.back()->attach(scene.world.world(), kDt);
    }
    bench::time_steps(state, [&] { scene.world.step(kDt); }, [&] { rigid.world.step(kDt); }, n);
    bench::count_springs(state, joints.size(), [&](std::size_t i) -> const plascap::PlasticJointLaw& { return joints[i]->law(); });
    joints.clear();  // each joint leaves the world as it is destroyed
}

// Arguments: elastic (0 none, 1 stiff, 2 sampled springs: bench::Springs), joints, split islands;
// counter `springs`: the dofs per joint that were springs (the others held as rows). Plascap: the default BulletPlasticJoint; Spring2: the
// paper's route (a btGeneric6DofSpring2Constraint driven from outside).
void Plascap(benchmark::State& state) {
    step_with_joints<plascap::BulletPlasticJoint>(state, static_cast<int>(state.range(1)), state.range(2) == 1,
                                                  all_six_plastic(static_cast<bench::Springs>(state.range(0))));
}
// The default joint on Bullet's own solver: cold-started rows, Baumgarte in their velocities.
void PlascapCold(benchmark::State& state) {
    step_with_joints<plascap::BulletPlasticJoint>(state, static_cast<int>(state.range(1)), state.range(2) == 1,
                                                  all_six_plastic(static_cast<bench::Springs>(state.range(0))), plascap::BulletSolverKind::Bullet);
}
void Spring2(benchmark::State& state) {
    step_with_joints<plascap::BulletPlasticJointSpring2>(state, static_cast<int>(state.range(1)), state.range(2) == 1,
                                                         all_six_plastic(static_cast<bench::Springs>(state.range(0))));
}

// Every size on one solve; 100 and 1,000 joints per island too (10,000 per island is the O(n²)
// scan: minutes per run).
void sizes(benchmark::internal::Benchmark* b, bool with_elastic) {
    for (int elastic : with_elastic ? std::vector<int>{0, 1, 2} : std::vector<int>{-1}) {
        for (int n : {100, 1000, 10000}) {
            for (int split : {0, 1}) {
                if (n == 10000 && split == 1) continue;
                if (elastic < 0) {
                    b->Args({n, split});
                } else {
                    b->Args({elastic, n, split});
                }
            }
        }
    }
    b->Unit(benchmark::kMicrosecond);
}
BENCHMARK(Fixed)->ArgNames({"joints", "split"})->Apply([](auto* b) { sizes(b, false); });
BENCHMARK(Plascap)->ArgNames({"elastic", "joints", "split"})->Apply([](auto* b) { sizes(b, true); });
BENCHMARK(PlascapCold)->ArgNames({"elastic", "joints", "split"})->Apply([](auto* b) { sizes(b, true); });
BENCHMARK(Spring2)->ArgNames({"elastic", "joints", "split"})->Apply([](auto* b) { sizes(b, true); });

bool any_active(const HangingBoxes& scene) {
    for (const auto& box : scene.boxes)
        if (box->body().isActive()) return true;
    return false;
}

// Every box asleep: both worlds' boxes allowed to sleep (BulletBox forbids it), each world stepped
// until none is active (Bullet: 2 s under its sleeping speeds), with rigid-plastic joints, which
// hold the boxes still. A plastic joint whose island sleeps costs a glance, no settle and no plan
// (BulletPlasticJoint::solved; counter `solved`: joints the last timed step solved, 0 here).
// Arguments: joints, split islands.
void Sleeping(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const bool split = state.range(1) == 1;
    HangingBoxes rigid(n, split, plascap::BulletSolverKind::Bullet);
    FixedJoints fixed(rigid);
    HangingBoxes scene(n, split);
    std::vector<std::unique_ptr<plascap::BulletPlasticJoint>> joints;
    for (int i = 0; i < n; ++i) {
        joints.push_back(std::make_unique<plascap::BulletPlasticJoint>(nullptr, scene.boxes[i]->body(), scene.anchor(i),
                                                                       all_six_plastic(bench::Springs::None)));
        joints.back()->attach(scene.world.world(), kDt);
    }
    for (HangingBoxes* boxes : {&rigid, &scene})
        for (auto& box : boxes->boxes) box->body().forceActivationState(ACTIVE_TAG);
    for (int i = 0; i < 400 && (any_active(rigid) || any_active(scene)); ++i) {
        rigid.world.step(kDt);
        scene.world.step(kDt);
    }
    if (any_active(rigid) || any_active(scene)) {
        state.SkipWithError("the hanging boxes did not fall asleep in 400 steps");
    } else {
        bench::time_steps(state, [&] { scene.world.step(kDt); }, [&] { rigid.world.step(kDt); }, n);
        int solved = 0;
        for (const auto& joint : joints) solved += joint->solved() ? 1 : 0;
        state.counters["solved"] = solved;
    }
    joints.clear();
}
BENCHMARK(Sleeping)->ArgNames({"joints", "split"})->Apply([](auto* b) { sizes(b, false); });

// Box against coupled yield: the cases of joint_yield_settings.hpp, 1,000 joints, one solve.
void YieldSurfaces(benchmark::State& state) {
    step_with_joints<plascap::BulletPlasticJoint>(state, 1000, false, bench::yield_surface_settings(state));
}
BENCHMARK(YieldSurfaces)->Apply(bench::yield_surface_cases);

}  // namespace
