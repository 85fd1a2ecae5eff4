#include "plascap/adapters/ode_plastic_joints.hpp"

#include <algorithm>
#include <vector>

namespace plascap {

OdePlasticJoint& OdePlasticJoints::add(dBodyID a, dBodyID b, const Pose& frame_in_world,
                                       const PlasticJointSettings& settings, double takes_hold_at) {
    joints_.push_back({std::make_unique<OdePlasticJoint>(world_, a, b, frame_in_world, settings), takes_hold_at});
    if (a) joined_.insert(std::minmax(a, b));
    return *joints_.back().joint;
}

void OdePlasticJoints::step(double dt, Stepper stepper) {
    for (Entry& e : joints_) {
        // Due when the step starts within half a step of the time asked for (no drift from summing dt).
        if (!e.joint->engaged() && e.takes_hold_at < time_ + 0.5 * dt) e.joint->engage(time_);
        if (e.joint->engaged()) e.joint->before_step(dt);
    }
    if (stepper == Stepper::Quick) {
        dWorldQuickStep(world_, dt);
    } else {
        dWorldStep(world_, dt);
    }
    for (Entry& e : joints_) {
        if (!e.joint->engaged()) continue;
        if (e.joint->after_step(dt) == JointEvent::Broke && e.joint->body_a())
            joined_.erase(joined_.find(std::minmax(e.joint->body_a(), e.joint->body_b())));
    }
    time_ += dt;
}

bool OdePlasticJoints::joined(dBodyID a, dBodyID b) const { return joined_.count(std::minmax(a, b)) > 0; }

namespace {

struct Collision {
    const OdePlasticJoints& joints;
    dWorldID world;
    dJointGroupID contacts;
    const dSurfaceParameters& surface;
    std::vector<dContact> buffer;
    const std::function<bool(dBodyID, dBodyID)>& skip;
};

void near_callback(void* data, dGeomID g1, dGeomID g2) {
    Collision& c = *static_cast<Collision*>(data);
    const dBodyID b1 = dGeomGetBody(g1), b2 = dGeomGetBody(g2);
    if (!b1 && !b2) return;                                // static against static
    if (b1 && b2 && c.joints.joined(b1, b2)) return;     // held by a plastic joint
    if (c.skip && c.skip(b1, b2)) return;
    const int n = dCollide(g1, g2, static_cast<int>(c.buffer.size()), &c.buffer[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
        c.buffer[i].surface = c.surface;
        dJointAttach(dJointCreateContact(c.world, c.contacts, &c.buffer[i]), b1, b2);
    }
}

}  // namespace

void OdePlasticJoints::collide(dSpaceID space, dJointGroupID contacts, const dSurfaceParameters& surface, int max_contacts,
                               const std::function<bool(dBodyID, dBodyID)>& skip) {
    Collision c{*this, world_, contacts, surface, std::vector<dContact>(static_cast<std::size_t>(std::max(1, max_contacts))), skip};
    dSpaceCollide(space, &c, &near_callback);
}

}  // namespace plascap
