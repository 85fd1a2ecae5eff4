#include "bullet_scenes.hpp"

namespace plascap::test {
namespace {

template <class Joint>
void record(Trace& trace, Joint& joint, btRigidBody& body, Dof dof, const btVector3& up,
            double potential_energy) {
    const PerDof<double> x = joint.positions();
    const ElasticPlasticLaw& law = *joint.law().law(dof);
    trace.time.push_back(joint.time());
    trace.position.push_back(x[index(dof)]);
    trace.force.push_back(joint.forces()[index(dof)]);
    trace.plastic.push_back(law.accumulated_plastic());
    trace.dissipated.push_back(law.dissipated());
    trace.body_y.push_back(body.getCenterOfMassPosition().dot(up));
    const double kinetic = 0.5 * body.getLinearVelocity().length2() / body.getInvMass() +
                           0.5 * body.getAngularVelocity().dot(body.getInvInertiaTensorWorld().inverse() *
                                                               body.getAngularVelocity());
    trace.elastic.push_back(joint.law().elastic_energy(x));
    trace.energy.push_back(kinetic + potential_energy + trace.elastic.back() + law.dissipated());
}

template <class Joint>
Trace run_hanging(const HangingBlock& s) {
    const btMatrix3x3 turn(s.turn);
    const btVector3 up = turn * btVector3(0, 1, 0);
    BulletWorld world(-s.g * up, s.iterations);
    BulletBox block(btVector3(0.1, 0.1, 0.1), s.mass, btTransform(s.turn, turn * btVector3(0, -0.5, 0)));
    world.world().addRigidBody(&block.body());

    PlasticJointSettings settings;
    settings.modes = {DofMode::Rigid, DofMode::Plastic, DofMode::Rigid, DofMode::Rigid, DofMode::Rigid, DofMode::Rigid};
    settings.laws[index(Dof::N)] = DofLaw{s.capacity, s.capacity, s.stiffness};
    settings.max_plastic_displacement = s.max_plastic_displacement;
    Joint joint(nullptr, block.body(), btTransform(s.turn, btVector3(0, 0, 0)), settings);

    for (int i = 0; i < s.engage_after_steps; ++i) world.step(s.dt);  // the paper's joint acts from step 2
    joint.attach(world.world(), s.dt);
    const double y0 = block.body().getCenterOfMassPosition().dot(up);
    Trace trace;
    for (int i = 0; i < s.steps; ++i) {
        world.step(s.dt);
        const double y = block.body().getCenterOfMassPosition().dot(up);
        record(trace, joint, block.body(), Dof::N, up, s.mass * s.g * (y - y0));
        if (joint.law().broken() && trace.broken_at < 0) trace.broken_at = *joint.law().broken_at();
    }
    joint.detach(world.world());
    world.world().removeRigidBody(&block.body());
    return trace;
}

template <class Joint>
Trace run_cantilever(const Cantilever& s) {
    // The rod lies along world x from the anchor; the joint's beam axis y is the rod's axis and its
    // x axis is world up, so z = x × y = −world z and gravity bends the rod about +z: the Mz dof.
    const btMatrix3x3 turn(s.turn);
    const btVector3 up = turn * btVector3(0, 1, 0);
    BulletWorld world(-s.g * up, s.iterations);
    BulletBox rod(btVector3(s.length / 2, s.thickness / 2, s.thickness / 2), s.mass,
                  btTransform(s.turn, turn * btVector3(s.length / 2, 0, 0)));
    world.world().addRigidBody(&rod.body());

    PlasticJointSettings settings;
    settings.modes = {DofMode::Rigid, DofMode::Rigid, DofMode::Rigid, DofMode::Rigid, DofMode::Rigid, DofMode::Plastic};
    settings.laws[index(Dof::Mz)] = DofLaw{s.capacity, s.capacity, s.stiffness};
    const btMatrix3x3 frame_basis(0, 1, 0,   // columns: x = world y, y = world x, z = −world z
                                  1, 0, 0,
                                  0, 0, -1);
    btTransform frame(turn * frame_basis, btVector3(0, 0, 0));
    Joint joint(nullptr, rod.body(), frame, settings);
    joint.attach(world.world(), s.dt);
    const double y0 = rod.body().getCenterOfMassPosition().dot(up);
    Trace trace;
    for (int i = 0; i < s.steps; ++i) {
        world.step(s.dt);
        const double y = rod.body().getCenterOfMassPosition().dot(up);
        record(trace, joint, rod.body(), Dof::Mz, up, s.mass * s.g * (y - y0));
    }
    joint.detach(world.world());
    world.world().removeRigidBody(&rod.body());
    return trace;
}

}  // namespace

Trace run(const HangingBlock& s) {
    return s.spring1 ? run_hanging<BulletPlasticJoint6DofSpring>(s) : run_hanging<BulletPlasticJoint>(s);
}

Trace run(const Cantilever& s) {
    return s.spring1 ? run_cantilever<BulletPlasticJoint6DofSpring>(s) : run_cantilever<BulletPlasticJoint>(s);
}

}  // namespace plascap::test
