#pragma once
// The work an impulse did on a rigid body in one step, from the body's velocities at the step's start
// and end. For v1 = v0 + P/m the body's kinetic energy changes by ½m(v1² − v0²) = P·(v0 + v1)/2 (the
// work–energy theorem for an impulse, e.g. Brach, "Mechanical Impact Dynamics", 2007, ch. 3), and
// likewise by L·(ω0 + ω1)/2 for an angular impulse L at a constant inertia. Summed over every impulse
// on the body (gravity's, the loads', each constraint's), these shares add up to the change exactly
// (linearly; the angular part as far as the inertia turns little within the step), so each
// constraint's share is its own work: the contacts' in the energy ledger (docs/structures.md).
#include "plascap/adapters/vec3.hpp"

namespace plascap {

struct BodyVelocity {
    Vec3 linear{};   // of the centre of mass [m/s]
    Vec3 angular{};  // [rad/s]
};

// impulse [N·s] through the centre of mass, angular_impulse [N·m·s] about it; the work [J].
inline double impulse_work(const Vec3& impulse, const Vec3& angular_impulse, const BodyVelocity& start,
                           const BodyVelocity& end) {
    double work = 0.0;
    for (int i = 0; i < 3; ++i)
        work += 0.5 * (impulse[i] * (start.linear[i] + end.linear[i]) + angular_impulse[i] * (start.angular[i] + end.angular[i]));
    return work;
}

}  // namespace plascap
