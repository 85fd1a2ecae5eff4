#include "plascap/adapters/row_effective_mass.hpp"

#include <cmath>

namespace plascap {
namespace {

// v·M·v = Σ m_ii v_i² + Σ_{i<j} (m_ij + m_ji) v_i v_j, exact for any M, with the off-diagonal
// pairs summed once per body: nine products a row rather than twelve.
struct SymmetricQuadratic {
    double xx, yy, zz, xy2, xz2, yz2;
    explicit SymmetricQuadratic(const Mat3& m)
        : xx(m[0][0]), yy(m[1][1]), zz(m[2][2]), xy2(m[0][1] + m[1][0]), xz2(m[0][2] + m[2][0]), yz2(m[1][2] + m[2][1]) {}
    double operator()(const Vec3& v) const {
        return xx * v[0] * v[0] + yy * v[1] * v[1] + zz * v[2] * v[2] + xy2 * v[0] * v[1] + xz2 * v[0] * v[2] +
               yz2 * v[1] * v[2];
    }
};

// One body's shares of J·M⁻¹·Jᵀ for the six rows: m⁻¹ + (r × a)·I⁻¹·(r × a) for a translation
// along a at lever r = anchor − centre, a·I⁻¹·a for a rotation about a.
void add_shares(PerDof<double>& w, const JointAxesInWorld& axes, const BodyInertia& body) {
    const SymmetricQuadratic inverse_inertia(body.inverse_inertia_world);
    const Vec3 lever = {axes.anchor[0] - body.centre[0], axes.anchor[1] - body.centre[1], axes.anchor[2] - body.centre[2]};
    for (std::size_t i = 0; i < 3; ++i) {
        w[i] += body.inverse_mass + inverse_inertia(cross(lever, axes.translation[i]));
        w[i + 3] += inverse_inertia(axes.rotation[i]);
    }
}

}  // namespace

PerDof<double> row_effective_masses(const JointAxesInWorld& axes, const BodyInertia& b,
                                    const std::optional<BodyInertia>& a) {
    PerDof<double> w{};  // J·M⁻¹·Jᵀ per row, Qx, N, Qz, Mx, My, Mz (dof.hpp's order)
    add_shares(w, axes, b);
    if (a) add_shares(w, axes, *a);
    PerDof<double> masses;
    for (std::size_t i = 0; i < w.size(); ++i) masses[i] = w[i] > 0.0 ? 1.0 / w[i] : INFINITY;
    return masses;
}

}  // namespace plascap
