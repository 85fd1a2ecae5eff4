#include "plascap/adapters/ode_plastic_joints.hpp"

#include <algorithm>

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
        const bool was_broken = e.joint->law().broken();
        e.joint->after_step(dt);
        if (!was_broken && e.joint->law().broken() && e.joint->body_a())
            joined_.erase(joined_.find(std::minmax(e.joint->body_a(), e.joint->body_b())));
    }
    time_ += dt;
}

bool OdePlasticJoints::joined(dBodyID a, dBodyID b) const { return joined_.count(std::minmax(a, b)) > 0; }

}  // namespace plascap
