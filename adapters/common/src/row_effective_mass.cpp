#include "plascap/adapters/row_effective_mass.hpp"

#include <cmath>

namespace plascap {
namespace {

double quadratic(const Mat3& m, const Vec3& v) {
    return dot(v, {dot(m[0], v), dot(m[1], v), dot(m[2], v)});
}

// One body's share of J·M⁻¹·Jᵀ for a row along `axis`: m⁻¹ + (r × a)·I⁻¹·(r × a) for a translation
// at lever r, a·I⁻¹·a for a rotation.
double share(const BodyInertia& body, const Vec3& anchor, const Vec3& axis, bool rotation) {
    if (rotation) return quadratic(body.inverse_inertia_world, axis);
    const Vec3 lever = {anchor[0] - body.centre[0], anchor[1] - body.centre[1], anchor[2] - body.centre[2]};
    return body.inverse_mass + quadratic(body.inverse_inertia_world, cross(lever, axis));
}

}  // namespace

PerDof<double> row_effective_masses(const JointAxesInWorld& axes, const BodyInertia& b,
                                    const std::optional<BodyInertia>& a) {
    PerDof<double> masses{};
    for (Dof dof : kAllDofs) {
        const bool rotation = is_rotation(dof);
        const Vec3& axis = rotation ? axes.rotation[axis_of(dof)] : axes.translation[axis_of(dof)];
        double w = share(b, axes.anchor, axis, rotation);
        if (a) w += share(*a, axes.anchor, axis, rotation);
        masses[index(dof)] = w > 0.0 ? 1.0 / w : INFINITY;
    }
    return masses;
}

}  // namespace plascap
