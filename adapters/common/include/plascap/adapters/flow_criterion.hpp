#pragma once
// Whether a rigid-plastic row's motion at its bound is plastic flow or the slack of an unconverged
// solve (issue 20).
//
// Bullet's and ODE's iterative solvers (projected Gauss–Seidel, stopped after a fixed number of
// iterations) leave each row's force off the converged one by an error that changes from step to
// step. A compact body on a long lever couples its rows strongly, and ODE's QuickStep, which starts
// every row from zero, then leaves them ±10 % off at 50 iterations: a row loaded to 0.9 of its
// capacity touches its bound in many steps, and booking each touch as flow ratchets the joint.
// Over several steps, though, the row's mean force is the load it carries (momentum balance: a body
// that does not accelerate on average is held, on average, by exactly its load). So a row at its
// bound flows when
//   - its mean share of the bound (an exponential mean, each step weighing kMeanShareWeight) has
//     reached kConfirmedShare on that side: a sustained load at capacity; or
//   - the motion the step let through would take more than kBeyondNoise of the bound to stop in one
//     step, m·|Δx|/dt² with m the row's effective mass (row_effective_mass.hpp): an impact;
//   - or it flowed in the step before and is still at its bound on that side.
// Otherwise the motion is the solver's: the hold pulls it back. The consecutive steps at the bound
// before a flow is confirmed are booked with it (their motion and the row's work on it), so a slow
// overload, whose mean takes about 40 steps from rest to reach kConfirmedShare, loses nothing.
// Limits (docs/adapters.md): m is the row's own effective mass, not the larger one the body has
// through the joint's other rows or contacts, so an impact through a lever or a contact must move
// the dof further before it counts; and at few iterations (ODE's QuickStep below about 30) the
// noise can keep a real, marginal overload's mean below kConfirmedShare.
#include <cmath>

namespace plascap {

// A row counts as at its bound above this share of it (the solvers clamp to the bound exactly;
// rotations read back through non-orthogonal Euler axes need the margin).
inline constexpr double kAtCapacity = 0.99;
// Weight of each step in the row's exponential mean share (a mean over about 10 steps).
inline constexpr double kMeanShareWeight = 0.1;
// The mean share of the bound (on the side loaded) from which motion at the bound is flow.
inline constexpr double kConfirmedShare = 0.985;
// The share of the bound from which a step's motion is no solver slack (at 50 iterations the slack
// of the issue-20 block is below 0.01).
inline constexpr double kBeyondNoise = 0.05;

class FlowCriterion {
public:
    // After a step: the row's force as a signed share of its bound on that side (±1 at the bound),
    // and the share of the bound it would take to stop, in one step, the motion the step let
    // through. True when the row flowed in the step.
    // Inline: every rigid-plastic dof asks every step (issue 16).
    bool flowed(double share, double stopping_share) {
        mean_share_ += kMeanShareWeight * (share - mean_share_);  // exponential moving mean
        last_share_ = share;
        const bool continues = flowing_ * share > 0.0;  // the step before flowed, on this side
        const bool sustained = std::abs(mean_share_) >= kConfirmedShare && mean_share_ * share > 0.0;
        const bool beyond_noise = stopping_share >= kBeyondNoise;
        flowing_ = at_bound() && (continues || sustained || beyond_noise) ? share : 0.0;
        return flowing_ != 0.0;
    }

    double last_share() const { return last_share_; }                      // of the last step
    bool at_bound() const { return std::abs(last_share_) >= kAtCapacity; }  // in the last step

private:
    double mean_share_ = 0.0;
    double flowing_ = 0.0;  // the share of the last step if it flowed, else 0
    double last_share_ = 0.0;
};

}  // namespace plascap
