#pragma once
// A plain 3-vector of doubles for the engine-neutral code: world coordinates [m, N, N·m].
#include <array>

namespace plascap {

using Vec3 = std::array<double, 3>;

}  // namespace plascap
