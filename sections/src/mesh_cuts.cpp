#include "mesh_cuts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "planar_distance.hpp"
#include "plascap/sections/ring_integrals.hpp"

namespace plascap::detail {
namespace {

// Relative size (of the part) below which two features count as one: far above round-off, far
// below anything a section is drawn with.
constexpr double kNear = 1e-12;

struct Line {
    BendingAxis axis;  // X: the line z = level; Z: the line x = level
    double level;
};

double along(Point p, BendingAxis axis) { return axis == BendingAxis::X ? p.x : p.z; }

Point on_line(const Line& line, double s) {
    return line.axis == BendingAxis::X ? Point{s, line.level} : Point{line.level, s};
}

// Where edge p–q, its ends strictly on opposite sides, crosses the line. The ends are put in a
// fixed order first, so the ring vertex and the chord end computed from one edge agree to the bit.
Point crossing(Point p, Point q, const Line& line) {
    if (std::tie(p.x, p.z) > std::tie(q.x, q.z)) std::swap(p, q);
    const double dp = level_of(p, line.axis) - line.level, dq = level_of(q, line.axis) - line.level;
    const double s = along(p, line.axis) + (along(q, line.axis) - along(p, line.axis)) * (dp / (dp - dq));
    return on_line(line, s);
}

bool strictly_across(Point p, Point q, const Line& line) {
    const double dp = level_of(p, line.axis) - line.level, dq = level_of(q, line.axis) - line.level;
    return (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0);
}

// The larger side of the part's bounding box.
double part_size(const Part& part) {
    double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min, z_min = x_min, z_max = -x_min;
    for (Point p : part.outer) {
        x_min = std::min(x_min, p.x);
        x_max = std::max(x_max, p.x);
        z_min = std::min(z_min, p.z);
        z_max = std::max(z_max, p.z);
    }
    return std::max(x_max - x_min, z_max - z_min);
}

// A cut within kNear of a vertex's level passes through that vertex instead: otherwise the
// crossings on its two edges would make a feature of round-off size.
double snapped_level(const Part& part, Line line, double near) {
    double best = line.level, distance = near;
    const auto visit = [&](const Ring& ring) {
        for (Point p : ring) {
            const double d = std::abs(level_of(p, line.axis) - line.level);
            if (d > 0.0 && d <= distance) {
                distance = d;
                best = level_of(p, line.axis);
            }
        }
    };
    visit(part.outer);
    for (const Ring& hole : part.holes) visit(hole);
    return best;
}

// The ring with a vertex added wherever an edge crosses one of the lines, in order along the edge.
Ring with_crossings(const Ring& ring, const std::vector<Line>& lines) {
    Ring out;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point p = ring[i], q = ring[(i + 1) % ring.size()];
        out.push_back(p);
        std::vector<std::pair<double, Point>> added;  // (distance from p, point)
        for (const Line& line : lines) {
            if (!strictly_across(p, q, line)) continue;
            const Point c = crossing(p, q, line);
            added.emplace_back(std::hypot(c.x - p.x, c.z - p.z), c);
        }
        std::sort(added.begin(), added.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& entry : added) out.push_back(entry.second);
    }
    return out;
}

// The positions along the line where the rings cross it, with vertices on the line counted on
// the upper side (`on_line_is_above`) or the lower one: the boundary of the part just above or
// just below the line.
std::vector<double> boundary_crossings(const std::vector<Ring>& rings, const Line& line, bool on_line_is_above) {
    std::vector<double> positions;
    const auto above = [&](Point p) {
        return on_line_is_above ? level_of(p, line.axis) >= line.level : level_of(p, line.axis) > line.level;
    };
    for (const Ring& ring : rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const Point p = ring[i], q = ring[(i + 1) % ring.size()];
            if (above(p) == above(q)) continue;
            if (level_of(p, line.axis) == line.level) positions.push_back(along(p, line.axis));
            else if (level_of(q, line.axis) == line.level) positions.push_back(along(q, line.axis));
            else positions.push_back(along(crossing(p, q, line), line.axis));
        }
    }
    std::sort(positions.begin(), positions.end());
    return positions;
}

