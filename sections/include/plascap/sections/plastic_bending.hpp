#pragma once
// Fully plastic bending: the plastic neutral axis — the line of constant level (z for Mx, x for Mz)
// with equal yield force on both sides, Σ fy·A_below(t) = N/2 — and the plastic moment about it,
// ∫ fy·|level − t| dA (paper eqs. 2.12, 2.13; ../shared/DESIGN.md, "Capacity definitions").
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

struct PlasticBending {
    double axis = 0.0;    // level of the plastic neutral axis, local coordinates [m]
    double moment = 0.0;  // ∫ fy·|level − axis| dA [N·m]
};

// F(t) = Σ fy·A_below(t) is piecewise quadratic in t, with breaks at vertex levels. Starting at the
// force-weighted centroid, each step cuts the section at t (one pass over the edges: F(t), the
// chord and its slope, the nearest vertex levels a <= t < b, the moment about t), which gives F on
// [a, b] exactly, and solves that quadratic in closed form. If the root lies outside [a, b] the
// bracket shrinks past the piece and the next t is the quadratic's root (or the bracket's middle).
// The answer is the exact root of the exact quadratic of its piece: no tolerance decides the end.
// The moment follows from the one about t: M(s) = M(t) + ∫_t^s (2F − N) dt', exact on the piece.
// Where the axis is not unique (a force-free gap between parts with equal force on both sides), the
// middle of the gap is returned; the moment is the same anywhere in it.
PlasticBending plastic_bending(const ValidSection& section, BendingAxis axis);

// Yield force Σ fy·A on one side of the line level = t [N] (local coordinates).
double yield_force(const ValidSection& section, BendingAxis axis, double t, Side side);

}  // namespace plascap
