#include "plascap/sections/neutral_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace plascap {
namespace {

std::vector<double> sorted_vertex_levels(const ValidSection& section, BendingAxis axis) {
    std::vector<double> levels;
    levels.reserve(section.vertex_count());
    for (const Part& part : section.parts()) {
        for (Point p : part.outer) levels.push_back(level_of(p, axis));
        for (const Ring& hole : part.holes)
            for (Point p : hole) levels.push_back(level_of(p, axis));
    }
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    return levels;
}

// Σ fy · chord length at t, for t at an end of [a, b] (no vertex level inside): dF/dt there.
double yield_force_rate(const ValidSection& section, BendingAxis axis, double a, double b, double t) {
    double rate = 0.0;
    for (const Part& part : section.parts()) {
        double chord = chord_length(part.outer, axis, a, b, t);
        for (const Ring& hole : part.holes) chord += chord_length(hole, axis, a, b, t);
        rate += part.material.fy * chord;
    }
    return rate;
}

bool carries_no_force(const ValidSection& section, BendingAxis axis, double a, double b) {
    return yield_force_rate(section, axis, a, b, a) == 0.0 && yield_force_rate(section, axis, a, b, b) == 0.0;
}

// Smallest root u in [0, h] of F0 + w0·u + ½·k·u² = target with F0 <= target, in the form
// u = 2D / (w0 + sqrt(w0² + 2kD)) that has no cancellation (w0 >= 0).
double solve_quadratic_piece(double deficit, double w0, double w1, double h) {
    const double k = (w1 - w0) / h;
    const double discriminant = std::fmax(0.0, w0 * w0 + 2.0 * k * deficit);
    const double denominator = w0 + std::sqrt(discriminant);
    if (denominator <= 0.0) return 0.5 * h;
    return std::clamp(2.0 * deficit / denominator, 0.0, h);
}

}  // namespace

double yield_force(const ValidSection& section, BendingAxis axis, double t, Side side) {
    double force = 0.0;
    for (const Part& part : section.parts()) {
        double area = half_plane_moments(part.outer, axis, t, side).area;
        for (const Ring& hole : part.holes) area += half_plane_moments(hole, axis, t, side).area;
        force += part.material.fy * area;
    }
    return force;
}

double plastic_neutral_axis(const ValidSection& section, BendingAxis axis) {
    const std::vector<double> levels = sorted_vertex_levels(section, axis);
    const double total = yield_force(section, axis, levels.back(), Side::Below);
    const double target = 0.5 * total;

    // Largest lo with F(levels[lo]) <= target; F(levels[0]) = 0 and F(levels.back()) = total.
    std::size_t lo = 0, hi = levels.size() - 1;
    double force_lo = 0.0, force_hi = total;
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        const double force_mid = yield_force(section, axis, levels[mid], Side::Below);
        if (force_mid <= target) {
            lo = mid;
            force_lo = force_mid;
        } else {
            hi = mid;
            force_hi = force_mid;
        }
    }
    const double a = levels[lo], b = levels[hi];
    if (carries_no_force(section, axis, a, b)) return 0.5 * (a + b);  // the axis lies in a gap

    const double w0 = yield_force_rate(section, axis, a, b, a);
    const double w1 = yield_force_rate(section, axis, a, b, b);
    const double t = a + solve_quadratic_piece(target - force_lo, w0, w1, b - a);

    // Landed on the edge of a force-free gap, the two halves equal up to round-off: the axis is
    // not unique there, so take the middle of the gap (a tie-break, not a root-finding tolerance).
    const double round_off = 16.0 * std::numeric_limits<double>::epsilon() * total;
    if (target - force_lo <= round_off && lo > 0 && carries_no_force(section, axis, levels[lo - 1], a))
        return 0.5 * (levels[lo - 1] + a);
    if (force_hi - target <= round_off && hi + 1 < levels.size() &&
        carries_no_force(section, axis, b, levels[hi + 1]))
        return 0.5 * (b + levels[hi + 1]);
    return t;
}

}  // namespace plascap
