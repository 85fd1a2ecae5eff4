#pragma once
// The work a joint's rows did on its two bodies, step by step: the rows' forces on each body times
// its mean velocity over the step (impulse_work.hpp). Both adapters note the bodies' velocities when
// a step starts and hand the rows' summed forces when it ends. Set against what the law booked
// (elastic energy and dissipation), it shows what the rows did that the law did not: solver slack in
// rows that should hold, a rigid row stopping a motion at once — or a joint creating energy.
// Off until counting() is asked for (an energy ledger does; a game need not pay for it).
#include <optional>

#include "plascap/adapters/impulse_work.hpp"
#include "plascap/adapters/joint_loads.hpp"

namespace plascap {

class RowsWork {
public:
    void start_counting() { counting_ = true; }
    bool counting() const { return counting_; }
    // The bodies' velocities as the step starts; a is absent when b is joined to the world.
    void step_starts(const BodyVelocity& b, const std::optional<BodyVelocity>& a) {
        if (!counting_) return;
        start_b_ = b;
        start_a_ = a;
        started_ = true;
    }
    // The rows' forces over the step on b and on a (world frame, torques about each body's centre)
    // and the bodies' velocities now. Books nothing without a start.
    void step_ends(const WorldLoad& on_b, const WorldLoad& on_a, const BodyVelocity& b, const std::optional<BodyVelocity>& a,
                   double dt) {
        if (!started_) return;
        total_ += impulse_work(scaled(on_b.force, dt), scaled(on_b.torque_about_com, dt), start_b_, b);
        if (a && start_a_) total_ += impulse_work(scaled(on_a.force, dt), scaled(on_a.torque_about_com, dt), *start_a_, *a);
        started_ = false;
    }
    double total() const { return total_; }  // [J], since the joint took hold

private:
    static Vec3 scaled(const Vec3& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }

    BodyVelocity start_b_;
    std::optional<BodyVelocity> start_a_;
    bool counting_ = false;
    bool started_ = false;
    double total_ = 0.0;
};

}  // namespace plascap
