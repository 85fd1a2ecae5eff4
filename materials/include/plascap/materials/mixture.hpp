#pragma once
// Reinforcement spread evenly over a material, the paper's shortcut for reinforced concrete
// ("0.04 % steel reinforced concrete", Section 3). The capacity integrals are linear in the
// strengths, so the mixture's strengths are the area-weighted ones.
#include "plascap/materials/material.hpp"

namespace plascap {

// fy, fc, E and density: (1 − ratio)·matrix + ratio·reinforcement (rule of mixtures, Voigt);
// G from the mixed E and the matrix's ν when both give E; the breaking limits and the shear
// criterion of the reinforcement, which decides when the member breaks. Name "C25/30 + 0.04 % B500B".
// Throws InputError unless 0 < ratio < 1.
Material smeared_mixture(const Material& matrix, const Material& reinforcement, double ratio);

}  // namespace plascap
