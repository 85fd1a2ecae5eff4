#pragma once
// The Bullet benchmarks' scene (issue 16): n boxes of 10 kg, each hanging from the world at the
// centre of its top face, spaced so none collide; the rigid baseline's btFixedConstraint per box,
// and the settings of a plastic joint with all six dofs plastic. Used by bench_bullet_joints and
// bullet_step_zones.
#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>
#include <BulletDynamics/ConstraintSolver/btFixedConstraint.h>

#include <memory>
#include <vector>

#include "plascap/adapters/bullet_world.hpp"
#include "plascap/adapters/plastic_joint_settings.hpp"
#include "hanging_box_springs.hpp"

namespace bench {

inline constexpr double kDt = 1.0 / 60;

// n boxes of 10 kg, each held from the world at its top, spaced so none collide.
struct HangingBoxes {
    plascap::BulletWorld world;
    std::vector<std::unique_ptr<plascap::BulletBox>> boxes;
    HangingBoxes(int n, bool split_islands, plascap::BulletSolverKind solver = plascap::BulletSolverKind::Plascap)
        : world(btVector3(0, -9.81, 0), 10, solver) {
        // Bullet's per-island solve finds each island's constraints by scanning all of them: O(n²)
        // per step (issue 16's scaling sweep measures it). Unsplit, everything is one solve.
        world.world().getSimulationIslandManager()->setSplitIslands(split_islands);
        for (int i = 0; i < n; ++i) {
            boxes.push_back(std::make_unique<plascap::BulletBox>(btVector3(0.2, 0.5, 0.2), 10.0,
                                                                 btTransform(btQuaternion::getIdentity(), at(i, -0.5))));
            world.world().addRigidBody(&boxes.back()->body());
        }
    }
    ~HangingBoxes() {
        for (auto& b : boxes) world.world().removeRigidBody(&b->body());
    }
    static btVector3 at(int i, double y) { return btVector3(3.0 * (i % 100), y, 3.0 * (i / 100)); }
    btTransform anchor(int i) const { return btTransform(btQuaternion::getIdentity(), at(i, 0.0)); }
    int size() const { return static_cast<int>(boxes.size()); }
};

struct FixedJoints {
    HangingBoxes& scene;
    std::vector<std::unique_ptr<btFixedConstraint>> joints;
    explicit FixedJoints(HangingBoxes& s) : scene(s) {
        for (int i = 0; i < s.size(); ++i) {
            btRigidBody& body = s.boxes[i]->body();
            const btTransform in_b = body.getCenterOfMassTransform().inverse() * s.anchor(i);
            joints.push_back(std::make_unique<btFixedConstraint>(btTypedConstraint::getFixedBody(), body, s.anchor(i), in_b));
            s.world.world().addConstraint(joints.back().get(), true);
        }
    }
    ~FixedJoints() {
        for (auto& j : joints) scene.world.world().removeConstraint(j.get());
    }
};

// All six dofs plastic (capacities well above the load, so the boxes hang still as with the fixed
// joints); `springs` their stiffnesses (hanging_box_springs.hpp: none; stiff, four rigid-plastic rows
// and two springs; sampled, six springs).
inline plascap::PlasticJointSettings all_six_plastic(bench::Springs springs) {
    plascap::PlasticJointSettings settings;
    for (plascap::Dof dof : plascap::kAllDofs) {
        settings.modes[plascap::index(dof)] = plascap::DofMode::Plastic;
        settings.laws[plascap::index(dof)] = plascap::DofLaw{1e5, 1e5, bench::spring_stiffness(springs, dof)};
    }
    return settings;
}

}  // namespace bench
