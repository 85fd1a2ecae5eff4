#pragma once
// What ODE's dWorldStep (plastic-sim's `ode-step`) will cost a scene before it runs. dWorldStep
// solves each island — bodies joined to each other by joints — as one dense LCP over all its rows
// (ODE's Dantzig solver, lcp.cpp), so a step costs about rows³: a whole building takes minutes a
// step where dWorldQuickStep takes milliseconds (docs/structures.md, "Known limits").
#include <cstddef>
#include <optional>
#include <string>

#include "scene.hpp"

namespace plascap {

struct Island {
    std::size_t bodies = 0;
    std::size_t rows = 0;  // the joints' rows: their dofs that are not free, at most
};

// The island with the most rows, as the scene's joints join its moving bodies (a static body holds
// like the world and joins nothing). Contacts made during the run may join islands further.
Island largest_island(const Scene& scene);

// A warning when `ode-step` would take longer than a few minutes on the scene, naming the island,
// the seconds a step it is likely to take and what to use instead; none otherwise.
std::optional<std::string> exact_step_warning(const Scene& scene);

}  // namespace plascap
