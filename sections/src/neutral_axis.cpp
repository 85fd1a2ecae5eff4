#include "plascap/sections/neutral_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace plascap {
namespace {

template <class Visit>
void for_each_ring(const ValidSection& section, Visit visit) {
    for (const Part& part : section.parts()) {
        visit(part.outer, part.material.fy);
        for (const Ring& hole : part.holes) visit(hole, part.material.fy);
    }
}

// What one pass over the edges tells about the line level = t.
struct Probe {
    double force_below = 0.0;                             // F(t) = Σ fy·A_below(t)
    double a = -std::numeric_limits<double>::infinity();  // largest vertex level <= t
    double b = std::numeric_limits<double>::infinity();   // smallest vertex level > t
};

Probe probe(const ValidSection& section, BendingAxis axis, double t) {
    Probe p;
    for_each_ring(section, [&](const Ring& ring, double fy) {
        p.force_below += fy * half_plane_moments(ring, axis, t, Side::Below).area;
        for (Point q : ring) {
            const double level = level_of(q, axis);
            if (level <= t) p.a = std::max(p.a, level);
            else p.b = std::min(p.b, level);
        }
    });
    return p;
}

// dF/dt = Σ fy·chord at t = a and t = b, for the piece [a, b] (no vertex level strictly inside).
Chords force_rates(const ValidSection& section, BendingAxis axis, double a, double b) {
    Chords rates;
    for_each_ring(section, [&](const Ring& ring, double fy) {
        const Chords c = chord_lengths(ring, axis, a, b);
        rates.at_a += fy * c.at_a;
        rates.at_b += fy * c.at_b;
    });
    return rates;
}

// Smallest u >= 0 with w·u + ½·k·u² = deficit (deficit >= 0, w >= 0 on a force piece), written
// u = 2·deficit / (w + √(w² + 2·k·deficit)) so that nothing cancels (Numerical Recipes §5.6).
double step_to_target(double deficit, double w, double k) {
    w = std::max(w, 0.0);
    const double denominator = w + std::sqrt(std::max(0.0, w * w + 2.0 * k * deficit));
    return denominator > 0.0 ? 2.0 * deficit / denominator : std::numeric_limits<double>::infinity();
}

// Per part: level range of the outer ring, force fy·A and force moment fy·∫level dA.
struct PartSummary {
    double lo, hi;
    double force;
    double force_moment;
};

std::vector<PartSummary> summarize_parts(const ValidSection& section, BendingAxis axis) {
    std::vector<PartSummary> parts;
    for (const Part& part : section.parts()) {
        PartSummary s{level_of(part.outer[0], axis), level_of(part.outer[0], axis), 0.0, 0.0};
        for (Point q : part.outer) s.lo = std::min(s.lo, level_of(q, axis)), s.hi = std::max(s.hi, level_of(q, axis));
        RingMoments m = ring_moments(part.outer);
        for (const Ring& hole : part.holes) {
            const RingMoments h = ring_moments(hole);
            m.area += h.area, m.Sx += h.Sx, m.Sz += h.Sz;
        }
        s.force = part.material.fy * m.area;
        s.force_moment = part.material.fy * (axis == BendingAxis::X ? m.Sz : m.Sx);
        parts.push_back(s);
    }
    return parts;
}

// The axis is not unique when the parts split into a lower and an upper group, apart from each
// other, with equal force up to round-off: then it is the middle of the gap between the groups.
std::optional<double> middle_of_balanced_gap(std::vector<PartSummary> parts, double total) {
    std::sort(parts.begin(), parts.end(), [](const PartSummary& x, const PartSummary& y) { return x.lo < y.lo; });
    const double round_off = 16.0 * std::numeric_limits<double>::epsilon() * total;
    double force_below = 0.0, top = parts[0].lo;
    for (const PartSummary& part : parts) {
        if (part.lo > top && std::fabs(force_below - 0.5 * total) <= round_off) return 0.5 * (top + part.lo);
        force_below += part.force;
        top = std::max(top, part.hi);
    }
    return std::nullopt;
}

}  // namespace

double yield_force(const ValidSection& section, BendingAxis axis, double t, Side side) {
    double force = 0.0;
    for_each_ring(section, [&](const Ring& ring, double fy) { force += fy * half_plane_moments(ring, axis, t, side).area; });
    return force;
}

double plastic_neutral_axis(const ValidSection& section, BendingAxis axis) {
    const std::vector<PartSummary> parts = summarize_parts(section, axis);
    double lo = parts[0].lo, hi = parts[0].hi, total = 0.0, force_moment = 0.0;
    for (const PartSummary& part : parts) {
        lo = std::min(lo, part.lo), hi = std::max(hi, part.hi);
        total += part.force, force_moment += part.force_moment;
    }
    const double target = 0.5 * total;
    if (const std::optional<double> gap = middle_of_balanced_gap(parts, total)) return *gap;

    double t = force_moment / total;  // force-weighted centroid: exact for doubly symmetric sections
    for (;;) {
        if (!(t > lo && t < hi)) {
            t = 0.5 * (lo + hi);
            // The bracket has closed on a vertex level: the root is there, up to round-off.
            if (!(t > lo && t < hi)) return t;
        }
        const Probe p = probe(section, axis, t);
        const Chords w = force_rates(section, axis, p.a, p.b);
        const double k = (w.at_b - w.at_a) / (p.b - p.a);  // F'' on the piece
        const double w_t = w.at_a + k * (t - p.a);         // F'(t)
        if (p.force_below <= target) {
            // Root at t + u with F(t) + w_t·u + ½k·u² = target; inside the piece unless u > b − t.
            const double u = step_to_target(target - p.force_below, w_t, k);
            if (u <= p.b - t) return t + u;
            lo = p.b;
            t = std::isfinite(u) ? t + u : 0.5 * (lo + hi);
        } else {
            // Root at t − v with F(t) − w_t·v + ½k·v² = target.
            const double v = step_to_target(p.force_below - target, w_t, -k);
            if (v <= t - p.a) return t - v;
            hi = p.a;
            t = std::isfinite(v) ? t - v : 0.5 * (lo + hi);
        }
    }
}

}  // namespace plascap
