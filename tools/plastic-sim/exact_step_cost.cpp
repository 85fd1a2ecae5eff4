#include "exact_step_cost.hpp"

#include <boost/pending/disjoint_sets.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <vector>

namespace plascap {
namespace {

// A step of one island of `rows` rows, from dWorldStep on a straight chain of IPE 200 segments
// (2-core VM, 2026-12-07): 0.18 s at 1,206 rows, 1.6 s at 2,406 and 19 s at 4,806 — rows^3.4
// through the last point. An order of magnitude, not a promise: machines differ.
double seconds_a_step(std::size_t rows) { return 19.0 * std::pow(static_cast<double>(rows) / 4806.0, 3.4); }

// Warn when the run is likely to take longer than this.
constexpr double kWarnAfterSeconds = 600.0;

std::size_t rows_of(const SceneJoint& j) {
    std::size_t rows = 0;
    for (DofMode mode : j.settings.modes) rows += mode == DofMode::Free ? 0 : 1;
    return rows;
}

}  // namespace

Island largest_island(const Scene& scene) {
    const std::size_t n = scene.bodies.size();
    std::vector<std::size_t> rank(n), parent(n);
    boost::disjoint_sets<std::size_t*, std::size_t*> sets(rank.data(), parent.data());
    for (std::size_t i = 0; i < n; ++i) sets.make_set(i);
    const auto moving = [&](std::size_t body) { return !scene.bodies[body].is_static; };
    for (const SceneJoint& j : scene.joints)
        if (j.a && moving(*j.a) && moving(j.b)) sets.union_set(*j.a, j.b);
    std::vector<Island> islands(n);
    for (std::size_t i = 0; i < n; ++i)
        if (moving(i)) ++islands[sets.find_set(i)].bodies;
    for (const SceneJoint& j : scene.joints) {
        if (moving(j.b)) {
            islands[sets.find_set(j.b)].rows += rows_of(j);
        } else if (j.a && moving(*j.a)) {
            islands[sets.find_set(*j.a)].rows += rows_of(j);
        }
    }
    Island largest;
    for (const Island& island : islands)
        if (island.rows > largest.rows) largest = island;
    return largest;
}

std::optional<std::string> exact_step_warning(const Scene& scene) {
    const Island island = largest_island(scene);
    const double step = seconds_a_step(island.rows);
    const double run = step * static_cast<double>(scene.steps());
    if (!(run > kWarnAfterSeconds)) return std::nullopt;
    std::ostringstream w;
    w << std::fixed << std::setprecision(1) << "ode-step (dWorldStep) solves the largest island's " << island.rows << " rows ("
      << island.bodies << " bodies joined by joints) as one dense LCP, whose cost grows as rows³: about " << step
      << " s a step, " << run / 3600.0 << " h for the scene's " << scene.steps()
      << " steps on a 2-core machine; --engine ode (dWorldQuickStep) iterates instead";
    return w.str();
}

}  // namespace plascap
