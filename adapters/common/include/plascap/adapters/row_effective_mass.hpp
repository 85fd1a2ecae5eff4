#pragma once
// The effective mass of each joint row, 1/(J·M⁻¹·Jᵀ), which the regime choice (paper eq. 3.2) needs:
// translation rows act at the anchor on both bodies (lever r = anchor − centre), rotation rows are
// pure torques. A static body or the world contributes nothing; a row with nothing to move has an
// infinite effective mass.
#include <optional>

#include "plascap/adapters/joint_frame.hpp"

namespace plascap {

struct BodyInertia {
    double inverse_mass = 0.0;           // [1/kg]
    Mat3 inverse_inertia_world{};        // [1/(kg·m²)], world frame
    Vec3 centre{};                       // centre of mass [m]
};

PerDof<double> row_effective_masses(const JointAxesInWorld& axes, const BodyInertia& b,
                                    const std::optional<BodyInertia>& a);

}  // namespace plascap
