#pragma once
// Fully plastic bending: the plastic neutral axis — the line of constant level (z for Mx, x for Mz)
// with equal yield force on both sides, Σ fy·A_below(t) = N/2 — and the plastic moment about it,
// ∫ fy·|level − t| dA (paper eqs. 2.12, 2.13; README, "What it computes").
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

// Which side of the axis is in tension (fy); the other is in compression (fc). With
// fc = fy the two give the same axis and moment.
enum class TensionSide { Below, Above };

// The sign convention of capacities.hpp: Mx puts z < z_pna in tension, Mz puts x > x_pna in
// tension (Mx = −∫z·σ dA, Mz = ∫x·σ dA); the _neg capacities (negative = true) the opposite.
inline TensionSide tension_side(BendingAxis axis, bool negative) {
    const bool below = (axis == BendingAxis::X) != negative;
    return below ? TensionSide::Below : TensionSide::Above;
}

struct PlasticBending {
    double axis = 0.0;    // level of the plastic neutral axis, local coordinates [m]
    double moment = 0.0;  // ∫ s·|level − axis| dA, s = fy on the tension side, fc on the other [N·m]
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
// With fc ≠ fy: the equal-force axis Σ fy·A(tension side) = Σ fc·A(compression side); F stays
// piecewise quadratic (areas are), so the same solve applies, with the mean strength in the rates.
PlasticBending plastic_bending(const ValidSection& section, BendingAxis axis, TensionSide tension);

// Yield force on one side of the line level = t [N] (local coordinates): Σ fy·A on the tension
// side, Σ fc·A on the other.
double yield_force(const ValidSection& section, BendingAxis axis, TensionSide tension, double t, Side side);

}  // namespace plascap
