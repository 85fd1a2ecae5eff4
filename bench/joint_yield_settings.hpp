#pragma once
// The joint settings the engine benchmarks compare: the paper's box of independent limits and the
// coupled surface (docs/yield-surface.md), lightly loaded or near the surface. The section is a
// 0.1 × 0.1 m square whose squash load is the hanging box's weight over `load_share`.
#include <benchmark/benchmark.h>

#include <memory>

#include "plascap/adapters/plastic_joint_settings.hpp"
#include "plascap/adapters/section_yield_condition.hpp"
#include "plascap/sections/shapes.hpp"

namespace bench {

enum class Yield { Box = 0, Coupled = 1 };

// All six dofs plastic when `all_six`, else the rotations (translations rigid).
inline plascap::PlasticJointSettings joint_settings(Yield yield, double weight, double load_share, bool stiff, bool all_six) {
    const double side = 0.1, fy = weight / load_share / (side * side);
    const plascap::ValidSection section = plascap::validate_section(plascap::rectangle_section(side, side, fy));
    const auto condition = plascap::section_yield_condition(plascap::section_yield(section));
    const plascap::PerDof<double> up = condition->axis_capacity(true), down = condition->axis_capacity(false);
    plascap::PlasticJointSettings s;
    for (plascap::Dof dof : plascap::kAllDofs) {
        const std::size_t i = plascap::index(dof);
        const bool plastic = all_six || plascap::is_rotation(dof);
        s.modes[i] = plastic ? plascap::DofMode::Plastic : plascap::DofMode::Rigid;
        s.laws[i] = plascap::DofLaw{up[i], down[i], std::nullopt};
        if (stiff) s.laws[i].stiffness = 100.0;  // as the other variants: an explicit spring row
    }
    if (yield == Yield::Coupled) s.yield_condition = condition;
    return s;
}

// The YieldSurfaces cases (issue 14: coupled ≤ 1.1× box), all six dofs plastic on the square above:
// state.range(0) = 1 coupled, range(1) = 1 elastic-plastic, range(2) the load in % of the squash
// load (10: far inside, the exact U is never needed; 80: solved every step). 10 kg boxes.
inline plascap::PlasticJointSettings yield_surface_settings(const benchmark::State& state) {
    return joint_settings(state.range(0) == 1 ? Yield::Coupled : Yield::Box, 10.0 * 9.81, state.range(2) / 100.0,
                          state.range(1) == 1, true);
}

inline void yield_surface_cases(benchmark::internal::Benchmark* b) {
    b->ArgNames({"coupled", "elastic", "load%"})->ArgsProduct({{0, 1}, {0, 1}, {10, 80}})->Unit(benchmark::kMicrosecond);
}

}  // namespace bench
