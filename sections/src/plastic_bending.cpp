#include "plascap/sections/plastic_bending.hpp"

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

// The whole section cut at level t, yield-force weighted.
struct SectionCut {
    double force_below = 0.0;  // F(t) = Σ fy·A_below [N]
    double force_above = 0.0;  // N − F(t)
    double moment = 0.0;       // ∫ fy·|level − t| dA [N·m]
    double rate = 0.0;         // dF/dt = Σ fy·chord (edges strictly crossing t)
    double rate_slope = 0.0;   // d²F/dt²
    double a = -std::numeric_limits<double>::infinity();  // largest vertex level <= t
    double b = std::numeric_limits<double>::infinity();   // smallest vertex level > t
};

SectionCut cut_section(const ValidSection& section, BendingAxis axis, double t) {
    SectionCut s;
    for_each_ring(section, [&](const Ring& ring, double fy) {
        const LevelCut c = cut_at(ring, axis, t);
        s.force_below += fy * c.area_below;
        s.force_above += fy * c.area_above;
        s.moment += fy * (c.moment_above - c.moment_below);  // both sides positive: no cancellation
        s.rate += fy * c.chord;
        s.rate_slope += fy * c.chord_slope;
        s.a = std::max(s.a, c.vertex_below);
        s.b = std::min(s.b, c.vertex_above);
    });
    return s;
}

// F' and F'' on the piece [a, b] when t = a is itself a vertex level (the edges ending at t do not
// cross it strictly, so the cut cannot see them): from the chord lengths at both ends.
void rates_from_piece_ends(const ValidSection& section, BendingAxis axis, SectionCut& cut) {
    double at_a = 0.0, at_b = 0.0;
    for_each_ring(section, [&](const Ring& ring, double fy) {
        const Chords c = chord_lengths(ring, axis, cut.a, cut.b);
        at_a += fy * c.at_a;
        at_b += fy * c.at_b;
    });
    cut.rate = at_a;
    cut.rate_slope = (at_b - at_a) / (cut.b - cut.a);
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
        const RingMoments m = part_moments(part);
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

// Where the root can still be, and how fast that interval shrinks.
struct Bracket {
    double lo, hi;
    double width;     // hi − lo before the last missed step
    int missed_steps;

    // The next t after a step that missed its piece: the quadratic's root, except that (as in
    // Numerical Recipes' rtsafe) from the third miss on, a step that did not halve the bracket is
    // followed by bisection, so the search needs O(log) steps even where quadratics extrapolate badly.
    double next_guess(double candidate) {
        const bool slow = ++missed_steps > 2 && hi - lo > 0.5 * width;
        width = hi - lo;
        return slow || !std::isfinite(candidate) ? 0.5 * (lo + hi) : candidate;
    }
};

PlasticBending at_level(const ValidSection& section, BendingAxis axis, double t) {
    return {t, cut_section(section, axis, t).moment};
}

}  // namespace

double yield_force(const ValidSection& section, BendingAxis axis, double t, Side side) {
    const SectionCut cut = cut_section(section, axis, t);
    return side == Side::Below ? cut.force_below : cut.force_above;
}

PlasticBending plastic_bending(const ValidSection& section, BendingAxis axis) {
    const std::vector<PartSummary> parts = summarize_parts(section, axis);
    double lo = parts[0].lo, hi = parts[0].hi, total = 0.0, force_moment = 0.0;
    for (const PartSummary& part : parts) {
        lo = std::min(lo, part.lo), hi = std::max(hi, part.hi);
        total += part.force, force_moment += part.force_moment;
    }
    if (const std::optional<double> gap = middle_of_balanced_gap(parts, total)) return at_level(section, axis, *gap);

    double t = force_moment / total;  // force-weighted centroid: exact for doubly symmetric sections
    Bracket bracket{lo, hi, hi - lo, 0};
    for (;;) {
        if (!(t > bracket.lo && t < bracket.hi)) {
            t = 0.5 * (bracket.lo + bracket.hi);
            // The bracket has closed on a vertex level: the root is there, up to round-off.
            if (!(t > bracket.lo && t < bracket.hi)) return at_level(section, axis, t);
        }
        SectionCut cut = cut_section(section, axis, t);
        if (cut.a == t) rates_from_piece_ends(section, axis, cut);
        const double w = cut.rate, k = cut.rate_slope;
        // Half the force imbalance: F(s) − N/2 = 0 at the root, F(t) − N/2 = −deficit.
        const double deficit = 0.5 * (cut.force_above - cut.force_below);
        double step;  // signed distance from t to the root of this piece's quadratic
        if (deficit >= 0.0) {
            step = step_to_target(deficit, w, k);  // F(t) + w·u + ½k·u² = N/2
            if (!(step <= cut.b - t)) {
                bracket.lo = cut.b;
                t = bracket.next_guess(t + step);
                continue;
            }
        } else {
            step = -step_to_target(-deficit, w, -k);  // F(t) − w·v + ½k·v² = N/2
            if (!(-step <= t - cut.a)) {
                bracket.hi = cut.a;
                t = bracket.next_guess(t + step);
                continue;
            }
        }
        // M(t + Δ) = M(t) + ∫_0^Δ (F_below − F_above)(t + δ) dδ, with F_below − F_above = −2·deficit + 2wδ + kδ².
        const double moment = cut.moment - 2.0 * deficit * step + w * step * step + k * step * step * step / 3.0;
        return {t + step, moment};
    }
}

}  // namespace plascap
