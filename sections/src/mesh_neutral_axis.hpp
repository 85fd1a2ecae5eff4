#pragma once
// The plastic neutral axis found on a triangle mesh — independent of the exact route's
// piecewise-quadratic solve in plastic_bending.cpp, so the two routes check each other.
#include <vector>

#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/section_mesh.hpp"

namespace plascap::detail {

// The strengths a part carries below and above the axis (fy on the tension side, fc on the other).
struct SideStrengths {
    double below = 0.0, above = 0.0;  // [Pa]
};

// A reinforcement bar: a point area with its net strengths (its own minus the displaced part's).
struct PointArea {
    Point at;
    double area = 0.0;
    SideStrengths strength;
};

// The level t (z for BendingAxis::X, x for Z) where the yield force on either side is equal:
// Σ s_above·A(level > t) = Σ s_below·A(level < t) (paper eqs. 2.12–2.13). Each triangle's area beyond t
// is exact (similar triangles); t is the root by Brent's method (gsl_root_fsolver_brent) to
// round-off. Where the root is not unique (a gap without material), the middle of the gap.
// Bars add steps to the balance; Brent's method converges onto a step where the root is one.
double mesh_neutral_axis(const SectionMesh& mesh, const std::vector<SideStrengths>& strength_of_part,
                         const std::vector<PointArea>& bars, BendingAxis axis);

}  // namespace plascap::detail
