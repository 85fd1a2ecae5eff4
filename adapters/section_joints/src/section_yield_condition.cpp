#include "plascap/adapters/section_yield_condition.hpp"

#include <cmath>

namespace plascap {
namespace {

SectionLoads section_loads(const PerDof<double>& l) {
    return {l[index(Dof::N)], l[index(Dof::Qx)], l[index(Dof::Qz)], l[index(Dof::Mx)], l[index(Dof::Mz)], l[index(Dof::My)]};
}

PerDof<double> per_dof(const SectionLoads& s) {
    PerDof<double> l{};
    l[index(Dof::N)] = s.N, l[index(Dof::Qx)] = s.Qx, l[index(Dof::Qz)] = s.Qz;
    l[index(Dof::Mx)] = s.Mx, l[index(Dof::Mz)] = s.Mz, l[index(Dof::My)] = s.T;
    return l;
}

class SectionYieldCondition final : public YieldCondition {
public:
    explicit SectionYieldCondition(SectionYield yield) : yield_(std::move(yield)) {}

    YieldEvaluation evaluate(const PerDof<double>& loads, YieldHint& hint) const override {
        std::optional<SectionResultant> warm;
        if (hint.valid) warm = SectionResultant{hint.values[0], hint.values[1], hint.values[2]};
        const SectionYieldState state = yield_.evaluate(section_loads(loads), warm);
        if (state.nm_normal) {
            hint.values = {state.nm_normal->N, state.nm_normal->Mx, state.nm_normal->Mz};
            hint.valid = true;
        }
        return {state.utilisation, per_dof(state.gradient)};
    }

    PerDof<double> axis_capacity(bool positive) const override {
        const double sign = positive ? 1.0 : -1.0;
        const YieldSurface& s = yield_.surface();
        const auto on_axis = [&](SectionResultant direction) { return 1.0 / s.utilisation(direction); };
        PerDof<double> c{};
        c[index(Dof::N)] = on_axis({sign, 0, 0});
        c[index(Dof::Mx)] = on_axis({0, sign, 0});
        c[index(Dof::Mz)] = on_axis({0, 0, sign});
        c[index(Dof::Qx)] = yield_.shear_torsion().Qx;
        c[index(Dof::Qz)] = yield_.shear_torsion().Qz;
        c[index(Dof::My)] = yield_.shear_torsion().T;
        return c;
    }

private:
    SectionYield yield_;
};

}  // namespace

std::shared_ptr<const YieldCondition> section_yield_condition(SectionYield yield) {
    return std::make_shared<SectionYieldCondition>(std::move(yield));
}

}  // namespace plascap
