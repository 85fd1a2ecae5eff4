#include "plascap/sections/yield_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stress_block.hpp"

#include "plascap/input_error.hpp"

namespace plascap {
namespace {

using detail::Mat3d;
using detail::Vec3d;

Vec3d as_vec(const SectionResultant& r) { return {r.N, r.Mx, r.Mz}; }
SectionResultant as_resultant(const Vec3d& v) { return {v[0], v[1], v[2]}; }
double dot3(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const Vec3d& a) { return std::sqrt(dot3(a, a)); }

Point area_centroid(const ValidSection& section) {
    double area = 0.0, sx = 0.0, sz = 0.0;
    for (const RingMoments& m : section.part_moments()) area += m.area, sx += m.Sx, sz += m.Sz;
    return {sx / area, sz / area};
}

// Two unit vectors completing u/|u| to an orthonormal basis.
std::array<Vec3d, 2> plane_basis(const Vec3d& u) {
    const Vec3d d{u[0] / norm3(u), u[1] / norm3(u), u[2] / norm3(u)};
    const int smallest = std::abs(d[0]) <= std::abs(d[1]) && std::abs(d[0]) <= std::abs(d[2]) ? 0
                         : std::abs(d[1]) <= std::abs(d[2])                                    ? 1
                                                                                               : 2;
    Vec3d e1{};
    e1[smallest] = 1.0;
    const double along = dot3(e1, d);
    for (int i = 0; i < 3; ++i) e1[i] -= along * d[i];
    const double n1 = norm3(e1);
    for (double& v : e1) v /= n1;
    const Vec3d e2{d[1] * e1[2] - d[2] * e1[1], d[2] * e1[0] - d[0] * e1[2], d[0] * e1[1] - d[1] * e1[0]};
    return {e1, e2};
}

}  // namespace

struct YieldSurface::Impl {
    detail::BlockSection blocks;
    Vec3d scale{1.0, 1.0, 1.0};  // resultant units: (N, Mx, Mz) = scale ∘ scaled

    Impl(const ValidSection& section, Point c) : blocks(section, c) {
        const Vec3d t = blocks.all_tension(), k = blocks.all_compression();
        const double force = 0.5 * (std::abs(t[0]) + std::abs(k[0]));
        scale[0] = force > 0.0 ? force : 1.0;
        // Bending about each axis through the reference: the size of the moments, for conditioning.
        for (int axis = 1; axis <= 2; ++axis) {
            Vec3d n{};
            n[axis] = 1.0;
            const double up = blocks.block(n).support;
            n[axis] = -1.0;
            const double down = blocks.block(n).support;
            const double moment = 0.5 * (up + down);
            scale[axis] = moment > 0.0 ? moment : scale[0];
        }
    }

    // min φ(ν) = h̃(ν) − ν·p over the plane ν·u = 1, all in scaled units (h̃(ν) = h(ν ⊘ scale));
    // φ's minimum is the length of the ray p + t·u inside the surface (polar duality).
    SurfaceHit ray(const Vec3d& p, const Vec3d& u, const std::optional<SectionResultant>& warm) const;

