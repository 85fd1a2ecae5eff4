// The Bullet adapter's cost (issue 6): one world step with 1,000 plastic joints against the same
// scene with 1,000 btFixedConstraint. Target: ≤ 1.3×. Run: build/bench/bench_bullet_joints
#include <benchmark/benchmark.h>

#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>
#include <BulletDynamics/ConstraintSolver/btFixedConstraint.h>

#include <memory>
#include <vector>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_world.hpp"
#include "joint_yield_settings.hpp"

namespace {

constexpr int kJoints = 1000;
constexpr double kDt = 1.0 / 60;

// 1,000 boxes of 10 kg, each held from the world at its top, spaced so none collide.
struct HangingBoxes {
    plascap::BulletWorld world{btVector3(0, -9.81, 0), 10};
    std::vector<std::unique_ptr<plascap::BulletBox>> boxes;
    explicit HangingBoxes(bool split_islands) {
        // Bullet's per-island solve finds each island's constraints by scanning all of them: O(n²)
        // per step, which dominates both cases at 1,000 joints. Unsplit, everything is one solve.
        world.world().getSimulationIslandManager()->setSplitIslands(split_islands);
        for (int i = 0; i < kJoints; ++i) {
            const btVector3 at(3.0 * (i % 40), -0.5, 3.0 * (i / 40));
            boxes.push_back(std::make_unique<plascap::BulletBox>(btVector3(0.2, 0.5, 0.2), 10.0,
                                                                 btTransform(btQuaternion::getIdentity(), at)));
            world.world().addRigidBody(&boxes.back()->body());
        }
    }
    ~HangingBoxes() {
        for (auto& b : boxes) world.world().removeRigidBody(&b->body());
    }
    btTransform anchor(int i) const { return btTransform(btQuaternion::getIdentity(), btVector3(3.0 * (i % 40), 0, 3.0 * (i / 40))); }
};

// state.range(1): 1 = Bullet's default per-island solve, 0 = one solve for the whole world.
void FixedConstraints(benchmark::State& state) {
    HangingBoxes scene(state.range(1) == 1);
    std::vector<std::unique_ptr<btFixedConstraint>> joints;
    for (int i = 0; i < kJoints; ++i) {
        btRigidBody& body = scene.boxes[i]->body();
        const btTransform in_b = body.getCenterOfMassTransform().inverse() * scene.anchor(i);
        joints.push_back(std::make_unique<btFixedConstraint>(btTypedConstraint::getFixedBody(), body, scene.anchor(i), in_b));
        scene.world.world().addConstraint(joints.back().get(), true);
    }
    for (auto _ : state) scene.world.step(kDt);
    for (auto& j : joints) scene.world.world().removeConstraint(j.get());
}
BENCHMARK(FixedConstraints)->Args({0, 1})->Args({0, 0})->Unit(benchmark::kMicrosecond);

// One plastic joint per box with `settings`; times the world's steps.
void step_with_joints(benchmark::State& state, HangingBoxes& scene, const plascap::PlasticJointSettings& settings) {
    std::vector<std::unique_ptr<plascap::BulletPlasticJoint>> joints;
    for (int i = 0; i < kJoints; ++i) {
        joints.push_back(std::make_unique<plascap::BulletPlasticJoint>(nullptr, scene.boxes[i]->body(), scene.anchor(i), settings));
        joints.back()->attach(scene.world.world(), kDt);
    }
    for (auto _ : state) scene.world.step(kDt);
    joints.clear();  // each joint leaves the world as it is destroyed
}

// All six dofs plastic (capacities well above the load, so the boxes hang still as with the fixed
// joints); state.range(0) = 1 gives every dof an elastic stiffness (explicit spring rows).
void PlasticJoints(benchmark::State& state) {
    HangingBoxes scene(state.range(1) == 1);
    plascap::PlasticJointSettings settings;
    for (plascap::Dof dof : plascap::kAllDofs) {
        settings.modes[plascap::index(dof)] = plascap::DofMode::Plastic;
        settings.laws[plascap::index(dof)] = plascap::DofLaw{1e5, 1e5, std::nullopt};
        if (state.range(0) == 1) settings.laws[plascap::index(dof)].stiffness = 100.0;
    }
    step_with_joints(state, scene, settings);
}
BENCHMARK(PlasticJoints)->Args({0, 1})->Args({1, 1})->Args({0, 0})->Args({1, 0})->Unit(benchmark::kMicrosecond);

// Box against coupled yield: the cases of joint_yield_settings.hpp.
void YieldSurfaces(benchmark::State& state) {
    HangingBoxes scene(false);
    step_with_joints(state, scene, bench::yield_surface_settings(state));
}
BENCHMARK(YieldSurfaces)->Apply(bench::yield_surface_cases);

}  // namespace
