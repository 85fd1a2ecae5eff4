#pragma once
// The plastic capacities of a section (paper eqs. 2.10-2.14; README, "What it computes"):
//   N  = Σ fy·A                 axial force along y            [N]     eq. 2.10
//   Qx = Qz = Σ τy·A            shear forces along x and z     [N]     eq. 2.11
//   Mx = ∫ fy·|z − z_pna| dA    bending about x                [N·m]   eq. 2.12, about the plastic neutral axis
//   Mz = ∫ fy·|x − x_pna| dA    bending about z                [N·m]   eq. 2.13
//   My = ∫ τy·|p − c| dA        torsion about y, c = joint point [N·m] eq. 2.14, Fig. 2.6
// τy = fy/2 (Tresca) or fy/√3 (von Mises), from the tension strength fy.
//
// Where a material's compression strength fc differs from fy, the capacity depends on the load's
// sign. With σ the stress along y, the moments of the stresses are Mx = −∫ z·σ dA and
// Mz = ∫ x·σ dA (right-hand rule, y the beam axis), so:
//   N      = Σ fy·A, tension;                N_neg  = Σ fc·A, compression (a magnitude);
//   Mx     puts z < z_pna in tension (fy) and z > z_pna in compression (fc), the axis where the
//          two forces are equal: Σ fy·A(z < z_pna) = Σ fc·A(z > z_pna);
//   Mx_neg the opposite (tension above its axis z_pna_neg);
//   Mz     puts x > x_pna in tension and x < x_pna in compression; Mz_neg the opposite.
// All are magnitudes. With fc = fy everywhere, the _neg values equal the others.
#include <optional>

#include "plascap/sections/capacity_set.hpp"
#include "plascap/sections/geometry.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

struct Capacities {
    // Each capacity is present exactly when it was asked for.
    std::optional<double> N, Qx, Qz, Mx, Mz, My;
    std::optional<double> N_neg, Mx_neg, Mz_neg;

    double area = 0.0;                // [m²], always
    Point centroid;                   // area centroid [m], always
    std::optional<double> z_pna;      // plastic neutral axis of Mx, z = z_pna [m], with Mx
    std::optional<double> x_pna;      // plastic neutral axis of Mz, x = x_pna [m], with Mz
    std::optional<double> z_pna_neg;  // axis of Mx_neg [m], with Mx_neg
    std::optional<double> x_pna_neg;  // axis of Mz_neg [m], with Mz_neg
    std::optional<Point> reference;   // joint point of My [m], with My
    ShearCriterion shear = ShearCriterion::Tresca;

    std::optional<double> get(Capacity c) const;
};

// Exact closed forms over the polygons; coordinates of results are section coordinates.
Capacities compute_capacities(const ValidSection& section, CapacitySet wanted = CapacitySet::all());

}  // namespace plascap
