#include "plascap/sections/joint_stiffness.hpp"

#include <cmath>

#include "plascap/input_error.hpp"

namespace plascap {

JointStiffness joint_stiffness(const SectionStiffness& s, std::optional<double> GJ, double length) {
    if (!std::isfinite(length) || length <= 0.0)
        throw InputError("joint stiffness: the segment length must be a positive finite number in m");
    const double L = length;
    JointStiffness k;
    k.axial = s.EA / L;                   // EA/L
    k.bending_x = s.EIxx / L;             // EI/L
    k.bending_z = s.EIzz / L;
    k.shear_x = 12.0 * s.EIzz / (L * L * L);  // 12EI/L³, bending about z
    k.shear_z = 12.0 * s.EIxx / (L * L * L);
    if (GJ) k.torsion = *GJ / L;          // GJ/L
    return k;
}

}  // namespace plascap
