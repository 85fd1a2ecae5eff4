#include "plascap/adapters/joint_loads.hpp"

namespace plascap {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

PerDof<double> joint_frame_loads(const WorldLoad& load, const Vec3& centre_of_mass, const JointAxesInWorld& axes) {
    const Vec3 lever = {axes.anchor[0] - centre_of_mass[0], axes.anchor[1] - centre_of_mass[1],
                        axes.anchor[2] - centre_of_mass[2]};
    const Vec3 shift = cross(lever, load.force);
    const Vec3 moment_about_anchor = {load.torque_about_com[0] - shift[0], load.torque_about_com[1] - shift[1],
                                      load.torque_about_com[2] - shift[2]};
    PerDof<double> loads{};
    for (std::size_t i = 0; i < 3; ++i) {
        loads[i] = dot(load.force, axes.translation[i]);
        loads[i + 3] = dot(moment_about_anchor, axes.rotation[i]);
    }
    return loads;
}

}  // namespace plascap
