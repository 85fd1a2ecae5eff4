#pragma once
// The work a joint's rows did on its two bodies, step by step: the rows' forces on each body times
// its mean velocity over the step (impulse_work.hpp). Both adapters note the bodies' velocities when
// a step starts and hand the rows' summed forces when it ends. Set against what the law booked
// (elastic energy and dissipation), it shows what the rows did that the law did not: solver slack in
// rows that should hold, a rigid row stopping a motion at once — or a joint creating energy.
// Off until counting() is asked for (an energy ledger does; a game need not pay for it).
#include <memory>
#include <optional>

#include "plascap/adapters/impulse_work.hpp"
#include "plascap/adapters/joint_loads.hpp"

namespace plascap {

class RowsWork {
public:
    void start_counting() {
        if (!counting_) counting_ = std::make_unique<Counting>();
    }
    bool counting() const { return counting_ != nullptr; }
    // The bodies' velocities as the step starts; a is absent when b is joined to the world.
    void step_starts(const BodyVelocity& b, const std::optional<BodyVelocity>& a) {
        if (!counting_) return;
        counting_->start_b = b;
        counting_->start_a = a;
        counting_->started = true;
    }
    // The rows' forces over the step on b and on a (world frame, torques about each body's centre)
    // and the bodies' velocities now. Books nothing without a start.
    void step_ends(const WorldLoad& on_b, const WorldLoad& on_a, const BodyVelocity& b, const std::optional<BodyVelocity>& a,
                   double dt) {
        if (!counting_ || !counting_->started) return;
        Counting& c = *counting_;
        c.total += impulse_work(scaled(on_b.force, dt), scaled(on_b.torque_about_com, dt), c.start_b, b);
        if (a && c.start_a) c.total += impulse_work(scaled(on_a.force, dt), scaled(on_a.torque_about_com, dt), *c.start_a, *a);
        c.started = false;
    }
    double total() const { return counting_ ? counting_->total : 0.0; }  // [J], since the joint took hold

private:
    // Held apart, made only when counting starts: a joint that does not count keeps 8 bytes here
    // rather than 120, which a step of 10,000 joints would wait on memory for (issue 16).
    struct Counting {
        BodyVelocity start_b;
        std::optional<BodyVelocity> start_a;
        bool started = false;
        double total = 0.0;
    };
    std::unique_ptr<Counting> counting_;
};

}  // namespace plascap
