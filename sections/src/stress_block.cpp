#include "stress_block.hpp"

#include <cmath>

#include "bar_strength.hpp"

namespace plascap::detail {
namespace {

// The clipped-edge integrals of one side (w > 0) and the chord's moments on the line w = 0, in the
// line's frame: w across it, u along it, (w, u) right-handed like (x, z).
struct SideIntegrals {
    double area = 0.0;  // ∫ dA over w > 0        (Green: ∮ w du)
    double w = 0.0;     // ∫ w dA over w > 0      (∮ w²/2 du)
    double u = 0.0;     // ∫ u dA over w > 0      (∮ w·u du)
    double chord[3] = {0.0, 0.0, 0.0};  // ∫ u^k du over the chord, k = 0, 1, 2
};

struct LineFrame {
    Point e_w, e_u;  // unit normal of the line (towards g > 0) and its direction
    double w_offset; // w(p) = p·e_w + w_offset
};

double along(Point p, Point e) { return p.x * e.x + p.z * e.z; }

// One straight piece (w, u) a → b lying on the w ≥ 0 side; each integral is exact for linear w, u.
void add_piece(SideIntegrals& s, double wa, double ua, double wb, double ub) {
    const double du = ub - ua;
    s.area += du * (wa + wb) / 2.0;
    s.w += du * (wa * wa + wa * wb + wb * wb) / 6.0;
    s.u += du * (2.0 * wa * ua + wa * ub + wb * ua + 2.0 * wb * ub) / 6.0;
}

void add_ring(SideIntegrals& s, const Ring& ring, const LineFrame& f) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point p0 = ring[i], p1 = ring[(i + 1) % n];
        const double w0 = along(p0, f.e_w) + f.w_offset, w1 = along(p1, f.e_w) + f.w_offset;
        const double u0 = along(p0, f.e_u), u1 = along(p1, f.e_u);
        const bool in0 = w0 >= 0.0, in1 = w1 >= 0.0;
        if (in0 && in1) {
            add_piece(s, w0, u0, w1, u1);
            continue;
        }
        if (!in0 && !in1) continue;
        const double u_cross = u0 + (u1 - u0) * (w0 / (w0 - w1));
        if (in0) add_piece(s, w0, u0, 0.0, u_cross);
        else add_piece(s, 0.0, u_cross, w1, u1);
        // Walking a counter-clockwise ring, the chord starts where w rises through 0 and ends where
        // it falls: ∫ u^k du = Σ ±u^(k+1)/(k+1).
        const double sign = in0 ? 1.0 : -1.0;
        double power = u_cross;
        for (int k = 0; k < 3; ++k, power *= u_cross) s.chord[k] += sign * power / (k + 1);
    }
}

// ρ(p) = (1, −(z − c_z), x − c_x): what a unit stress at p adds to (N, Mx, Mz).
Vec3d rho(Point p, Point c) { return {1.0, -(p.z - c.z), p.x - c.x}; }

void add_scaled(Vec3d& to, const Vec3d& v, double s) {
    for (int i = 0; i < 3; ++i) to[i] += s * v[i];
}

}  // namespace

BlockSection::BlockSection(const ValidSection& section, Point reference_local) : c_(reference_local) {
    for (std::size_t p = 0; p < section.parts().size(); ++p) {
        const Part& part = section.parts()[p];
        const RingMoments& m = section.part_moments()[p];
        parts_.push_back({part, m, part.material.fy, part.material.compression_strength()});
        const Vec3d first{m.area, -(m.Sz - c_.z * m.area), m.Sx - c_.x * m.area};  // ∫ρ dA
        add_scaled(tension_, first, part.material.fy);
        add_scaled(compression_, first, -part.material.compression_strength());
        for (const Bar& bar : part.bars) {
            const BarStrength s = bar_strength(bar, part.material, ShearCriterion::Tresca);
            add_scaled(tension_, rho(bar.at, c_), s.tension * bar.area);
            add_scaled(compression_, rho(bar.at, c_), -s.compression * bar.area);
        }
    }
}

StressBlock BlockSection::block(const Vec3d& n) const {
    StressBlock out;
    const double slope = std::hypot(n[1], n[2]);  // |∇g|
    if (!(slope > 0.0)) {  // no line: the whole section on one side
        out.resultant = n[0] > 0.0 ? tension_ : n[0] < 0.0 ? compression_ : Vec3d{};
        out.support = n[0] * out.resultant[0];
        return out;
    }
    LineFrame f;
    f.e_w = {n[2] / slope, -n[1] / slope};
    f.e_u = {-f.e_w.z, f.e_w.x};
    f.w_offset = n[0] / slope - along(c_, f.e_w);
    const Point on_line{-f.w_offset * f.e_w.x, -f.w_offset * f.e_w.z};  // the line's point at u = 0
    const Vec3d rho0 = rho(on_line, c_);
    const Vec3d rho1{0.0, -f.e_u.z, f.e_u.x};  // dρ/du along the line

    for (const PartData& pd : parts_) {
        SideIntegrals s;
        add_ring(s, pd.part.outer, f);
        for (const Ring& hole : pd.part.holes) add_ring(s, hole, f);
        const RingMoments& m = pd.moments;
        const double w_total = m.Sx * f.e_w.x + m.Sz * f.e_w.z + f.w_offset * m.area;
        const double u_total = m.Sx * f.e_u.x + m.Sz * f.e_u.z;
        // σ = fy where w > 0, −fc where w < 0.
        const double force = pd.fy * s.area - pd.fc * (m.area - s.area);
        const double sigma_w = pd.fy * s.w - pd.fc * (w_total - s.w);
        const double sigma_u = pd.fy * s.u - pd.fc * (u_total - s.u);
        // p = (w − w_offset)·e_w + u·e_u, so ∫σ(p − c) dA from ∫σ, ∫σw and ∫σu.
        const double first_x = (sigma_w - f.w_offset * force) * f.e_w.x + sigma_u * f.e_u.x - c_.x * force;
        const double first_z = (sigma_w - f.w_offset * force) * f.e_w.z + sigma_u * f.e_u.z - c_.z * force;
        out.resultant[0] += force;
        out.resultant[1] += -first_z;  // Mx = −∫σ(z − c_z) dA
        out.resultant[2] += first_x;  // Mz = ∫σ(x − c_x) dA
        const double jump = (pd.fy + pd.fc) / slope;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                out.hessian[i][j] += jump * (s.chord[0] * rho0[i] * rho0[j] +
                                             s.chord[1] * (rho0[i] * rho1[j] + rho1[i] * rho0[j]) +
                                             s.chord[2] * rho1[i] * rho1[j]);
        for (const Bar& bar : pd.part.bars) {
            const BarStrength bs = bar_strength(bar, pd.part.material, ShearCriterion::Tresca);
            const bool tension = along(bar.at, f.e_w) + f.w_offset >= 0.0;
            add_scaled(out.resultant, rho(bar.at, c_), (tension ? bs.tension : -bs.compression) * bar.area);
        }
    }
    out.support = n[0] * out.resultant[0] + n[1] * out.resultant[1] + n[2] * out.resultant[2];
    return out;
}

}  // namespace plascap::detail
