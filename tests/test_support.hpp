#pragma once
// Small builders shared by the tests.
#include <cmath>
#include <utility>
#include <vector>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/geometry.hpp"

namespace plascap::test {

inline Ring box(double x0, double z0, double x1, double z1) { return {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}; }

inline Part part(Ring outer, double fy, std::vector<Ring> holes = {}) {
    return Part{std::move(outer), std::move(holes), Material{"", fy}};
}

inline Section section_of(std::vector<Part> parts, ShearCriterion shear = ShearCriterion::Tresca) {
    Section s;
    s.parts = std::move(parts);
    s.shear = shear;
    return s;
}

inline Capacities capacities_of(const Section& s, CapacitySet wanted = CapacitySet::all()) {
    return compute_capacities(validate_section(s), wanted);
}

inline double relative_error(double value, double reference) { return std::fabs(value - reference) / std::fabs(reference); }

}  // namespace plascap::test
