#pragma once
// plastic-sim --html: the run as one self-contained page that replays it in 3-D (three.js) with its
// energy ledger and the joints' states (docs/replay.md).
#include <string>

#include "replay_recorder.hpp"
#include "simulation.hpp"

namespace plascap {

struct ReplayPageInfo {
    std::string title;   // the scene file's name
    std::string engine;  // the engine's description
    ReplayBudget budget;
};

// Throws InputError when the file cannot be written.
void write_replay_page(const std::string& path, const Scene& scene, const SimulationResult& result, const ReplayRecorder& replay,
                       const ReplayPageInfo& info);

}  // namespace plascap
