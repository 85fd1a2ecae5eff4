#pragma once
// From a section to a plastic joint in one call — the bridge between plascap::sections and the
// engine-neutral law (plascap::adapters_common, which knows nothing of sections): the capacities of
// every dof, the section's coupled yield condition (docs/yield-surface.md), the stiffness of the beam
// segment the joint stands for, and the breaking limits of its material.
#include <optional>

#include "plascap/adapters/plastic_joint_settings.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/section_yield.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

struct SectionJointOptions {
    // What each dof does; rows only for plastic and rigid ones. Default: all six plastic.
    PerDof<DofMode> modes{DofMode::Plastic, DofMode::Plastic, DofMode::Plastic,
                          DofMode::Plastic, DofMode::Plastic, DofMode::Plastic};
    bool coupled = true;  // yield on the section's coupled surface; false: each dof at its own capacity
    TorsionCapacity torsion = TorsionCapacity::FullyPlastic;  // My's capacity: T_p, or eq. 2.14
    // The length of the beam segment the joint stands for [m]: the stiffness EA/L, 12EI/L³, EI/L,
    // GJ/L (joint_stiffness.hpp; needs E for every material) and the breaking displacement ε_u·L.
    // None: rigid-plastic, and no displacement limit.
    std::optional<double> segment_length;
};

// Throws InputError naming the problem: a capacity a plastic dof needs is zero, the stiffness needs a
// missing E, a non-positive length. The breaking limits are the smallest the section's materials give
// (ultimate_strain × length, max_plastic_rotation); none: never breaks.
PlasticJointSettings section_joint_settings(const ValidSection& section, const SectionJointOptions& options = {});

// The capacity of each dof from a section's capacities (both signs; see capacities.hpp for which
// rotation puts which side in tension): Qx, Qz, My act alike both ways; N resists positive motion
// (elongation when the joint's y axis points from a to b) with N and negative with N_neg; Mx and Mz
// with Mx, Mz one way and Mx_neg, Mz_neg the other. No stiffness: the law is rigid-plastic until one
// is set. Throws InputError if a capacity the dof needs is missing or zero.
DofLaw dof_law_from_section(Dof dof, const Capacities& capacities);

// EA/L, 12EI/L³ (shear), EI/L, GJ/L of a beam segment of the section, per dof [N/m, N·m/rad]; the
// torsion stiffness only where every material gives G (or E and ν). Throws InputError unless every
// material gives E.
PerDof<std::optional<double>> segment_stiffness(const ValidSection& section, double length);

}  // namespace plascap
