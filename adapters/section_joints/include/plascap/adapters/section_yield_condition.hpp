#pragma once
// A joint's coupled yield condition from a section: the exact N–Mx–Mz surface reduced by shear and
// torsion (sections/section_yield.hpp), seen through the joint's dofs (dof.hpp): Qx, N, Qz, Mx,
// My (torsion), Mz. The bridge between the sections library and the engine-neutral law.
#include <memory>

#include "plascap/adapters/yield_condition.hpp"
#include "plascap/sections/section_yield.hpp"

namespace plascap {

std::shared_ptr<const YieldCondition> section_yield_condition(SectionYield yield);

}  // namespace plascap
