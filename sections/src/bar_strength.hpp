#pragma once
// A reinforcement bar displaces its part's material: what it adds to a capacity is its own
// strength minus the part's, times its area, at its position (both routes use this).
#include "plascap/materials/shear_criterion.hpp"
#include "plascap/sections/geometry.hpp"

namespace plascap::detail {

struct BarStrength {
    double tension = 0.0;      // fy_bar − fy_part [Pa]
    double compression = 0.0;  // fc_bar − fc_part [Pa]
    double shear = 0.0;        // τ_bar − τ_part [Pa]
};

inline BarStrength bar_strength(const Bar& bar, const Material& part, ShearCriterion shear) {
    return {bar.material.fy - part.fy, bar.material.compression_strength() - part.compression_strength(),
            shear_yield_stress(bar.material.fy, shear) - shear_yield_stress(part.fy, shear)};
}

}  // namespace plascap::detail
