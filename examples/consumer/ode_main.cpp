// The one-call library path on ODE, through an installed plascap: the same 10 mm S355 round bar as
// bullet_main.cpp, a section by name turned into a plastic joint's settings in one call, hanging a
// 3 t weight that stretches it at a = g − N/m, N = fy·πd²/4 (docs/references.md). OdePlasticJoints
// steps the world and every joint in one call.
#include <ode/ode.h>

#include <cmath>
#include <cstdio>

#include "plascap/adapters/ode_plastic_joints.hpp"
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

    dInitODE2(0);
    const dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, -g, 0);
    const dBodyID weight = dBodyCreate(world);
    dMass mass;
    dMassSetBoxTotal(&mass, m, 0.4, 0.4, 0.4);
    dBodySetMass(weight, &mass);
    dBodySetPosition(weight, 0, -0.5, 0);

    const double N = settings.laws[plascap::index(plascap::Dof::N)].capacity_positive;
    double drop = 0.0, plastic = 0.0;
    const int steps = 30;
    {
        plascap::OdePlasticJoints joints(world);  // settings as above; world, weight: a dWorldID, a dBodyID
        // The joint frame at the anchor, 0.5 m above the weight: x, y (the bar's axis, up), z as the world's.
        joints.add(nullptr, weight, plascap::Pose{}, settings)  // nullptr: the world
            .on_break([](const plascap::JointBreak& b) { std::printf("broke at %.3f s\n", b.time); });
        // Before each step, joints.collide(space, contacts, surface) would skip joined pairs; nothing collides here.
        for (int i = 0; i < steps; ++i) joints.step(dt, plascap::OdePlasticJoints::Stepper::Exact);
        drop = -0.5 - dBodyGetPosition(weight)[1];
        plastic = joints[0].law().plastic_displacement();
    }  // the joints go before their world
    dWorldDestroy(world);
    dCloseODE();

    const double closed_form = 355e6 * M_PI * 0.01 * 0.01 / 4;  // the 1e-6 arc tolerance's polygon is a hair smaller
    const double expected = 0.5 * (g - N / m) * dt * dt * steps * (steps + 1);
    std::printf("N = %.1f N (fy*pi*d^2/4 = %.1f N), drop %.6f m (expected %.6f), plastic %.6f m\n", N, closed_form, drop,
                expected, plastic);
    return std::fabs(N / closed_form - 1.0) < 1e-5 && std::fabs(drop / expected - 1.0) < 1e-6 ? 0 : 1;
}
