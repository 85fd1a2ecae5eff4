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

PerDof<std::optional<RowCommand>> PlasticJointDriver::plan_with_masses(const JointFrameState& state,
                                                                       const Vec3& centre_of_b, double dt,
                                                                       const PerDof<double>& effective_masses) {
    planned_axes_ = state.axes;
    planned_centre_of_b_ = centre_of_b;
    return law_.plan(state.positions, dt, effective_masses);
}

JointEvent PlasticJointDriver::settle(const WorldLoad& on_b, const PerDof<double>& positions, double dt,
                                      const PerDof<double>& corrected_motion) {
    time_ += dt;
    if (law_.broken()) return JointEvent::None;
    forces_ = joint_frame_loads(on_b, planned_centre_of_b_, planned_axes_);
    const double before = law_.plastic_displacement() + law_.plastic_rotation();
    law_.settle(positions, forces_, time_, corrected_motion);
    if (sever_) law_.sever(time_);
    if (law_.broken()) {
        if (on_break_)
            on_break_({time_, law_.plastic_displacement(), law_.plastic_rotation(), law_.dissipated()});
        return JointEvent::Broke;
    }
    if (law_.plastic_displacement() + law_.plastic_rotation() > before) return JointEvent::Yielded;
    return law_.at_capacity() ? JointEvent::AtCapacity : JointEvent::None;
}

}  // namespace plascap
