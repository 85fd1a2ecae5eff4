#include "plascap/adapters/joint_frame.hpp"

#include <algorithm>
#include <cmath>

namespace plascap {
namespace {

Vec3 column(const Mat3& m, std::size_t j) { return {m[0][j], m[1][j], m[2][j]}; }
Vec3 apply(const Mat3& m, const Vec3& v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }

}  // namespace

Pose compose(const Pose& parent, const Pose& local) {
    const Vec3 moved = apply(parent.rotation, local.origin);
    return {{parent.origin[0] + moved[0], parent.origin[1] + moved[1], parent.origin[2] + moved[2]},
            multiply(parent.rotation, local.rotation)};
}

Pose relative(const Pose& parent, const Pose& world_pose) {
    const Mat3 inverse = transpose(parent.rotation);
    const Vec3 offset = {world_pose.origin[0] - parent.origin[0], world_pose.origin[1] - parent.origin[1],
                         world_pose.origin[2] - parent.origin[2]};
    return {apply(inverse, offset), multiply(inverse, world_pose.rotation)};
}

JointFrameState measure_joint(const Pose& a, const Pose& b) {
    JointFrameState s;
    const Pose b_in_a = relative(a, b);
    const Mat3& r = b_in_a.rotation;
    for (std::size_t i = 0; i < 3; ++i) s.positions[i] = b_in_a.origin[i];
    // R = Rz(θz)·Ry(θy)·Rx(θx): R20 = −sin θy, R21/R22 = tan θx, R10/R00 = tan θz.
    s.positions[index(Dof::My)] = std::asin(std::clamp(-r[2][0], -1.0, 1.0));
    s.positions[index(Dof::Mx)] = std::atan2(r[2][1], r[2][2]);
    s.positions[index(Dof::Mz)] = std::atan2(r[1][0], r[0][0]);

    s.axes.anchor = b.origin;
    for (std::size_t i = 0; i < 3; ++i) s.axes.translation[i] = column(a.rotation, i);
    const Vec3 a_z = column(a.rotation, 2), b_x = column(b.rotation, 0);
    const Vec3 e1 = normalised(cross(a_z, b_x));
    s.axes.rotation = {normalised(cross(e1, a_z)), e1, normalised(cross(b_x, e1))};
    return s;
}

}  // namespace plascap
