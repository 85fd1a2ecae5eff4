#include "plascap/sections/ring_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace plascap {
namespace {

// Coordinates of a point seen from a bending axis: u = level − t, v = the other coordinate.
struct LevelPoint {
    double u;
    double v;
};

// Green's theorem with the level coordinate u and the across coordinate v:
// ∫ dA = σ ∮ v du, where σ = +1 for (v, u) = (x, z) and −1 for (v, u) = (z, x).
double orientation_factor(BendingAxis axis) { return axis == BendingAxis::X ? 1.0 : -1.0; }

LevelPoint to_level(Point p, BendingAxis axis, double t) {
    return axis == BendingAxis::X ? LevelPoint{p.z - t, p.x} : LevelPoint{p.x - t, p.z};
}

// The same with the axis fixed at compile time, for the per-edge loops.
template <BendingAxis Axis>
LevelPoint to_level(Point p, double t) {
    if constexpr (Axis == BendingAxis::X) return {p.z - t, p.x};
    else return {p.x - t, p.z};
}

// 2·∮ v du and 6·∮ v u du along the straight segment a→b (exact for linear v(u)); the factors ½ and
// ⅙ are applied once per ring, not per edge.
void add_segment(LevelPoint a, LevelPoint b, double& twice_area, double& six_moment) {
    const double du = b.u - a.u;
    twice_area += (a.v + b.v) * du;
    six_moment += du * (2.0 * a.v * a.u + a.v * b.u + b.v * a.u + 2.0 * b.v * b.u);
}

// The point of segment a→b where u = 0 (a and b strictly on opposite sides).
LevelPoint crossing(LevelPoint a, LevelPoint b) {
    const double lambda = a.u / (a.u - b.u);
    return {0.0, a.v + lambda * (b.v - a.v)};
}

// i + 1, wrapping to 0: the integer division of (i + 1) % n costs more than an edge's arithmetic.
inline std::size_t next_index(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }

}  // namespace

RingExtent ring_extent(const Ring& ring) {
    RingExtent e{ring[0].x, ring[0].x, ring[0].z, ring[0].z};
    for (Point p : ring) {
        e.min_x = std::min(e.min_x, p.x), e.max_x = std::max(e.max_x, p.x);
        e.min_z = std::min(e.min_z, p.z), e.max_z = std::max(e.max_z, p.z);
    }
    return e;
}

RingMoments ring_moments(const Ring& ring) {
    RingMoments m;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point p = ring[i];
        const Point q = ring[next_index(i, n)];
        const double cross = p.x * q.z - q.x * p.z;
        m.area += cross;
        m.Sx += (p.x + q.x) * cross;
        m.Sz += (p.z + q.z) * cross;
    }
    m.area *= 0.5;
    m.Sx /= 6.0;
    m.Sz /= 6.0;
    return m;
}

namespace {

template <BendingAxis Axis>
LevelCut cut_ring_at(const Ring& ring, double t) {
    constexpr BendingAxis axis = Axis;
    LevelCut cut;
    cut.vertex_below = -std::numeric_limits<double>::infinity();
    cut.vertex_above = std::numeric_limits<double>::infinity();
    double area_below = 0.0, moment_below = 0.0, area_above = 0.0, moment_above = 0.0;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const LevelPoint a = to_level<Axis>(ring[i], t);
        const LevelPoint b = to_level<Axis>(ring[next_index(i, n)], t);
        const double level = a.u + t;
        if (a.u <= 0.0) cut.vertex_below = std::max(cut.vertex_below, level);
        else cut.vertex_above = std::min(cut.vertex_above, level);

        if (a.u <= 0.0 && b.u <= 0.0) {
            add_segment(a, b, area_below, moment_below);
        } else if (a.u >= 0.0 && b.u >= 0.0) {
            add_segment(a, b, area_above, moment_above);
        } else {  // strictly crossing the line
            const LevelPoint c = crossing(a, b);
            if (a.u < 0.0) {
                add_segment(a, c, area_below, moment_below);
                add_segment(c, b, area_above, moment_above);
            } else {
                add_segment(a, c, area_above, moment_above);
                add_segment(c, b, area_below, moment_below);
            }
            // Upward edges bound the chord on one side, downward edges on the other.
            const double direction = b.u > a.u ? 1.0 : -1.0;
            cut.chord += direction * c.v;
            cut.chord_slope += direction * (b.v - a.v) / (b.u - a.u);
        }
    }
    const double sigma = orientation_factor(axis);
    cut.area_below = 0.5 * sigma * area_below;
    cut.area_above = 0.5 * sigma * area_above;
    cut.moment_below = sigma * moment_below / 6.0;
    cut.moment_above = sigma * moment_above / 6.0;
    cut.chord *= sigma;
    cut.chord_slope *= sigma;
    return cut;
}

}  // namespace

LevelCut cut_at(const Ring& ring, BendingAxis axis, double t) {
    return axis == BendingAxis::X ? cut_ring_at<BendingAxis::X>(ring, t) : cut_ring_at<BendingAxis::Z>(ring, t);
}

RingMoments part_moments(const Part& part) {
    RingMoments m = ring_moments(part.outer);
    for (const Ring& hole : part.holes) {
        const RingMoments h = ring_moments(hole);
        m.area += h.area, m.Sx += h.Sx, m.Sz += h.Sz;
    }
    return m;
}

