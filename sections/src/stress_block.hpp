#pragma once
// The fully plastic stress block of a section for one neutral axis, in closed form over the
// polygons: the stress is fy on one side of a straight line and −fc on the other (rigid–perfectly
// plastic material; the lower- and upper-bound theorems make such blocks the boundary of the
// N–Mx–Mz interaction surface, e.g. Chen & Atsuta, "Theory of Beam-Columns", vol. 2, 1977, ch. 11).
//
// A block is chosen by a covector n = (n_N, n_Mx, n_Mz) of the resultant space: the stress is the one
// that maximises n·r, r = (N, Mx, Mz), which is fy where g(p) = n_N + n_Mz·(x − c_x) − n_Mx·(z − c_z) > 0
// and −fc where g < 0 (c = the moment reference). So
//   r(n)  = the block's resultant                 (= ∇h, Danskin's theorem),
//   h(n)  = n·r(n), the surface's support function (convex, positively homogeneous),
//   ∇²h(n) = Σ (fy + fc)/|∇g| ∫_chord ρρᵀ ds,  ρ(p) = (1, −(z − c_z), x − c_x),
// the last because moving n moves the line, and the stress jumps by fy + fc across it.
// Every integral is a sum over the rings' edges clipped to one side (Green's theorem with the line
// as one coordinate axis, so the cut adds nothing); bars add their strength difference at a point.
#include <array>
#include <vector>

#include "plascap/sections/valid_section.hpp"

namespace plascap::detail {

using Vec3d = std::array<double, 3>;
using Mat3d = std::array<Vec3d, 3>;

struct StressBlock {
    Vec3d resultant{};  // (N, Mx, Mz) [N, N·m, N·m]; moments about the reference, capacities.hpp's signs
    double support = 0.0;  // h(n) = n·resultant
    Mat3d hessian{};       // ∇²h(n); zero when the line misses the section
};

// The section reduced to what the blocks need, in local coordinates.
class BlockSection {
public:
    BlockSection(const ValidSection& section, Point reference_local);
    StressBlock block(const Vec3d& n) const;
    // Full tension (σ = fy everywhere) and full compression (σ = −fc) resultants.
    Vec3d all_tension() const { return tension_; }
    Vec3d all_compression() const { return compression_; }

private:
    struct PartData {
        Part part;  // a copy: the surface outlives the ValidSection it was built from
        RingMoments moments;
        double fy, fc;
    };
    std::vector<PartData> parts_;
    Point c_;
    Vec3d tension_{}, compression_{};
};

}  // namespace plascap::detail
