#pragma once
// A triangle mesh of a validated section, made by CGAL's constrained Delaunay triangulation
// (implemented in section_mesh.cpp, the only file that includes CGAL's meshing headers).
//
// The mesh can be made to conform to the kinks of the capacity integrands: the lines z = z_cut and
// x = x_cut (the plastic neutral axes, where |z − z_pna| and |x − x_pna| bend; two of each when
// tension and compression strengths differ) become mesh edges,
// and the joint point (where |p − c| has its cone tip) becomes a mesh vertex. Then every integrand
// is smooth inside every triangle and Gaussian cubature converges at its full rate.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "plascap/sections/geometry.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

struct MeshOptions {
    // Largest triangle area [m²]; 0 leaves the size free. A positive value turns on Delaunay
    // refinement (CGAL::refine_Delaunay_mesh_2) with this size bound and the shape bound below.
    double max_area = 0.0;
    // Delaunay refinement for shape (smallest angle ≥ 20.7°, CGAL's bound B = 0.125) even without
    // max_area. Off, the mesh is the constrained Delaunay triangulation of the rings and cuts.
    bool refine_shape = false;
    // Kinks to conform to, in the section's local coordinates (ValidSection::to_local).
    std::vector<double> z_cuts;     // each line z = z_cut becomes mesh edges
    std::vector<double> x_cuts;     // each line x = x_cut becomes mesh edges
    std::optional<Point> vertex;    // becomes a mesh vertex when it lies in or on a part
};

struct SectionMesh {
    std::vector<Point> vertices;                        // local coordinates [m]
    std::vector<std::array<std::size_t, 3>> triangles;  // counter-clockwise vertex indices
    std::vector<std::size_t> part_of;                   // the part each triangle lies in
    // True when Delaunay refinement ran out of its vertex budget (50 per input vertex, plus 4 per
    // max_area of the part, plus 10,000) before every triangle met the bounds: a feature or an
    // angle too small to resolve in doubles. The mesh is still a valid triangulation.
    bool refinement_stopped = false;
};

// Meshes every part (holes left out). Throws InputError when max_area is negative or not finite.
SectionMesh mesh_section(const ValidSection& section, const MeshOptions& options = {});

}  // namespace plascap
