#pragma once
// The springs the engine benchmarks give their hanging box's plastic dofs, and a count of the springs
// a run really sampled.
//
// The box: 10 kg, 0.4 × 1.0 × 0.4 m, held at the centre of its top face, stepped at 1/60 s. A dof's
// spring is sampled as an explicit force only while √(k/m)·dt ≤ 0.25 (the paper's eq. 3.2, m the
// row's effective mass; regime.hpp); past it the dof holds as a rigid-plastic row. The effective
// masses at that anchor (a box's inertia, I = m·(a² + b²)/12; a row at lever r from the centre of
// mass, 1/m_eff = 1/m + r²/I):
//   N (along the box's long axis):  10 kg;
//   Qx, Qz (r = 0.5 m, I = 0.967 kg·m²): 2.79 kg;
//   Mx, Mz: 0.967 kg·m²;  My (twist about the long axis): 0.267 kg·m².
//
//   Stiff   — 5,000 N/m and 100 N·m/rad on every dof (the variant the sweeps have always measured):
//             ω·dt = 0.37 (N), 0.71 (Qx, Qz), 0.32 (My), all past the limit, so only Mx and Mz
//             (0.17) are springs: four rigid-plastic rows and two springs.
//   Sampled — every spring within the limit: Qx, Qz 500 N/m (0.22), N 2,000 N/m (0.24), Mx, Mz
//             100 N·m/rad (0.17), My 50 N·m/rad (0.23): six springs. The box sags 4.9 cm under its
//             weight and swings about that undamped.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <optional>

#include "plascap/adapters/dof.hpp"
#include "plascap/adapters/plastic_joint_law.hpp"

namespace bench {

enum class Springs { None = 0, Stiff = 1, Sampled = 2 };

inline std::optional<double> spring_stiffness(Springs springs, plascap::Dof dof) {
    using plascap::Dof;
    switch (springs) {
        case Springs::None:
            return std::nullopt;
        case Springs::Stiff:
            return plascap::is_rotation(dof) ? 100.0 : 5000.0;
        case Springs::Sampled:
            if (dof == Dof::N) return 2000.0;
            if (dof == Dof::My) return 50.0;
            return plascap::is_rotation(dof) ? 100.0 : 500.0;
    }
    return std::nullopt;
}

// The counter `springs`: the dofs per joint whose law stepped as an elastic-plastic spring in the
// last step (the rest held as rows), so that a variant's name can be checked against what it ran.
// `law_of(i)`: the law of joint i of `count`.
template <class LawOf>
void count_springs(benchmark::State& state, std::size_t count, LawOf&& law_of) {
    std::size_t springs = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const plascap::PlasticJointLaw& law = law_of(i);
        for (plascap::Dof dof : plascap::kAllDofs) {
            const plascap::ElasticPlasticLaw* dof_law = law.law(dof);
            if (dof_law != nullptr && dof_law->regime() == plascap::Regime::ElasticPlastic) ++springs;
        }
    }
    state.counters["springs"] = count == 0 ? 0.0 : static_cast<double>(springs) / static_cast<double>(count);
}

}  // namespace bench
