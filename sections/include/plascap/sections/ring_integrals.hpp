#pragma once
// Exact integrals over one polygon ring by Green's theorem, signed by orientation
// (counter-clockwise positive, so a clockwise hole subtracts). All closed forms, no quadrature.
#include "plascap/sections/geometry.hpp"

namespace plascap {

// Which bending moment: Mx bends about x, so its stress varies with z and its plastic neutral
// axis is a line z = const; Mz bends about z, stress varies with x, neutral axis x = const.
enum class BendingAxis { X, Z };

// The coordinate the bending stress varies with ("level"): z for BendingAxis::X, x for Z.
inline double level_of(Point p, BendingAxis axis) { return axis == BendingAxis::X ? p.z : p.x; }

struct RingMoments {
    double area = 0.0;  // ∫ dA        [m²]
    double Sx = 0.0;    // ∫ x dA      [m³]
    double Sz = 0.0;    // ∫ z dA      [m³]
};

// The axis-aligned box around a ring [m].
struct RingExtent {
    double min_x, max_x, min_z, max_z;
};
RingExtent ring_extent(const Ring& ring);

// Area and first moments (shoelace / Green's theorem, e.g. Steger, "On the calculation of
// arbitrary moments of polygons", 1996).
RingMoments ring_moments(const Ring& ring);

// The same over a validated part: its outer ring (counter-clockwise) plus its holes (clockwise, so
// they subtract).
RingMoments part_moments(const Part& part);

// The ring seen from the line level = t: what lies below and above it, and how the line cuts it.
// By Green's theorem the cut along the line adds nothing to either side (d(level) = 0 on it), so
// every integral is a sum over the ring's edges clipped to one side, each exact.
struct LevelCut {
    double area_below = 0.0;
    double area_above = 0.0;
    double moment_below = 0.0;  // ∫ (level − t) dA below the line (<= 0)
    double moment_above = 0.0;  // ∫ (level − t) dA above the line (>= 0)
    double chord = 0.0;         // length of the line inside the ring, from the edges strictly crossing it
    double chord_slope = 0.0;   // d(chord)/dt from the same edges (exact while t stays between vertex levels)
    double vertex_below;        // largest vertex level <= t (−inf if none)
    double vertex_above;        // smallest vertex level > t (+inf if none)
};

LevelCut cut_at(const Ring& ring, BendingAxis axis, double t);

enum class Side { Below, Above };

struct HalfPlaneMoments {
    double area = 0.0;          // ∫ dA over the part of the ring on `side` of the line
    double first_moment = 0.0;  // ∫ (level − t) dA over the same part (negative below, positive above)
};

// One side of cut_at().
HalfPlaneMoments half_plane_moments(const Ring& ring, BendingAxis axis, double t, Side side);

// d/dt of the area below level t — the chord length of the ring on the line — at both ends of
// [a, b], where no vertex level lies strictly inside (a, b) so the chord is linear in t. Exact:
// evaluated from the edges spanning the interval.
struct Chords {
    double at_a = 0.0;
    double at_b = 0.0;
};
Chords chord_lengths(const Ring& ring, BendingAxis axis, double a, double b);

// ∫ |p − c| dA: the paper's eq. 2.14 integral about the joint point c, by the per-edge closed form
// of the triangle fan from c: ∫∫_tri r dA = (h/6)[s r + h² asinh(s/h)] evaluated between the edge
// ends, h the edge line's distance from c and s the position along it (∫ sec³).
double distance_integral(const Ring& ring, Point c);

}  // namespace plascap