HalfPlaneMoments half_plane_moments(const Ring& ring, BendingAxis axis, double t, Side side) {
    const LevelCut cut = cut_at(ring, axis, t);
    return side == Side::Below ? HalfPlaneMoments{cut.area_below, cut.moment_below}
                               : HalfPlaneMoments{cut.area_above, cut.moment_above};
}

Chords chord_lengths(const Ring& ring, BendingAxis axis, double a, double b) {
    Chords chords;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const LevelPoint p = to_level(ring[i], axis, 0.0);
        const LevelPoint q = to_level(ring[next_index(i, n)], axis, 0.0);
        const double lo = std::fmin(p.u, q.u);
        const double hi = std::fmax(p.u, q.u);
        if (lo == hi || lo > a || hi < b) continue;  // edge does not span [a, b]
        const double slope = (q.v - p.v) / (q.u - p.u);
        const double v_a = p.v + slope * (a - p.u);
        const double v_b = p.v + slope * (b - p.u);
        // Upward edges bound the chord on one side, downward edges on the other.
        chords.at_a += q.u > p.u ? v_a : -v_a;
        chords.at_b += q.u > p.u ? v_b : -v_b;
    }
    chords.at_a *= orientation_factor(axis);
    chords.at_b *= orientation_factor(axis);
    return chords;
}

namespace {

// ln(g1/g0) for g0, g1 > 0. Neighbouring vertices of a fine polygon (an arc's chords) give ratios
// near 1, where ln(g1/g0) = 2·atanh(u), u = (g1 − g0)/(g1 + g0), is a short odd series (Abramowitz &
// Stegun 4.1.27): for |u| < 1/128 the terms to u⁹ leave an error below u¹¹/11 < 1e-22·|u|, i.e. under
// the round-off of either form. Elsewhere std::log. (Profiled: the logarithm was a third of the
// time of all six capacities of a 1,000-vertex polygon.)
double log_ratio_of(double g1, double g0) {
    const double u = (g1 - g0) / (g1 + g0);
    if (std::fabs(u) >= 1.0 / 128) return std::log(g1 / g0);
    const double u2 = u * u;
    return 2.0 * u * (1.0 + u2 * (1.0 / 3 + u2 * (1.0 / 5 + u2 * (1.0 / 7 + u2 * (1.0 / 9)))));
}

}  // namespace

double distance_integral(const Ring& ring, Point c) {
    double sum = 0.0;
    const std::size_t n = ring.size();
    double ax = ring[n - 1].x - c.x, az = ring[n - 1].z - c.z;
    double r0 = std::sqrt(ax * ax + az * az);
    for (std::size_t i = 0; i < n; ++i) {
        const double bx = ring[i].x - c.x, bz = ring[i].z - c.z;
        const double r1 = std::sqrt(bx * bx + bz * bz);
        const double dx = bx - ax, dz = bz - az;
        const double cross = ax * bz - az * bx;  // twice the signed area of the fan triangle
        const double length_squared = dx * dx + dz * dz;
        if (cross != 0.0 && length_squared != 0.0) {  // else: the edge lies on a line through c
            // ∫∫_tri r dA = ∫ ρ(φ)³/3 dφ with ρ = h·sec φ (∫ sec³ = ½(sec·tan + ln(sec + tan))), in s = h·tan φ:
            // (h/6)[s·r + h²·ln(s + r)] between the edge ends, h the distance of c from the edge's line.
            // With the edge's length L, s = dot/L and h = |cross|/L, so that one division per edge, by L³,
            // is left besides the logarithm's (each division or root is a few ns; an edge had five):
            // 6·triangle = |cross|·(L·(dot1·r1 − dot0·r0) + cross²·ln(g1/g0)) / L³, g = s + r.
            const double length = std::sqrt(length_squared);
            const double dot0 = ax * dx + az * dz, dot1 = bx * dx + bz * dz;
            const double cross_squared = cross * cross;
            // L·g as a fraction n/d: dot + r·L, or for s < 0, where that would cancel (r² = s² + h²),
            // L·h²/(r − s) = cross²/(r·L − dot).
            const double n0 = dot0 >= 0.0 ? dot0 + r0 * length : cross_squared, d0 = dot0 >= 0.0 ? 1.0 : r0 * length - dot0;
            const double n1 = dot1 >= 0.0 ? dot1 + r1 * length : cross_squared, d1 = dot1 >= 0.0 ? 1.0 : r1 * length - dot1;
            const double g1_scaled = n1 * d0, g0_scaled = n0 * d1;  // g1/g0 = g1_scaled/g0_scaled
            const double log_ratio = g0_scaled > 0.0 && g1_scaled > 0.0 ? log_ratio_of(g1_scaled, g0_scaled) : 0.0;  // 0 only if cross² underflows
            const double triangle = std::fabs(cross) * (length * (dot1 * r1 - dot0 * r0) + cross_squared * log_ratio) /
                                    (length_squared * length);  // ×6
            sum += cross > 0.0 ? triangle : -triangle;
        }
        ax = bx, az = bz, r0 = r1;
    }
    return sum / 6.0;
}

}  // namespace plascap