    struct Eval {
        double phi;
        Vec3d r;   // scaled resultant
        Mat3d H;   // scaled Hessian
    };
    Eval evaluate(const Vec3d& nu, const Vec3d& p) const {
        Vec3d n;
        for (int i = 0; i < 3; ++i) n[i] = nu[i] / scale[i];
        const detail::StressBlock b = blocks.block(n);
        Eval e;
        for (int i = 0; i < 3; ++i) {
            e.r[i] = b.resultant[i] / scale[i];
            for (int j = 0; j < 3; ++j) e.H[i][j] = b.hessian[i][j] / (scale[i] * scale[j]);
        }
        e.phi = dot3(nu, e.r) - dot3(nu, p);
        return e;
    }
};

SurfaceHit YieldSurface::Impl::ray(const Vec3d& p, const Vec3d& u, const std::optional<SectionResultant>& warm) const {
    const double uu = dot3(u, u);
    const std::array<Vec3d, 2> e = plane_basis(u);
    Vec3d nu0;
    for (int i = 0; i < 3; ++i) nu0[i] = u[i] / uu;
    double y[2] = {0.0, 0.0};
    if (warm) {  // project the earlier normal (scaled, normalised to ν·u = 1) onto the plane
        Vec3d w = as_vec(*warm);
        for (int i = 0; i < 3; ++i) w[i] *= scale[i];
        const double wu = dot3(w, u);
        if (wu > 0.0) {
            for (double& v : w) v /= wu;
            y[0] = dot3(w, e[0]);
            y[1] = dot3(w, e[1]);
        }
    }
    const auto point_at = [&](const double (&yy)[2]) {
        Vec3d nu;
        for (int i = 0; i < 3; ++i) nu[i] = nu0[i] + yy[0] * e[0][i] + yy[1] * e[1][i];
        return nu;
    };
    Vec3d nu = point_at(y);
    Eval cur = evaluate(nu, p);
    double mu = 0.0;  // Levenberg–Marquardt damping, 0 while Newton's steps go downhill
    int unchanged = 0;
    SurfaceHit hit;
    constexpr int kMaxSteps = 200;
    for (; hit.iterations < kMaxSteps; ++hit.iterations) {
        Vec3d grad3;
        for (int i = 0; i < 3; ++i) grad3[i] = cur.r[i] - p[i];
        const double g[2] = {dot3(grad3, e[0]), dot3(grad3, e[1])};
        const double gnorm = std::hypot(g[0], g[1]);
        if (gnorm <= 1e-15 * std::max(1.0, norm3(cur.r))) break;  // the block's resultant is on the ray
        double G[2][2];
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
                double s = 0.0;
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) s += e[a][i] * cur.H[i][j] * e[b][j];
                G[a][b] = s;
            }
        const double trace = G[0][0] + G[1][1];
        bool accepted = false, converged = false;
        for (int tries = 0; tries < 60; ++tries) {
            const double a = G[0][0] + mu, d = G[1][1] + mu, b = G[0][1];
            const double det = a * d - b * b;
            if (!(det > 1e-300) || !(a > 0.0)) {  // flat (the line misses the section): damp more
                mu = std::max({2.0 * mu, 1e-3 * std::abs(trace), gnorm, 1e-12});
                continue;
            }
            const double step[2] = {-(d * g[0] - b * g[1]) / det, -(a * g[1] - b * g[0]) / det};
            // Newton's predicted decrease, −g·step/2 at μ = 0: below round-off of φ, φ is as low as it gets.
            if (mu == 0.0 && -(g[0] * step[0] + g[1] * step[1]) <= 1e-15 * std::abs(cur.phi)) {
                converged = true;
                break;
            }
            const double trial_y[2] = {y[0] + step[0], y[1] + step[1]};
            const Vec3d trial_nu = point_at(trial_y);
            const Eval trial = evaluate(trial_nu, p);
            if (trial.phi <= cur.phi) {
                unchanged = trial.phi == cur.phi ? unchanged + 1 : 0;
                y[0] = trial_y[0], y[1] = trial_y[1];
                nu = trial_nu;
                cur = trial;
                mu *= 0.25;
                accepted = true;
                break;
            }
            mu = std::max({4.0 * mu, 1e-6 * std::abs(trace), 1e-12});
        }
        if (converged || !accepted || unchanged >= 3) break;  // at round-off: nothing left to gain
        if (std::hypot(y[0], y[1]) > 1e12) break;  // running off: h → 0 along the plane
    }
    hit.utilisation = cur.phi;  // the ray's length, in units of |u|
    Vec3d point;
    for (int i = 0; i < 3; ++i) point[i] = (p[i] + cur.phi * u[i]) * scale[i];
    hit.point = as_resultant(point);
    Vec3d normal;
    for (int i = 0; i < 3; ++i) normal[i] = nu[i] / scale[i];
    const double np = dot3(normal, point);
    if (np > 0.0)
        for (double& v : normal) v /= np;
    hit.normal = as_resultant(normal);
    return hit;
}

YieldSurface::YieldSurface(const ValidSection& section) {
    const Point c = section.reference() ? section.to_local(*section.reference()) : area_centroid(section);
    impl_ = std::make_unique<Impl>(section, c);
    reference_ = section.to_section(c);
}

YieldSurface::~YieldSurface() = default;
YieldSurface::YieldSurface(YieldSurface&&) noexcept = default;
YieldSurface& YieldSurface::operator=(YieldSurface&&) noexcept = default;

SurfaceHit YieldSurface::along(const SectionResultant& load, const std::optional<SectionResultant>& warm) const {
    Vec3d u = as_vec(load);
    for (int i = 0; i < 3; ++i) u[i] /= impl_->scale[i];
    SurfaceHit hit;
    if (norm3(u) == 0.0) return hit;  // no load: utilisation 0
    hit = impl_->ray({0.0, 0.0, 0.0}, u, warm);
    const double length = hit.utilisation;
    hit.utilisation = length > 0.0 ? 1.0 / length : std::numeric_limits<double>::infinity();
    return hit;
}

double YieldSurface::utilisation(const SectionResultant& load) const { return along(load).utilisation; }

SurfaceHit YieldSurface::from(const SectionResultant& origin, const SectionResultant& direction,
                              const std::optional<SectionResultant>& warm) const {
    Vec3d p = as_vec(origin), u = as_vec(direction);
    for (int i = 0; i < 3; ++i) p[i] /= impl_->scale[i], u[i] /= impl_->scale[i];
    if (norm3(u) == 0.0) throw InputError("yield surface: a ray needs a direction");
    const double inside = utilisation(origin);
    if (!(inside < 1.0))
        throw InputError("yield surface: the ray's origin is not inside the surface (utilisation " + std::to_string(inside) + ")");
    return impl_->ray(p, u, warm);
}

SectionResultant YieldSurface::block(const SectionResultant& normal) const {
    return as_resultant(impl_->blocks.block(as_vec(normal)).resultant);
}

SectionResultant YieldSurface::full_tension() const { return as_resultant(impl_->blocks.all_tension()); }
SectionResultant YieldSurface::scale() const { return as_resultant(impl_->scale); }
SectionResultant YieldSurface::full_compression() const { return as_resultant(impl_->blocks.all_compression()); }

}  // namespace plascap
