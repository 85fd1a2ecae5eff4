#pragma once
// The Saint-Venant torsion constant J by finite elements (Prandtl's stress function; Timoshenko &
// Goodier, Theory of Elasticity, §§ 101–104): ∇²φ = −2 in the material, φ = 0 on the outer boundary
// and φ = c_k on each hole's boundary, c_k such that the hole's circulation closes (Bredt); then
// J = 2∫φ dA + 2·Σ c_k·A_k. Solved as the minimum of ½∫|∇φ|² dA − 2∫φ dA − 2·Σ c_k·A_k with
// quadratic (6-node) triangles on the CGAL mesh, each hole's boundary sharing one unknown, by
// Eigen's sparse Cholesky (SimplicialLDLT). The discrete J approaches J from below as O(h⁴) on
// smooth solutions: meshes of halving triangle area are solved, each pair Richardson-extrapolated
// (R = (4·J(h/√2) − J(h))/3), until two successive R agree to the tolerance; the last R is the
// result and their difference the estimate.
//
// Parts are solved one by one and their J added: parts that only touch are not welded together.
#include <cstddef>
#include <optional>

#include "plascap/sections/valid_section.hpp"

namespace plascap {

struct TorsionOptions {
    double relative_tolerance = 1e-4;  // stop when the error estimate is below this (relative)
    std::size_t max_triangles = 2000000;
};

struct TorsionConstant {
    double J = 0.0;        // [m⁴]
    std::optional<double> GJ;  // [N·m²], when every part has the same shear modulus G (else parts differ: not summed)
    double error = 0.0;    // estimated absolute error [m⁴]
    std::size_t triangles = 0;  // of the finest mesh
    bool converged = false;     // false: max_triangles reached first
};

TorsionConstant saint_venant_torsion(const ValidSection& section, const TorsionOptions& options = {});

// J of one mesh (no refinement loop), for convergence studies.
double saint_venant_torsion_on_mesh(const ValidSection& section, double max_area, std::size_t* triangles = nullptr);

}  // namespace plascap
