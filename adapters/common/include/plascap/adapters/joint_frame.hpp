#pragma once
// Where a joint is, from the world poses of its frame as carried by body a and by body b: the dof
// positions, and the axes its rows act along, as Euler angles: Bullet's 6-dof spring constraints
// compute the same inside Bullet, and this defines it for engine-neutral code and tests alike.
// plascap's own Bullet constraint and the ODE adapter measure swing and twist instead
// (measure_joint_swing_twist, swing_twist.hpp), which has no singularity at a 90° twist.
//   translations: the components, along frame a's axes, of b's anchor minus a's;
//   rotations: the angles of R = Aᵀ·B = Rz(θz)·Ry(θy)·Rx(θx), right-handed (Bullet's XYZ order
//   seen from b, sign-corrected), exact for any turn short of θy = ±90°.
// The rotation rows' axes are those that freeze one angle each (Bullet's Spring2 uses the same):
// e1 = a_z × b_x, e0 = e1 × a_z, e2 = b_x × e1, normalised.
#include <array>

#include "plascap/adapters/dof.hpp"
#include "plascap/adapters/joint_loads.hpp"
#include "plascap/adapters/vec3.hpp"

namespace plascap {

using Mat3 = std::array<Vec3, 3>;  // rows

struct Pose {
    Vec3 origin{};
    Mat3 rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // columns: the frame's x, y, z in the world
};

struct JointFrameState {
    PerDof<double> positions{};  // [m, rad]
    JointAxesInWorld axes;       // anchor = frame b's origin
};

JointFrameState measure_joint(const Pose& frame_on_a, const Pose& frame_on_b);

// a·b and aᵀ; inline, as the steps of every joint's measurement.
inline Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 m{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return m;
}

inline Mat3 transpose(const Mat3& a) {
    Mat3 m{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) m[i][j] = a[j][i];
    return m;
}

// Poses and rotations composed: parent ∘ local.
Pose compose(const Pose& parent, const Pose& local);
// The pose of `world_pose` seen from `parent` (parent⁻¹ ∘ world_pose).
Pose relative(const Pose& parent, const Pose& world_pose);

}  // namespace plascap
