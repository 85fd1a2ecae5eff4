#pragma once
// A polygon whose corners may be rounded by circular arcs, and its discretisation into a Ring.
//
// Each corner P_i with radius r > 0 becomes an arc tangent to both adjacent edges: with the
// turning angle φ between the incoming and outgoing edge, the tangent points lie r·tan(φ/2) from
// P_i and the arc sweeps φ (elementary geometry of a fillet, e.g. Oberg et al., Machinery's
// Handbook, "Fillets").
//
// Exact area of the rounded polygon (signed, counter-clockwise positive): the sharp polygon's
// shoelace area, minus r²·(tan(φ/2) − φ/2) at every left turn (the rounding cuts the corner off)
// and plus it at every right turn (the rounding fills the corner).
//
// Discretisation: n chords inscribed in an arc of radius r and angle φ miss the area
// n·(r²/2)·(θ − sin θ), θ = φ/n, the area of n circular segments; n is the smallest count that
// keeps this below the arc's area budget. The error falls as n⁻² (θ − sin θ ≈ θ³/6).
#include <cstddef>
#include <string>
#include <vector>

#include "plascap/sections/geometry.hpp"

namespace plascap {

struct RoundedCorner {
    Point at;                // the sharp corner [m]
    double radius = 0.0;     // fillet radius [m]; 0: a sharp corner
    std::string name = "";   // what the radius is called, for messages ("root radius r")
};

using RoundedRing = std::vector<RoundedCorner>;

// Exact signed area of the rounded polygon [m²].
double rounded_signed_area(const RoundedRing& ring);

// The rounded corners (arcs) in the ring.
std::size_t arc_count(const RoundedRing& ring);

// Area one arc of radius r and angle φ misses when it is drawn with n inscribed chords [m²].
double chord_area_error(double radius, double angle, std::size_t chords);

// The ring with every arc replaced by the fewest inscribed chords whose missing area is at most
// `area_budget_per_arc` [m²]. Throws InputError naming the corner's radius when two tangent points
// on one edge overlap (the radius does not fit), or when a corner is straight (no turn) but rounded.
Ring discretise(const RoundedRing& ring, double area_budget_per_arc);

// Total area missed by discretise() with that budget [m²] (the sum over the arcs, each exact).
double discretisation_area_error(const RoundedRing& ring, double area_budget_per_arc);

}  // namespace plascap
