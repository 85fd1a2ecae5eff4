#include "plascap/sections/ring_integrals.hpp"

#include <cmath>
#include <cstddef>

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

// ∮ v du and ∮ v u du along the straight segment a→b (exact for linear v(u)).
void add_segment(LevelPoint a, LevelPoint b, double& area, double& moment) {
    const double du = b.u - a.u;
    area += 0.5 * (a.v + b.v) * du;
    moment += du * (2.0 * a.v * a.u + a.v * b.u + b.v * a.u + 2.0 * b.v * b.u) / 6.0;
}

// The point of segment a→b where u = 0 (a and b strictly on opposite sides).
LevelPoint crossing(LevelPoint a, LevelPoint b) {
    const double lambda = a.u / (a.u - b.u);
    return {0.0, a.v + lambda * (b.v - a.v)};
}

}  // namespace

RingMoments ring_moments(const Ring& ring) {
    RingMoments m;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point p = ring[i];
        const Point q = ring[(i + 1) % n];
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

HalfPlaneMoments half_plane_moments(const Ring& ring, BendingAxis axis, double t, Side side) {
    // Flip u for the upper side so that "kept" is always u <= 0; flip the results back.
    const double flip = side == Side::Below ? 1.0 : -1.0;
    double area = 0.0;
    double moment = 0.0;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        LevelPoint a = to_level(ring[i], axis, t);
        LevelPoint b = to_level(ring[(i + 1) % n], axis, t);
        a.u *= flip;
        b.u *= flip;
        if (a.u <= 0.0 && b.u <= 0.0) {
            add_segment(a, b, area, moment);
        } else if (a.u < 0.0) {
            add_segment(a, crossing(a, b), area, moment);
        } else if (b.u < 0.0) {
            add_segment(crossing(a, b), b, area, moment);
        }
    }
    // With u flipped, ∮ v du and ∮ v u du change sign and sign respectively:
    // area = σ·flip·∮ v du', first moment = σ·∮ v u' du' (u = flip·u').
    const double sigma = orientation_factor(axis);
    return {sigma * flip * area, sigma * moment};
}

double chord_length(const Ring& ring, BendingAxis axis, double a, double b, double t) {
    double length = 0.0;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const LevelPoint p = to_level(ring[i], axis, 0.0);
        const LevelPoint q = to_level(ring[(i + 1) % n], axis, 0.0);
        const double lo = std::fmin(p.u, q.u);
        const double hi = std::fmax(p.u, q.u);
        if (lo == hi || lo > a || hi < b) continue;  // edge does not span [a, b]
        const double v = p.v + (q.v - p.v) * ((t - p.u) / (q.u - p.u));
        length += q.u > p.u ? v : -v;  // upward edges bound the chord on one side, downward on the other
    }
    return orientation_factor(axis) * length;
}

double distance_integral(const Ring& ring, Point c) {
    double sum = 0.0;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double ax = ring[i].x - c.x, az = ring[i].z - c.z;
        const Point q = ring[(i + 1) % n];
        const double bx = q.x - c.x, bz = q.z - c.z;
        const double dx = bx - ax, dz = bz - az;
        const double length = std::hypot(dx, dz);
        const double cross = ax * bz - az * bx;  // twice the signed area of the fan triangle
        if (length == 0.0 || cross == 0.0) continue;  // edge on a line through c: zero area
        const double h = std::fabs(cross) / length;
        const double s0 = (ax * dx + az * dz) / length;
        const double s1 = (bx * dx + bz * dz) / length;
        const double r0 = std::hypot(ax, az);
        const double r1 = std::hypot(bx, bz);
        // ∫∫_tri r dA = ∫ ρ(φ)³/3 dφ with ρ = h·sec φ, written with s = h·tan φ and asinh(s/h) = ln((s + r)/h).
        const double triangle = h / 6.0 * (s1 * r1 - s0 * r0 + h * h * (std::asinh(s1 / h) - std::asinh(s0 / h)));
        sum += cross > 0.0 ? triangle : -triangle;
    }
    return sum;
}

}  // namespace plascap
