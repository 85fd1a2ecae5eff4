#pragma once
// The plastic neutral axis: the line of constant level (z for Mx, x for Mz) with equal yield
// force on both sides, Σ fy·A_below(t) = N/2 (../shared/DESIGN.md, "Capacity definitions").
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

// Yield force Σ fy·A on the side of the line level = t [N] (local coordinates).
double yield_force(const ValidSection& section, BendingAxis axis, double t, Side side);

// Level of the plastic neutral axis in local coordinates. F(t) = Σ fy·A_below(t) is piecewise
// quadratic in t, with breaks at vertex levels. Starting at the force-weighted centroid, each step
// evaluates F at t, finds the piece [a, b] around t (the nearest vertex levels) and its quadratic
// from the chord lengths at a and b, and solves that quadratic in closed form; if the root lies
// outside the piece, the bracket shrinks past it and the next t is the quadratic's root (or the
// bracket's middle). The answer is the exact root of the exact quadratic of its piece, no tolerance.
// Where the axis is not unique (a force-free gap between parts with equal force on both sides), the
// middle of the gap is returned; Mx is the same anywhere in it. Cost: a few passes over the edges.
double plastic_neutral_axis(const ValidSection& section, BendingAxis axis);

}  // namespace plascap
