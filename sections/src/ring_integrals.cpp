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

// 2·atanh(u) = ln((1 + u)/(1 − u)) for |u| < 1/128 by its odd series (Abramowitz & Stegun 4.1.27): the
// terms to u⁷ leave an error below u⁹/9 < 2e-18·|u|, under a double's round-off. Written as
// (1 + u²/3) + u⁴·(1/5 + u²/7) so that the two halves are computed side by side.
inline double twice_atanh_small(double u) {
    const double u2 = u * u;
    return 2.0 * u * ((1.0 + u2 * (1.0 / 3)) + (u2 * u2) * (1.0 / 5 + u2 * (1.0 / 7)));
}

constexpr std::size_t edges_per_batch = 64;

// One batch of a ring's edges, with the vertices seen from c: vertex k starts edge k, vertex k + 1 ends it.
struct FanBatch {
    std::size_t edges = 0;
    double x[edges_per_batch + 1], z[edges_per_batch + 1], r[edges_per_batch + 1];
    double g0[edges_per_batch], g1[edges_per_batch];             // g1/g0 = n1·d1⁻¹ / (n0·d0⁻¹), as n1·d0 and n0·d1
    double algebraic[edges_per_batch], weight[edges_per_batch];  // |cross|·L·[dot·r], |cross|·cross²
    double log_ratio[edges_per_batch], scale[edges_per_batch];   // ln(g1/g0), ±1/L³ (0 for a degenerate edge)
};

void load_vertices(const Ring& ring, Point c, std::size_t first, FanBatch& b) {
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k <= b.edges; ++k) {
        const Point p = ring[first + k == 0 ? n - 1 : first + k - 1];
        b.x[k] = p.x - c.x, b.z[k] = p.z - c.z;
    }
    for (std::size_t k = 0; k <= b.edges; ++k) b.r[k] = std::sqrt(b.x[k] * b.x[k] + b.z[k] * b.z[k]);
}

// ∫∫_tri r dA = ∫ ρ(φ)³/3 dφ with ρ = h·sec φ (∫ sec³ = ½(sec·tan + ln(sec + tan))), in s = h·tan φ:
// (h/6)[s·r + h²·ln(s + r)] between the edge ends, h the distance of c from the edge's line. With the
// edge's length L, s = dot/L and h = |cross|/L:
// 6·triangle = |cross|·(L·(dot1·r1 − dot0·r0) + cross²·ln(g1/g0)) / L³, g = s + r.
// Straight-line arithmetic (no branch, no call) so that the compiler does two edges at once.
void edge_terms(FanBatch& b) {
    for (std::size_t k = 0; k < b.edges; ++k) {
        const double ax = b.x[k], az = b.z[k], bx = b.x[k + 1], bz = b.z[k + 1], r0 = b.r[k], r1 = b.r[k + 1];
        const double dx = bx - ax, dz = bz - az;
        const double cross = ax * bz - az * bx;  // twice the signed area of the fan triangle
        const double length_squared = dx * dx + dz * dz;
        const double length = std::sqrt(length_squared);
        const double dot0 = ax * dx + az * dz, dot1 = bx * dx + bz * dz;
        const double cross_squared = cross * cross;
        // L·g as a fraction n/d: dot + r·L, or for s < 0, where that would cancel (r² = s² + h²),
        // L·h²/(r − s) = cross²/(r·L − dot).
        const double n0 = dot0 >= 0.0 ? dot0 + r0 * length : cross_squared, d0 = dot0 >= 0.0 ? 1.0 : r0 * length - dot0;
        const double n1 = dot1 >= 0.0 ? dot1 + r1 * length : cross_squared, d1 = dot1 >= 0.0 ? 1.0 : r1 * length - dot1;
        const double g1 = n1 * d0, g0 = n0 * d1;
        const double magnitude = std::fabs(cross);
        b.g0[k] = g0, b.g1[k] = g1;
        b.algebraic[k] = magnitude * length * (dot1 * r1 - dot0 * r0);
        b.weight[k] = magnitude * cross_squared;
        // Neighbouring vertices of a fine polygon (an arc's chords) give g1/g0 near 1: ln(g1/g0) =
        // 2·atanh(u), u = (g1 − g0)/(g1 + g0); the other edges get std::log afterwards.
        b.log_ratio[k] = twice_atanh_small((g1 - g0) / (g1 + g0));
        // An edge on a line through c (cross = 0, or a repeated vertex) adds nothing.
        const bool degenerate = cross == 0.0 || length_squared == 0.0;
        b.scale[k] = degenerate ? 0.0 : (cross > 0.0 ? 1.0 : -1.0) / (length_squared * length);
    }
}

// ln(g1/g0) where the series does not hold; 0 where cross² underflows (g = 0).
void far_log_ratios(FanBatch& b) {
    for (std::size_t k = 0; k < b.edges; ++k) {
        const double g0 = b.g0[k], g1 = b.g1[k];
        if (std::fabs(g1 - g0) >= (g1 + g0) / 128) b.log_ratio[k] = g0 > 0.0 && g1 > 0.0 ? std::log(g1 / g0) : 0.0;
    }
}

double batch_sum(const FanBatch& b) {
    double sum = 0.0;
    for (std::size_t k = 0; k < b.edges; ++k)
        if (b.scale[k] != 0.0) sum += (b.algebraic[k] + b.weight[k] * b.log_ratio[k]) * b.scale[k];
    return sum;
}

}  // namespace

double distance_integral(const Ring& ring, Point c) {
    // The edges go in batches, so that the per-edge arithmetic runs two edges at a time: My of a
    // 1,000-gon 10.2 → 7.6 µs against the edge-by-edge loop (docs/exact-route.md, "Cost").
    FanBatch batch;
    double sum = 0.0;
    for (std::size_t first = 0; first < ring.size(); first += edges_per_batch) {
        batch.edges = std::min(edges_per_batch, ring.size() - first);
        load_vertices(ring, c, first, batch);
        edge_terms(batch);
        far_log_ratios(batch);
        sum += batch_sum(batch);
    }
    return sum / 6.0;
}

}  // namespace plascap
