#include "plascap/sections/plastic_bending.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace plascap {
namespace {

// The strengths that act below and above the axis: tension fy on the tension side, compression
// fc on the other.
struct Strengths {
    double below = 0.0, above = 0.0;  // [Pa]
    double mean() const { return 0.5 * (below + above); }
};

Strengths strengths_of(const Material& material, TensionSide tension) {
    const double fy = material.fy, fc = material.compression_strength();
    return tension == TensionSide::Below ? Strengths{fy, fc} : Strengths{fc, fy};
}

template <class Visit>
void for_each_ring(const ValidSection& section, TensionSide tension, Visit visit) {
    for (const Part& part : section.parts()) {
        const Strengths strengths = strengths_of(part.material, tension);
        visit(part.outer, strengths);
        for (const Ring& hole : part.holes) visit(hole, strengths);
    }
}

// The whole section cut at level t, strength weighted. The force balance is carried as
// deficit(t) = ½(F_above − F_below); its derivative is −Σ ½(s_below + s_above)·chord, so the
// rates use the mean strength (with fc = fy: fy, as in the paper).
struct SectionCut {
    double force_below = 0.0;  // Σ s_below·A_below [N]
    double force_above = 0.0;  // Σ s_above·A_above [N]
    double moment = 0.0;       // ∫ s·|level − t| dA [N·m]
    double rate = 0.0;         // Σ s_mean·chord (edges strictly crossing t)
    double rate_slope = 0.0;   // its derivative
    double a = -std::numeric_limits<double>::infinity();  // largest vertex level <= t
    double b = std::numeric_limits<double>::infinity();   // smallest vertex level > t
};

// A bar's net strengths (its own minus the part's it displaces) on either side of the axis.
Strengths bar_strengths(const Bar& bar, const Material& part, TensionSide tension) {
    const Strengths own = strengths_of(bar.material, tension), displaced = strengths_of(part, tension);
    return {own.below - displaced.below, own.above - displaced.above};
}

// Bars are point areas: a step in the force at their level (a piece end, like a vertex level), and
// a moment s·A·|level − t|. A bar exactly at t counts below, as vertex levels do.
void add_bars(const ValidSection& section, BendingAxis axis, TensionSide tension, double t, SectionCut& s) {
    for (const Part& part : section.parts())
        for (const Bar& bar : part.bars) {
            const Strengths strength = bar_strengths(bar, part.material, tension);
            const double level = level_of(bar.at, axis);
            if (level <= t) {
                s.force_below += strength.below * bar.area;
                s.moment += strength.below * bar.area * (t - level);
                s.a = std::max(s.a, level);
            } else {
                s.force_above += strength.above * bar.area;
                s.moment += strength.above * bar.area * (level - t);
                s.b = std::min(s.b, level);
            }
        }
}

SectionCut cut_section(const ValidSection& section, BendingAxis axis, TensionSide tension, double t) {
    SectionCut s;
    add_bars(section, axis, tension, t, s);
    for_each_ring(section, tension, [&](const Ring& ring, Strengths strength) {
        const LevelCut c = cut_at(ring, axis, t);
        s.force_below += strength.below * c.area_below;
        s.force_above += strength.above * c.area_above;
        // Both sides positive (moment_below is ∫(level − t) < 0): no cancellation.
        s.moment += strength.above * c.moment_above - strength.below * c.moment_below;
        s.rate += strength.mean() * c.chord;
        s.rate_slope += strength.mean() * c.chord_slope;
        s.a = std::max(s.a, c.vertex_below);
        s.b = std::min(s.b, c.vertex_above);
    });
    return s;
}

// F' and F'' on the piece [a, b] when t = a is itself a vertex level (the edges ending at t do not
// cross it strictly, so the cut cannot see them): from the chord lengths at both ends.
void rates_from_piece_ends(const ValidSection& section, BendingAxis axis, TensionSide tension, SectionCut& cut) {
    double at_a = 0.0, at_b = 0.0;
    for_each_ring(section, tension, [&](const Ring& ring, Strengths strength) {
        const Chords c = chord_lengths(ring, axis, cut.a, cut.b);
        at_a += strength.mean() * c.at_a;
        at_b += strength.mean() * c.at_b;
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

// Per part: level range of the outer ring, its force on either side of an axis, and the
// mean-strength weight and first moment for the starting guess.
struct PartSummary {
    double lo, hi;
    double force_if_below;  // s_below·A
    double force_if_above;  // s_above·A
    double weight;          // s_mean·A
    double weight_moment;   // s_mean·∫level dA
};

std::vector<PartSummary> summarize_parts(const ValidSection& section, BendingAxis axis, TensionSide tension) {
    std::vector<PartSummary> parts;
    for (std::size_t p = 0; p < section.parts().size(); ++p) {
        const Part& part = section.parts()[p];
        // The outer ring's level range, from validation: a min and max over the vertices here, each a
        // chain of dependent instructions, was a quarter of the time of all six capacities (perf).
        const RingExtent& box = section.part_extents()[p];
        PartSummary s = axis == BendingAxis::X ? PartSummary{box.min_z, box.max_z, 0.0, 0.0, 0.0, 0.0}
                                               : PartSummary{box.min_x, box.max_x, 0.0, 0.0, 0.0, 0.0};
        const RingMoments& m = section.part_moments()[p];
        const Strengths strength = strengths_of(part.material, tension);
        s.force_if_below = strength.below * m.area;
        s.force_if_above = strength.above * m.area;
        for (const Bar& bar : part.bars) {
            const Strengths net = bar_strengths(bar, part.material, tension);
            s.force_if_below += net.below * bar.area;
            s.force_if_above += net.above * bar.area;
        }
        s.weight = strength.mean() * m.area;
        s.weight_moment = strength.mean() * (axis == BendingAxis::X ? m.Sz : m.Sx);
        parts.push_back(s);
    }
    return parts;
}

// The axis is not unique when the parts split into a lower and an upper group, apart from each
// other, whose forces balance up to round-off: then it is the middle of the gap between the groups.
std::optional<double> middle_of_balanced_gap(std::vector<PartSummary> parts) {
    std::sort(parts.begin(), parts.end(), [](const PartSummary& x, const PartSummary& y) { return x.lo < y.lo; });
    double force_above = 0.0, scale = 0.0;
    for (const PartSummary& part : parts) force_above += part.force_if_above, scale += part.weight;
    const double round_off = 16.0 * std::numeric_limits<double>::epsilon() * scale;
    double force_below = 0.0, top = parts[0].lo;
    for (const PartSummary& part : parts) {
        if (part.lo > top && std::fabs(force_below - force_above) <= round_off) return 0.5 * (top + part.lo);
        force_below += part.force_if_below;
        force_above -= part.force_if_above;
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

PlasticBending at_level(const ValidSection& section, BendingAxis axis, TensionSide tension, double t) {
    return {t, cut_section(section, axis, tension, t).moment};
}

}  // namespace

double yield_force(const ValidSection& section, BendingAxis axis, TensionSide tension, double t, Side side) {
    const SectionCut cut = cut_section(section, axis, tension, t);
    return side == Side::Below ? cut.force_below : cut.force_above;
}

PlasticBending plastic_bending(const ValidSection& section, BendingAxis axis, TensionSide tension) {
    const std::vector<PartSummary> parts = summarize_parts(section, axis, tension);
    double lo = parts[0].lo, hi = parts[0].hi, weight = 0.0, weight_moment = 0.0;
    for (const PartSummary& part : parts) {
        lo = std::min(lo, part.lo), hi = std::max(hi, part.hi);
        weight += part.weight, weight_moment += part.weight_moment;
    }
    if (const std::optional<double> gap = middle_of_balanced_gap(parts)) return at_level(section, axis, tension, *gap);

    double t = weight_moment / weight;  // strength-weighted centroid: exact for doubly symmetric sections with fc = fy
    Bracket bracket{lo, hi, hi - lo, 0};
    for (;;) {
        if (!(t > bracket.lo && t < bracket.hi)) {
            t = 0.5 * (bracket.lo + bracket.hi);
            // The bracket has closed on a vertex level: the root is there, up to round-off.
            if (!(t > bracket.lo && t < bracket.hi)) return at_level(section, axis, tension, t);
        }
        SectionCut cut = cut_section(section, axis, tension, t);
        if (cut.a == t) rates_from_piece_ends(section, axis, tension, cut);
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
