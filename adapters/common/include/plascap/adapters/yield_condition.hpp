#pragma once
// A joint's coupled yield condition: one convex function U of the six loads the joint carries,
// U = 1 on the yield surface (docs/yield-surface.md). Engine-neutral: the law (plastic_joint_law.hpp)
// needs only U and its gradient; where the surface comes from (a section's exact surface,
// section_yield_condition.hpp) is not its business.
//
// Loads are the section's stress resultants per dof, load = −(generalised force on body b), so a
// load's sign is that of the dof motion it resists: N > 0 is tension (resists elongation), Mx > 0
// resists positive rotation about x, and so on (capacities.hpp's senses).
#include <array>

#include "plascap/adapters/dof.hpp"

namespace plascap {

struct YieldEvaluation {
    double utilisation = 0.0;  // U(load); +inf where the load can never be carried
    PerDof<double> gradient{};  // ∂U/∂load, the outward normal [1/N, 1/(N·m)]
};

// A few numbers a condition may keep between calls to start near its last answer (the solve of an
// exact surface converges in 1–3 steps from there). Each joint keeps its own.
struct YieldHint {
    std::array<double, 3> values{};
    bool valid = false;
};

class YieldCondition {
public:
    virtual ~YieldCondition() = default;
    virtual YieldEvaluation evaluate(const PerDof<double>& loads, YieldHint& hint) const = 0;
    // Where the surface meets each positive and negative dof axis, the others 0: the capacities
    // of the independent-limit ("box") law of the same section [N | N·m].
    virtual PerDof<double> axis_capacity(bool positive) const = 0;
};

}  // namespace plascap
