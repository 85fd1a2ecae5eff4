#pragma once
// The fully plastic torque by Nadai's sand-heap analogy (A. Nadai, Theory of Flow and Fracture of
// Solids, 1950, ch. 35): T_p = 2·τy·(volume under φ), φ the largest function with slope ≤ 1 that
// is 0 on the outer boundary and constant on each hole's boundary. Here
//   φ(p) = min(d(p, outer), min_k (c_k + d(p, hole_k))),
// c_k the hole's plateau: the shortest path from the outer boundary to hole k over the gaps
// between boundaries (Dijkstra), and the volume is ∫φ dA over the material + Σ c_k·A_k.
// φ has kinks along the medial axis, so the integral over a shape-refined mesh is globally adaptive:
// a 4 × 4 Gauss rule per triangle with the estimate |Q(4) − Q(2)|, the triangle of the largest
// estimate quadrisected until the estimates add up to the tolerance (docs/elastic-and-torsion.md).
// τy per part (Tresca or von Mises of its fy); parts are added, not welded.
#include <cstddef>

#include "plascap/sections/torsion_constant.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

struct PlasticTorsion {
    double T = 0.0;        // fully plastic torque [N·m]
    double error = 0.0;    // estimated absolute error [N·m]
    std::size_t triangles = 0;
    bool converged = false;  // the estimate is within options.relative_tolerance
};

PlasticTorsion plastic_torsion(const ValidSection& section, const TorsionOptions& options = {});

}  // namespace plascap
