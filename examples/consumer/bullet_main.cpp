// A plastic joint in Bullet through an installed plascap: a 3 kg block hangs from the world on a
// joint whose axial dof is rigid-plastic with capacity F = 18 N (every other dof rigid). Its weight
// W = 30 N exceeds F, so it flows at a = (W − F)/m = 4 m/s² (the rigid-plastic oscillator,
// docs/references.md): after n steps of h the semi-implicit Euler drop is a·h²·n(n+1)/2.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_world.hpp"

int main() {
    const double g = 10.0, m = 3.0, F = 18.0, dt = 0.01;
    plascap::BulletWorld world(btVector3(0, -g, 0), 10);
    plascap::BulletBox block(btVector3(0.1, 0.1, 0.1), m, btTransform(btQuaternion::getIdentity(), btVector3(0, -0.5, 0)));
    world.world().addRigidBody(&block.body());  // the world does not own its bodies

    plascap::PlasticJointSettings settings;
    settings.modes.fill(plascap::DofMode::Rigid);
    settings.modes[plascap::index(plascap::Dof::N)] = plascap::DofMode::Plastic;
    settings.laws[plascap::index(plascap::Dof::N)] = {F, F, std::nullopt};  // capacities, no stiffness
    // The joint frame at the anchor, 0.5 m above the block: x, y (the beam axis, up) and z as the world's.
    const btTransform frame = btTransform::getIdentity();
    plascap::BulletPlasticJoint joint(nullptr, block.body(), frame, settings);  // nullptr: the world
    joint.attach(world.world(), dt);

    const int steps = 30;
    for (int i = 0; i < steps; ++i) world.step(dt);
    const double expected = 0.5 * (m * g - F) / m * dt * dt * steps * (steps + 1);
    const double drop = -0.5 - block.body().getCenterOfMassPosition().y();
    std::printf("drop %.6f m (expected %.6f), plastic %.6f m, dissipated %.3f J\n", drop, expected,
                joint.law().plastic_displacement(), joint.law().dissipated());
    joint.detach(world.world());
    world.world().removeRigidBody(&block.body());
    return std::fabs(drop / expected - 1.0) < 1e-6 ? 0 : 1;
}
