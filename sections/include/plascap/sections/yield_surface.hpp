#pragma once
// The exact fully plastic N–Mx–Mz interaction surface of a section (docs/yield-surface.md).
//
// A load r = (N, Mx, Mz) — capacities.hpp's signs, moments about the section's reference point
// (the joint point; default the area centroid) — can be carried exactly when some stress field with
// −fc ≤ σ ≤ fy everywhere has r as its resultant (lower-bound theorem). That set is convex; its
// boundary is made of stress blocks, fy on one side of a straight neutral axis and −fc on the other.
// Its support function h(n) = max n·r is the block's resultant dotted with n, in closed form over
// the polygons (stress_block.hpp). So:
//   utilisation(L) = the gauge of the set, the λ with L/λ on the boundary
//                  = max over n of n·L / h(n)  (polar duality; Rockafellar, Convex Analysis, §15)
//                  = 1 / min { h(n) : n·L = 1 },
// a convex problem in two unknowns, solved by Newton's method with the exact gradient (the block's
// resultant) and Hessian (integrals along the neutral axis), damped (Levenberg–Marquardt), to
// round-off. No tolerance decides the result beyond the solver's stopping test at round-off.
#include <memory>
#include <optional>

#include "plascap/sections/valid_section.hpp"

namespace plascap {

// A stress resultant or a load: N tension positive [N]; Mx, Mz [N·m] positive in the senses of
// the capacities Mx and Mz (capacities.hpp), about the surface's reference point.
struct SectionResultant {
    double N = 0.0;
    double Mx = 0.0;
    double Mz = 0.0;
};

// Where a ray meets the surface.
struct SurfaceHit {
    double utilisation = 0.0;   // for along(): λ with load/λ on the surface; +inf if never
    SectionResultant point;     // the surface point on the ray
    // The outward normal there, as the gradient of the utilisation at the point: the covector
    // (1/N, 1/(N·m), 1/(N·m)) with normal·point = 1. Unique where the surface is smooth; at an edge
    // or vertex (pure N, a bar on the neutral axis) one of the normals of the cone.
    SectionResultant normal;
    // The neutral axis of the block at the point: the stress is fy where
    // normal.N + normal.Mz·(x − c_x) − normal.Mx·(z − c_z) > 0, section coordinates.
    int iterations = 0;         // Newton steps taken
};

class YieldSurface {
public:
    explicit YieldSurface(const ValidSection& section);
    ~YieldSurface();
    YieldSurface(YieldSurface&&) noexcept;
    YieldSurface& operator=(YieldSurface&&) noexcept;

    // 1 on the surface, < 1 inside, > 1 outside; 0 for no load; +inf for a load the section can
    // never carry (tension of a section without tensile strength).
    double utilisation(const SectionResultant& load) const;

    // The surface point on the ray from the origin through `load`, its utilisation and normal.
    // `warm_start`, a normal from a nearby earlier hit, makes it faster.
    SurfaceHit along(const SectionResultant& load, const std::optional<SectionResultant>& warm_start = {}) const;

    // The surface point on the ray from `origin` (strictly inside the surface) along `direction`;
    // hit.utilisation is then the ray's length to it in units of |direction|. Throws InputError if
    // `origin` is not inside.
    SurfaceHit from(const SectionResultant& origin, const SectionResultant& direction,
                    const std::optional<SectionResultant>& warm_start = {}) const;

    // The stress block whose resultant maximises normal·r: the surface point with that normal.
    SectionResultant block(const SectionResultant& normal) const;

    Point reference() const { return reference_; }  // section coordinates [m]
    // The ends of the N axis: full tension Σfy·A and full compression −Σfc·A (with their moments
    // about the reference, zero for a homogeneous section).
    SectionResultant full_tension() const;
    SectionResultant full_compression() const;
    // The size of each component: the mean of the squash loads, and the mean of the plastic
    // moments about the reference either way (the solver's units; curves sample by them).
    SectionResultant scale() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    Point reference_;
};

}  // namespace plascap