using Intervals = std::vector<std::pair<double, double>>;

Intervals pairs_of(const std::vector<double>& positions) {
    Intervals intervals;
    for (std::size_t i = 0; i + 1 < positions.size(); i += 2) intervals.emplace_back(positions[i], positions[i + 1]);
    return intervals;
}

Intervals intersection(const Intervals& a, const Intervals& b) {
    Intervals out;
    for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
        const double lo = std::max(a[i].first, b[j].first), hi = std::min(a[i].second, b[j].second);
        if (hi > lo) out.emplace_back(lo, hi);
        (a[i].second < b[j].second) ? ++i : ++j;
    }
    return out;
}

// The line's pieces inside the part — inside just above it and just below it, so a line along a
// boundary edge gives no chord there — split at the given positions.
void add_chords(const std::vector<Ring>& rings, const Line& line, std::vector<double> splits,
                std::vector<std::pair<Point, Point>>& chords) {
    const Intervals inside = intersection(pairs_of(boundary_crossings(rings, line, true)),
                                          pairs_of(boundary_crossings(rings, line, false)));
    std::sort(splits.begin(), splits.end());
    for (const auto& [lo, hi] : inside) {
        double from = lo;
        for (double s : splits) {
            if (s <= from || s >= hi) continue;
            chords.emplace_back(on_line(line, from), on_line(line, s));
            from = s;
        }
        chords.emplace_back(on_line(line, from), on_line(line, hi));
    }
}

// The joint point goes in unless it is outside the part's box, on or next to a ring edge (where
// inserting it could leave a sliver of round-off width), or next to a cut line without being on it.
bool vertex_fits(const std::vector<Ring>& rings, const std::vector<Line>& lines, Point v, double near) {
    double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min, z_min = x_min, z_max = -x_min;
    for (Point p : rings.front()) {
        x_min = std::min(x_min, p.x);
        x_max = std::max(x_max, p.x);
        z_min = std::min(z_min, p.z);
        z_max = std::max(z_max, p.z);
    }
    if (v.x < x_min || v.x > x_max || v.z < z_min || v.z > z_max) return false;
    for (const Line& line : lines) {
        const double d = std::abs(level_of(v, line.axis) - line.level);
        if (d > 0.0 && d <= near) return false;
    }
    for (const Ring& ring : rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const Point a = ring[i], b = ring[(i + 1) % ring.size()];
            // On or next to the boundary: a vertex there already, or one in round-off reach.
            if (distance_to_segment(v, a, b) <= near) return false;
        }
    }
    return true;
}

}  // namespace

MeshCuts plan_mesh_cuts(const Part& part, const std::vector<double>& z_cuts, const std::vector<double>& x_cuts,
                        std::optional<Point> vertex) {
    const double near = kNear * part_size(part);
    std::vector<Line> lines;
    const auto add_line = [&](BendingAxis axis, double level) {
        const Line line{axis, snapped_level(part, {axis, level}, near)};
        for (const Line& taken : lines)
            if (taken.axis == axis && std::abs(taken.level - line.level) <= near) return;  // one line, not a sliver
        lines.push_back(line);
    };
    for (double z : z_cuts) add_line(BendingAxis::X, z);
    for (double x : x_cuts) add_line(BendingAxis::Z, x);

    MeshCuts cuts;
    cuts.rings.push_back(with_crossings(part.outer, lines));
    for (const Ring& hole : part.holes) cuts.rings.push_back(with_crossings(hole, lines));

    const bool vertex_goes_in = vertex && vertex_fits(cuts.rings, lines, *vertex, near);
    if (vertex_goes_in) cuts.vertex = vertex;
    for (const Line& line : lines) {
        std::vector<double> splits;
        for (const Line& other : lines)
            if (other.axis != line.axis) splits.push_back(other.level);
        if (vertex_goes_in && level_of(*vertex, line.axis) == line.level) splits.push_back(along(*vertex, line.axis));
        add_chords(cuts.rings, line, splits, cuts.chords);
    }
    return cuts;
}

}  // namespace plascap::detail
