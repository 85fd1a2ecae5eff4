#include "topology_checks.hpp"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Surface_sweep_2_algorithms.h>

#include <map>
#include <vector>

namespace plascap::detail {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;  // exact predicates on doubles
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;    // exact intersections for sweeps
using SegmentTraits = CGAL::Arr_segment_traits_2<Epeck>;

template <class Kernel>
std::vector<typename Kernel::Point_2> to_points(const Ring& ring) {
    std::vector<typename Kernel::Point_2> points;
    points.reserve(ring.size());
    for (Point p : ring) points.emplace_back(p.x, p.z);
    return points;
}

void append_segments(const Ring& ring, std::vector<SegmentTraits::Curve_2>& segments) {
    const std::vector<Epeck::Point_2> points = to_points<Epeck>(ring);
    for (std::size_t i = 0; i < points.size(); ++i)
        segments.emplace_back(points[i], points[(i + 1) % points.size()]);
}

// True when two of the rings have a vertex in common (rings are simple: no repeats within one).
bool share_a_vertex(const std::vector<const Ring*>& rings) {
    std::map<std::pair<double, double>, std::size_t> owner;
    for (std::size_t r = 0; r < rings.size(); ++r) {
        for (Point p : *rings[r]) {
            const auto [it, inserted] = owner.emplace(std::make_pair(p.x, p.z), r);
            if (!inserted && it->second != r) return true;
        }
    }
    return false;
}

CGAL::Polygon_with_holes_2<Epeck> to_polygon_with_holes(const Part& part) {
    const std::vector<Epeck::Point_2> outer = to_points<Epeck>(part.outer);
    CGAL::Polygon_with_holes_2<Epeck> polygon{CGAL::Polygon_2<Epeck>(outer.begin(), outer.end())};
    for (const Ring& hole : part.holes) {
        const std::vector<Epeck::Point_2> points = to_points<Epeck>(hole);
        polygon.add_hole(CGAL::Polygon_2<Epeck>(points.begin(), points.end()));
    }
    return polygon;
}

}  // namespace

namespace {

bool collinear_points(const std::vector<Epick::Point_2>& p) {
    for (std::size_t i = 2; i < p.size(); ++i)
        if (!CGAL::collinear(p[0], p[1], p[i])) return false;
    return true;
}

}  // namespace

bool ring_is_simple(const Ring& ring) {
    const std::vector<Epick::Point_2> points = to_points<Epick>(ring);
    // A convex ring whose vertices are not all on one line is simple: CGAL's O(n) convexity test,
    // which also rejects a ring winding more than once, spares its O(n log n) sweep (two sorts of
    // the vertices, 60 % of validating a 1,000-gon).
    if (CGAL::is_convex_2(points.begin(), points.end(), Epick()) && !collinear_points(points)) return true;
    return CGAL::is_simple_2(points.begin(), points.end(), Epick());
}

bool all_collinear(const Ring& ring) { return collinear_points(to_points<Epick>(ring)); }

std::optional<std::pair<std::size_t, std::size_t>> find_intersecting_edges(const Ring& ring,
                                                                           std::size_t max_vertices) {
    const std::size_t n = ring.size();
    if (n > max_vertices) return std::nullopt;
    const std::vector<Epick::Point_2> p = to_points<Epick>(ring);
    auto edge = [&](std::size_t i) { return Epick::Segment_2(p[i], p[(i + 1) % n]); };
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if (!adjacent) {
                if (CGAL::do_intersect(edge(i), edge(j))) return std::make_pair(i, j);
            } else {
                // Neighbours share one vertex; they are bad only when they fold back onto each other.
                const std::size_t first = j == i + 1 ? i : j;  // edge entering the shared vertex
                const std::size_t shared = (first + 1) % n;
                const auto& a = p[first];
                const auto& b = p[shared];
                const auto& c = p[(shared + 1) % n];
                if (CGAL::collinear(a, b, c) && !CGAL::collinear_are_ordered_along_line(a, b, c))
                    return std::make_pair(i, j);
            }
        }
    }
    return std::nullopt;
}

std::optional<std::pair<std::size_t, std::size_t>> find_touching_edges(const Ring& a, const Ring& b,
                                                                       std::size_t max_vertices) {
    if (a.size() + b.size() > max_vertices) return std::nullopt;
    const std::vector<Epick::Point_2> p = to_points<Epick>(a);
    const std::vector<Epick::Point_2> q = to_points<Epick>(b);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Epick::Segment_2 edge_a(p[i], p[(i + 1) % p.size()]);
        for (std::size_t j = 0; j < q.size(); ++j)
            if (CGAL::do_intersect(edge_a, Epick::Segment_2(q[j], q[(j + 1) % q.size()]))) return std::make_pair(i, j);
    }
    return std::nullopt;
}

bool any_rings_touch(const std::vector<const Ring*>& rings) {
    if (share_a_vertex(rings)) return true;  // the sweep below ignores contacts at segment ends
    std::vector<SegmentTraits::Curve_2> segments;
    for (const Ring* ring : rings) append_segments(*ring, segments);
    return CGAL::do_curves_intersect(segments.begin(), segments.end());
}

bool rings_touch(const Ring& a, const Ring& b) { return any_rings_touch({&a, &b}); }

bool strictly_inside(const Ring& ring, Point p) {
    const std::vector<Epick::Point_2> points = to_points<Epick>(ring);
    return CGAL::bounded_side_2(points.begin(), points.end(), Epick::Point_2(p.x, p.z), Epick()) ==
           CGAL::ON_BOUNDED_SIDE;
}

double overlap_area(const Part& a, const Part& b) {
    const CGAL::Polygon_with_holes_2<Epeck> pa = to_polygon_with_holes(a);
    const CGAL::Polygon_with_holes_2<Epeck> pb = to_polygon_with_holes(b);
    if (!CGAL::do_intersect(pa, pb)) return 0.0;
    std::vector<CGAL::Polygon_with_holes_2<Epeck>> pieces;
    CGAL::intersection(pa, pb, std::back_inserter(pieces));
    Epeck::FT area = 0;
    for (const auto& piece : pieces) {
        area += piece.outer_boundary().area();
        for (auto hole = piece.holes_begin(); hole != piece.holes_end(); ++hole) area += hole->area();  // clockwise: negative
    }
    return CGAL::to_double(area);
}

}  // namespace plascap::detail
