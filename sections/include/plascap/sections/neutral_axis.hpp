#pragma once
// The plastic neutral axis: the line of constant level (z for Mx, x for Mz) with equal yield
// force on both sides, Σ fy·A_below(t) = N/2 (../shared/DESIGN.md, "Capacity definitions").
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

// Yield force Σ fy·A on the side of the line level = t [N] (local coordinates).
double yield_force(const ValidSection& section, BendingAxis axis, double t, Side side);

// Level of the plastic neutral axis in local coordinates. F(t) = Σ fy·A_below(t) is piecewise
// quadratic in t with breaks at vertex levels: bisect over the sorted vertex levels for the
// bracketing piece, then solve its quadratic in closed form. Where the axis is not unique (a gap
// between parts carries no force), the middle of the gap is returned; Mx is the same anywhere in it.
// Cost: O(n log n) for n vertices.
double plastic_neutral_axis(const ValidSection& section, BendingAxis axis);

}  // namespace plascap
