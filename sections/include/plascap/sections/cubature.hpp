#pragma once
// The cubature route: the same capacities as compute_capacities() (paper eqs. 2.10–2.14), found
// by meshing the section with CGAL and integrating every triangle with GSL. It is the general
// engine for integrands without closed forms, and an independent check of the exact route.
// Method and accuracy: docs/cubature-route.md.
#include <array>
#include <cstddef>
#include <optional>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/capacity_set.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

enum class CubatureRule {
    Adaptive,  // nested adaptive Gauss–Kronrod to a relative tolerance
    Fixed,     // Gauss–Legendre tensor rule of a fixed order
};

struct CubatureOptions {
    CubatureRule rule = CubatureRule::Adaptive;
    double tolerance = 1e-10;  // Adaptive: relative tolerance per triangle, in [1e-13, 0.1]
    int order = 8;             // Fixed: Gauss points per direction, in [1, 100]
    // Largest triangle [m²]; 0: no size bound. The adaptive rule integrates the constrained
    // triangulation as it is; the fixed rule always refines it for shape (angles ≥ 20.7°).
    double max_area = 0.0;
    // Mesh edges on the plastic neutral axes and a mesh vertex at the joint point, so every
    // integrand is smooth in every triangle. Off only to measure what that is worth.
    bool conforming = true;
};

// Throws InputError naming the option that is out of range.
void validate_cubature_options(const CubatureOptions& options);

struct CubatureResult {
    Capacities capacities;                        // the capacities asked for, as compute_capacities()
    std::array<std::optional<double>, kCapacityCount> error;  // estimated absolute error, by Capacity [N or N·m]
    std::size_t triangles = 0;                    // in the mesh that was integrated
    std::size_t evaluations = 0;                  // integrand evaluations
    double seconds = 0.0;                         // wall time of the whole route, meshing included
    bool refinement_stopped = false;              // see SectionMesh::refinement_stopped

    std::optional<double> estimated_error(Capacity c) const { return error[static_cast<std::size_t>(c)]; }
};

CubatureResult cubature_capacities(const ValidSection& section, CapacitySet wanted = CapacitySet::all(),
                                   const CubatureOptions& options = {});

}  // namespace plascap
