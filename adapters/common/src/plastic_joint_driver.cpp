#include "plascap/adapters/plastic_joint_driver.hpp"

namespace plascap {

PlasticJointDriver::PlasticJointDriver(const PlasticJointSettings& settings, RowCapabilities rows)
    : law_(settings, rows) {
    for (Dof dof : kAllDofs) {
        if (law_.mode(dof) == DofMode::Plastic && settings.laws[index(dof)].stiffness) springs_ = true;
    }
}

void PlasticJointDriver::engage(const PerDof<double>& positions, double now) {
    engaged_ = true;
    engaged_positions_ = positions;
    time_ = now;
    law_.start(positions);
}

JointEvent PlasticJointDriver::settle(const PerDof<double>& forces_on_b, const PerDof<double>& positions, double dt,
                                      const PerDof<double>& corrected_motion) {
    time_ += dt;
    if (law_.broken()) return JointEvent::None;
    const double before = law_.plastic_displacement() + law_.plastic_rotation();
    law_.settle(positions, forces_on_b, time_, corrected_motion);
    if (break_if_due() == JointEvent::Broke) return JointEvent::Broke;
    if (law_.plastic_displacement() + law_.plastic_rotation() > before) return JointEvent::Yielded;
    return law_.at_capacity() ? JointEvent::AtCapacity : JointEvent::None;
}

JointEvent PlasticJointDriver::idle(double dt) {
    time_ += dt;
    return law_.broken() ? JointEvent::None : break_if_due();  // a break is reported once
}

JointEvent PlasticJointDriver::break_if_due() {
    if (sever_) law_.sever(time_);
    if (!law_.broken()) return JointEvent::None;
    if (on_break_) (*on_break_)({time_, law_.plastic_displacement(), law_.plastic_rotation(), law_.dissipated()});
    return JointEvent::Broke;
}

}  // namespace plascap
