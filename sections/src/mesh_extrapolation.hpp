#pragma once
// Meshes of halving triangle area until a quantity with a smooth O(h^p) discretisation error (J by
// FEM, from one side) settles: halving the area divides the error by r = 2^(p/2), so
// R = (r·Q(h/√2) − Q(h))/(r − 1) removes its leading term, and the change of R between levels
// estimates R's own error (and exposes slower convergence at re-entrant corners, where the law
// does not hold).
#include <cmath>
#include <cstddef>

#include "plascap/input_error.hpp"

namespace plascap::detail {

struct Extrapolated {
    double value = 0.0;
    double error = 0.0;
    std::size_t triangles = 0;  // of the finest mesh
    bool converged = false;
};

// solve(max_area, triangles&) → Q on a mesh with that triangle area bound. Starts at area/64.
template <class Solve>
Extrapolated extrapolate_over_meshes(Solve solve, double area, double tolerance, std::size_t max_triangles,
                                     double order) {
    if (!(tolerance > 0.0 && tolerance < 1.0)) throw InputError("the relative tolerance must be between 0 and 1");
    Extrapolated result;
    double max_area = area / 64.0, previous_Q = 0.0, previous_R = 0.0;
    for (int level = 0;; ++level, max_area /= 2.0) {
        std::size_t triangles = 0;
        const double Q = solve(max_area, triangles);
        result.triangles = triangles;
        if (level > 0) {
            const double r = std::pow(2.0, order / 2.0);
            const double R = (r * Q - previous_Q) / (r - 1.0);
            if (level > 1) {
                result.value = R;
                result.error = std::abs(R - previous_R);
                if (result.error <= tolerance * std::abs(R)) {
                    result.converged = true;
                    return result;
                }
                if (2 * triangles > max_triangles) return result;
            }
            previous_R = R;
        }
        previous_Q = Q;
    }
}

}  // namespace plascap::detail
