#pragma once
// The elastic stiffness of a beam segment of length L joining two bodies, for the elastic part of
// each joint row (the adapters): the Euler–Bernoulli beam stiffness matrix's direct terms
// (Przemieniecki, Theory of Matrix Structural Analysis, 1968, §5.2):
//   axial along y       EA/L      [N/m]
//   bending about x, z  EI/L      [N·m/rad]   (uniform moment: θ = M·L/EI)
//   torsion about y     GJ/L      [N·m/rad]
//   shear along x, z    12·EI/L³  [N/m]       (both ends held against rotation; along x bends about z)
#include <optional>

#include "plascap/sections/elastic_properties.hpp"

namespace plascap {

struct JointStiffness {
    double axial = 0.0;
    double shear_x = 0.0, shear_z = 0.0;
    double bending_x = 0.0, bending_z = 0.0;
    std::optional<double> torsion;  // when GJ is known
};

// Throws InputError unless L is a positive finite length.
JointStiffness joint_stiffness(const SectionStiffness& section, std::optional<double> GJ, double length);

}  // namespace plascap
