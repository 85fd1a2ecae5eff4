#pragma once
// What the mesher must insert so that a part's mesh conforms to the kinks, worked out in plain
// floating point before CGAL sees it (CGAL-free, cheap to compile):
//   - the rings, with a new vertex wherever an edge crosses a cut line, at exactly that line's level;
//   - the chords: the pieces of each cut line inside the part, from ring vertex to ring vertex,
//     split where the two cut lines cross and at the joint point when it lies on a line.
// Every chord end is then an existing vertex with identical coordinates, so the triangulation
// never has to construct an intersection: Delaunay refinement sees no feature smaller than the
// input's own.
#include <optional>
#include <utility>
#include <vector>

#include "plascap/sections/geometry.hpp"

namespace plascap::detail {

struct MeshCuts {
    std::vector<Ring> rings;                       // outer ring first, then the holes
    std::vector<std::pair<Point, Point>> chords;   // segments to insert as constraints
    std::optional<Point> vertex;                   // the joint point, when it should be inserted
};

// z_cuts: the lines z = z_cut; x_cuts: the lines x = x_cut (a line within 1e-12 of the part size
// of one already taken is left out); vertex: the joint point. The vertex is
// left out when it lies outside the part's box, or within 1e-12 of the part's size from a ring
// edge without being on it (a sliver that refinement could not resolve in doubles).
MeshCuts plan_mesh_cuts(const Part& part, const std::vector<double>& z_cuts, const std::vector<double>& x_cuts,
                        std::optional<Point> vertex);

}  // namespace plascap::detail
