#include "mesh_neutral_axis.hpp"

#include "gsl_errors.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

namespace plascap::detail {
namespace {

struct LevelTriangle {
    std::array<double, 3> level;  // sorted levels of the corners
    double area = 0.0;
    SideStrengths strength;
};

// Area of the triangle beyond t (level > t). By similar triangles: the piece cut off at a corner
// is area·(distance to the corner)² / (product of that corner's two level spans).
double area_above(const LevelTriangle& t, double level) {
    const auto& [l0, l1, l2] = t.level;
    if (level >= l2) return 0.0;
    if (level <= l0) return t.area;
    if (level >= l1) return t.area * (l2 - level) * (l2 - level) / ((l2 - l0) * (l2 - l1));
    return t.area - t.area * (level - l0) * (level - l0) / ((l2 - l0) * (l1 - l0));
}

struct LevelBar {
    double level, area;
    SideStrengths strength;
};

struct Balance {
    std::vector<LevelTriangle> triangles;
    std::vector<LevelBar> bars;
    // Σ s_above·A_above − s_below·A_below: positive below the axis, negative above it.
    double operator()(double level) const {
        double sum = 0.0;
        for (const LevelTriangle& t : triangles) {
            const double above = area_above(t, level);
            sum += t.strength.above * above - t.strength.below * (t.area - above);
        }
        for (const LevelBar& b : bars) sum += b.level > level ? b.strength.above * b.area : -b.strength.below * b.area;
        return sum;
    }
};

double balance_at(double level, void* balance) { return (*static_cast<const Balance*>(balance))(level); }

Balance make_balance(const SectionMesh& mesh, const std::vector<SideStrengths>& strength_of_part,
                     const std::vector<PointArea>& bars, BendingAxis axis) {
    Balance balance;
    balance.triangles.reserve(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& corner = mesh.triangles[i];
        const Point a = mesh.vertices[corner[0]], b = mesh.vertices[corner[1]], c = mesh.vertices[corner[2]];
        LevelTriangle t;
        t.level = {level_of(a, axis), level_of(b, axis), level_of(c, axis)};
        std::sort(t.level.begin(), t.level.end());
        t.area = 0.5 * std::abs((b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z));
        t.strength = strength_of_part[mesh.part_of[i]];
        balance.triangles.push_back(t);
    }
    for (const PointArea& bar : bars) balance.bars.push_back({level_of(bar.at, axis), bar.area, bar.strength});
    return balance;
}

// Middle of the gap around t when no triangle has material at t; t itself otherwise.
double middle_of_gap(const Balance& balance, double t) {
    double below = -std::numeric_limits<double>::infinity(), above = std::numeric_limits<double>::infinity();
    for (const LevelTriangle& tri : balance.triangles) {
        if (tri.level[0] < t && tri.level[2] > t) return t;
        if (tri.level[2] <= t) below = std::max(below, tri.level[2]);
        if (tri.level[0] >= t) above = std::min(above, tri.level[0]);
    }
    return 0.5 * (below + above);
}

}  // namespace

double mesh_neutral_axis(const SectionMesh& mesh, const std::vector<SideStrengths>& strength_of_part,
                         const std::vector<PointArea>& bars, BendingAxis axis) {
    const GslErrorsReturned errors_returned;
    const Balance balance = make_balance(mesh, strength_of_part, bars, axis);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const LevelTriangle& t : balance.triangles) {
        lo = std::min(lo, t.level[0]);
        hi = std::max(hi, t.level[2]);
    }
    const double resolution = 4.0 * std::numeric_limits<double>::epsilon() * std::max({hi - lo, std::abs(lo), std::abs(hi)});
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
    gsl_function f{&balance_at, const_cast<Balance*>(&balance)};
    // A side without strength (concrete in tension) puts the axis at the section's edge.
    if (balance(hi) >= 0.0) return hi;
    if (balance(lo) <= 0.0) return lo;
    gsl_root_fsolver_set(solver.get(), &f, lo, hi);  // balance(lo) > 0 > balance(hi)
    for (int iteration = 0; iteration < 400; ++iteration) {
        if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
        lo = gsl_root_fsolver_x_lower(solver.get());
        hi = gsl_root_fsolver_x_upper(solver.get());
        if (hi - lo <= resolution) break;
    }
    return middle_of_gap(balance, gsl_root_fsolver_root(solver.get()));
}

}  // namespace plascap::detail
