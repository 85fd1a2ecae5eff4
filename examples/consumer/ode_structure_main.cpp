// structure_main.cpp on ODE: the cantilever of cantilever_structure.hpp (plascap::structures), its
// segments as dBodies with the member's mass and inertia, its joints through OdePlasticJoints. At
// 0.9 P_c = 0.9 M_p/L the support holds, at 1.1 P_c it turns into a hinge.
#include <ode/ode.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "plascap/adapters/ode_plastic_joints.hpp"
#include "plascap/adapters/structure_model.hpp"

#include "cantilever_structure.hpp"

namespace {

// The support's plastic rotation [rad] after a tip load of `load` [N], ramped over 1 s and held 1 s.
double support_rotation(const plascap::StructureModel& model, const plascap::Vec3& load) {
    const double dt = 0.002;
    const dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, 0);
    dWorldSetQuickStepNumIterations(world, 100);
    std::vector<dBodyID> bodies;
    for (const plascap::StructureSegment& s : model.segments) {
        const dBodyID body = dBodyCreate(world);
        dMass mass;
        dMassSetParameters(&mass, s.mass, 0, 0, 0, s.inertia[0], s.inertia[1], s.inertia[2], 0, 0, 0);  // principal, about its centre
        dBodySetMass(body, &mass);
        dBodySetPosition(body, s.position[0], s.position[1], s.position[2]);
        const dQuaternion q = {s.orientation[0], s.orientation[1], s.orientation[2], s.orientation[3]};  // w, x, y, z
        dBodySetQuaternion(body, q);
        bodies.push_back(body);
    }
    double rotation = 0.0;
    {
        plascap::OdePlasticJoints joints(world);
        for (const plascap::StructureJoint& j : model.joints)
            joints.add(j.a ? bodies[*j.a] : nullptr, bodies[j.b], j.frame(), j.settings);  // nullptr: the world
        const plascap::BodyPoint tip = model.nodes.back().at;  // node C, carried by the last segment
        for (int i = 0; i < 1000; ++i) {
            const double ramp = std::fmin(1.0, i * dt);
            dBodyAddForceAtRelPos(bodies[tip.body], load[0] * ramp, load[1] * ramp, load[2] * ramp, tip.local[0], tip.local[1], tip.local[2]);
            joints.step(dt, plascap::OdePlasticJoints::Stepper::QuickSplit);  // warm rows, corrections split off: no sag by slack
        }
        rotation = joints[model.joints.size() - 1].law().plastic_rotation();  // the support, the last joint
    }  // the joints go before their world
    dWorldDestroy(world);
    return rotation;
}

}  // namespace

int main() {
    const double L = kCantileverLength, Mp = kCantileverMp;
    dInitODE2(0);
    const plascap::StructureModel model = cantilever_model();
    const double holds = support_rotation(model, {0, -0.9 * Mp / L, 0}), folds = support_rotation(model, {0, -1.1 * Mp / L, 0});
    dCloseODE();
    std::printf("ODE: support's plastic rotation at 0.9 Mp/L: %.5f rad, at 1.1 Mp/L: %.3f rad\n", holds, folds);
    return holds < 1e-3 && folds > 0.05 ? 0 : 1;
}
