// The one-call library path on Bullet, through an installed plascap: a section by name and a
// material from the catalogue become a plastic joint's settings in one call, and the joint hangs a
// 3 t weight on a 10 mm S355 round bar. The bar's plastic axial capacity N = fy·πd²/4 = 27.9 kN is
// below the weight (29.4 kN), so it yields and stretches at a = g − N/m (the rigid-plastic
// oscillator, docs/references.md): after n steps of h the semi-implicit Euler drop is
// a·h²·n(n+1)/2.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_world.hpp"
#include "plascap/adapters/section_joint_settings.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/shape_designation.hpp"

int main() {
    const double g = 9.81, m = 3000.0, dt = 0.01;
    const plascap::Material& steel = plascap::MaterialCatalogue::built_in().get("S355", "example");
    const plascap::ValidSection bar = plascap::validate_section(plascap::shape_section("ROUND 10", steel));
    plascap::SectionJointOptions dofs;  // default: all six dofs plastic on the coupled yield surface
    dofs.modes.fill(plascap::DofMode::Rigid);
    dofs.modes[plascap::index(plascap::Dof::N)] = plascap::DofMode::Plastic;  // here only the axial one
    const plascap::PlasticJointSettings settings = plascap::section_joint_settings(bar, dofs);

    plascap::BulletWorld world(btVector3(0, -g, 0), 10);
    plascap::BulletBox weight(btVector3(0.2, 0.2, 0.2), m, btTransform(btQuaternion::getIdentity(), btVector3(0, -0.5, 0)));
    world.world().addRigidBody(&weight.body());  // the world does not own its bodies
    // The joint frame at the anchor, 0.5 m above the weight: x, y (the bar's axis, up) and z as the world's.
    plascap::BulletPlasticJoint joint(nullptr, weight.body(), btTransform::getIdentity(), settings);  // nullptr: the world
    joint.on_break([](const plascap::JointBreak& b) { std::printf("broke at %.3f s\n", b.time); });
    joint.attach(world.world(), dt);  // it leaves the world by itself when destroyed

    const int steps = 30;
    for (int i = 0; i < steps; ++i) world.step(dt);
    const double N = settings.laws[plascap::index(plascap::Dof::N)].capacity_positive;
    const double closed_form = 355e6 * M_PI * 0.01 * 0.01 / 4;  // the 1e-6 arc tolerance's polygon is a hair smaller
    const double expected = 0.5 * (g - N / m) * dt * dt * steps * (steps + 1);
    const double drop = -0.5 - weight.body().getCenterOfMassPosition().y();
    std::printf("N = %.1f N (fy*pi*d^2/4 = %.1f N), drop %.6f m (expected %.6f), plastic %.6f m, dissipated %.3f J\n", N,
                closed_form, drop, expected, joint.law().plastic_displacement(), joint.law().dissipated());
    joint.detach();  // before its body leaves the world
    world.world().removeRigidBody(&weight.body());
    return std::fabs(N / closed_form - 1.0) < 1e-5 && std::fabs(drop / expected - 1.0) < 1e-6 ? 0 : 1;
}
