#pragma once
// The engine-neutral run loop of plastic-sim: steps a SceneEngine through the scene, writes the
// per-step trace, reports progress on long runs, and returns the end state.
#include <functional>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <vector>

#include "energy_ledger.hpp"
#include "scene_engine.hpp"

namespace plascap {

struct JointSummary {
    bool engaged = false;
    std::optional<double> broken_at;  // [s]
    double plastic_displacement = 0.0;  // [m]
    double plastic_rotation = 0.0;      // [rad]
    double dissipated = 0.0;            // [J]
    double unbooked = 0.0;              // its rows' work its law did not book (energy_ledger.hpp) [J]
    PerDof<std::optional<Regime>> regimes;  // plastic dofs: the regime of the last step
    PerDof<double> omega_dt{};              // plastic dofs with a spring: ω·dt (eq. 3.2)
};

struct SimulationResult {
    double time = 0.0;
    std::size_t steps = 0;
    double wall_seconds = 0.0;
    std::vector<BodyState> bodies;
    std::vector<JointSummary> joints;
    std::vector<Vec3> nodes;  // where each scene node's material point is at the end [m]
    EnergyLedger energy;
    std::vector<std::string> warnings;  // from the engine
};

class ReplayRecorder;  // replay_recorder.hpp

struct SimulationOptions {
    std::ostream* trace_csv = nullptr;  // one row per step when set
    std::ostream* progress = nullptr;   // a line every ~2 s of wall time when set
    ReplayRecorder* replay = nullptr;   // samples the frames of plastic-sim --html when set
    // Called after every step, for a caller that watches the run (tests averaging a deflection).
    std::function<void(SceneEngine&)> after_each_step;
};

SimulationResult run_simulation(const Scene& scene, SceneEngine& engine, const SimulationOptions& options);

// The end state as the JSON summary: {"time", "bodies": {NAME: {"position", "velocity"}},
// "joints": {NAME: {"broken", "broken_at", "plastic_displacement", "plastic_rotation",
// "dissipated", ...}}, "nodes": {NAME: {"position", "displacement"}}, "energy": {...}}.
nlohmann::json json_summary(const Scene& scene, const SimulationResult& result, const std::string& engine);
void write_json_summary(std::ostream& out, const Scene& scene, const SimulationResult& result, const std::string& engine);
void write_text_summary(std::ostream& out, const Scene& scene, const SimulationResult& result, const std::string& engine);

}  // namespace plascap
