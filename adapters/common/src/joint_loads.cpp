#include "plascap/adapters/joint_loads.hpp"

#include <cmath>

namespace plascap {
namespace {



double determinant(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

// m = Σ x_i·axes[i], by Cramer's rule; projections if the axes are (nearly) coplanar.
Vec3 components_along(const Vec3& m, const std::array<Vec3, 3>& axes) {
    const double d = determinant(axes[0], axes[1], axes[2]);
    if (std::abs(d) < 1e-6) return {dot(m, axes[0]), dot(m, axes[1]), dot(m, axes[2])};
    return {determinant(m, axes[1], axes[2]) / d, determinant(axes[0], m, axes[2]) / d,
            determinant(axes[0], axes[1], m) / d};
}

}  // namespace

PerDof<double> joint_frame_loads(const WorldLoad& load, const Vec3& centre_of_mass, const JointAxesInWorld& axes) {
    const Vec3 lever = {axes.anchor[0] - centre_of_mass[0], axes.anchor[1] - centre_of_mass[1],
                        axes.anchor[2] - centre_of_mass[2]};
    const Vec3 shift = cross(lever, load.force);
    const Vec3 moment_about_anchor = {load.torque_about_com[0] - shift[0], load.torque_about_com[1] - shift[1],
                                      load.torque_about_com[2] - shift[2]};
    const Vec3 moments = components_along(moment_about_anchor, axes.rotation);
    PerDof<double> loads{};
    for (std::size_t i = 0; i < 3; ++i) {
        loads[i] = dot(load.force, axes.translation[i]);
        loads[i + 3] = moments[i];
    }
    return loads;
}

}  // namespace plascap
