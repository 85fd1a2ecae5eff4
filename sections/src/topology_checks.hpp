#pragma once
// Exact topological tests on rings and parts, implemented with CGAL in topology_checks.cpp —
// the only translation unit of plascap::sections that includes CGAL (it is compile-heavy).
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "plascap/sections/geometry.hpp"

namespace plascap::detail {

// True when the ring is a simple polygon (CGAL::is_simple_2, exact predicates).
bool ring_is_simple(const Ring& ring);

// True when all vertices lie on one line (exact orientation tests).
bool all_collinear(const Ring& ring);

// For a non-simple ring of at most `max_vertices` vertices: a pair of edges (i, j), edge k joining
// vertex k to k+1, that touch or cross other than at their shared vertex. O(n²): messages only.
std::optional<std::pair<std::size_t, std::size_t>> find_intersecting_edges(const Ring& ring,
                                                                           std::size_t max_vertices);

// True when two rings' boundaries have any point in common (crossing, touching or overlapping).
bool rings_touch(const Ring& a, const Ring& b);

// True when any two of the rings touch (one sweep over all their edges): the fast path before
// rings_touch() names the pair.
bool any_rings_touch(const std::vector<const Ring*>& rings);

// For two rings that touch, with at most `max_vertices` vertices together: an edge i of `a` and an
// edge j of `b` that have a point in common. O(n·m): messages only.
std::optional<std::pair<std::size_t, std::size_t>> find_touching_edges(const Ring& a, const Ring& b,
                                                                       std::size_t max_vertices);

// True when p is strictly inside the simple ring.
bool strictly_inside(const Ring& ring, Point p);

// Area of the intersection of two validated parts (regularized: a shared edge or vertex has none),
// by CGAL's 2D Boolean set operations on exact constructions; 0 when their interiors are apart.
double overlap_area(const Part& a, const Part& b);

}  // namespace plascap::detail
