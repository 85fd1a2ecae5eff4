#pragma once
// Small builders shared by the tests.
#include <cmath>
#include <random>
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

// A random star-shaped (hence simple) polygon around `centre`, 3 to 60 vertices; `snap` rounds
// the vertices to a 1/8 grid so that many share a level.
inline Ring random_star(std::mt19937& rng, Point centre, double radius, bool snap) {
    std::uniform_int_distribution<int> count(3, 60);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int n = count(rng);
    const double pi = std::acos(-1.0);
    Ring ring;
    for (int i = 0; i < n; ++i) {
        // Angles strictly increasing inside their own sector keep the star simple.
        const double angle = 2.0 * pi * (i + 0.1 + 0.8 * unit(rng)) / n;
        const double r = radius * (0.3 + 0.7 * unit(rng));
        Point p{centre.x + r * std::cos(angle), centre.z + r * std::sin(angle)};
        if (snap) p = {std::round(p.x * 8.0) / 8.0, std::round(p.z * 8.0) / 8.0};
        if (ring.empty() || p.x != ring.back().x || p.z != ring.back().z) ring.push_back(p);
    }
    return ring;
}

inline double relative_error(double value, double reference) { return std::fabs(value - reference) / std::fabs(reference); }

}  // namespace plascap::test
