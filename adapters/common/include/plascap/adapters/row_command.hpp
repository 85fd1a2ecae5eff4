#pragma once
// What a plastic dof's constraint row must do during the next step, in engine-neutral terms.
// Forces are generalised forces on body b in the dof's positive direction [N or N·m].
namespace plascap {

struct RowCommand {
    enum class Kind {
        // Rigid-plastic (paper §2, "target velocity 0, impulse bounded by capacity × dt"): drive the
        // dof's velocity to `velocity` using at most `bound` in either direction. `velocity` is 0
        // but for a Baumgarte correction back to the plastic offset of motion the solver let
        // through below capacity.
        Hold,
        // Elastic-plastic: apply exactly `force` (the capped spring force) this step.
        Push,
    };
    Kind kind = Kind::Hold;
    double bound = 0.0;     // Hold: largest force magnitude, ≥ 0, for a row with one symmetric bound
    double lower = 0.0;     // Hold: the force range, lower ≤ 0 ≤ upper, for a row with two bounds
    double upper = 0.0;     //   (RowCapabilities::two_sided_bounds); the law books flow on either
    double velocity = 0.0;  // Hold: target rate of the dof [m/s | rad/s]
    double force = 0.0;  // Push: signed force, |force| ≤ the capacity on its side
};

}  // namespace plascap
