#include "simulation.hpp"

#include <chrono>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

#include "body_energy.hpp"
#include "replay_recorder.hpp"
#include "trace_csv.hpp"

namespace plascap {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

JointSummary summarise(const PlasticJointLaw* law) {
    JointSummary s;
    if (!law) return s;
    s.engaged = true;
    s.broken_at = law->broken_at();
    s.plastic_displacement = law->plastic_displacement();
    s.plastic_rotation = law->plastic_rotation();
    s.dissipated = law->dissipated();
    for (Dof dof : kAllDofs) {
        if (const ElasticPlasticLaw* dof_law = law->law(dof)) {
            s.regimes[index(dof)] = dof_law->regime();
            s.omega_dt[index(dof)] = dof_law->omega_dt();
        }
    }
    return s;
}

// The joints' rows did more work on their bodies than their laws booked, by more than 2 % of the energy
// handled (the ledger's tolerance, docs/structures.md): some joint created energy. Names the joint
// with the most.
std::optional<std::string> energy_created_warning(const Scene& scene, const SimulationResult& r) {
    const EnergyLedger& e = r.energy;
    if (!(e.joints_unbooked > 0.02 * e.handled)) return std::nullopt;
    std::size_t worst = 0;
    for (std::size_t j = 1; j < r.joints.size(); ++j)
        if (r.joints[j].unbooked > r.joints[worst].unbooked) worst = j;
    std::ostringstream w;
    w << std::setprecision(4) << "the joints' rows did " << e.joints_unbooked << " J (" << std::fixed << std::setprecision(1)
      << 100.0 * e.joints_unbooked / e.handled << " % of the energy handled) more work than their laws booked: energy was created, most by joint \""
      << scene.joints[worst].name << "\" (" << std::defaultfloat << std::setprecision(4) << r.joints[worst].unbooked
      << " J); see docs/structures.md, \"Output\" (joints_unbooked)";
    return w.str();
}

}  // namespace

SimulationResult run_simulation(const Scene& scene, SceneEngine& engine, const SimulationOptions& options) {
    const Clock::time_point start = Clock::now();
    double next_report = 2.0;  // [s of wall time]
    SimulationResult result;
    result.steps = scene.steps();
    if (options.trace_csv) write_trace_header(*options.trace_csv, scene);
    EnergyAccount energy(scene, engine);
    if (options.replay) options.replay->record_start(engine, energy.ledger());
    if (options.progress)  // what the engine foresees, before a run it may make long
        for (const std::string& w : engine.warnings()) *options.progress << "plastic-sim: warning: " << w << std::endl;
    for (std::size_t i = 0; i < result.steps; ++i) {
        const std::vector<AppliedLoad> loads = apply_scene_loads(scene, engine);
        engine.step();
        energy.after_step(engine, loads);
        if (options.trace_csv) write_trace_row(*options.trace_csv, scene, engine, energy.ledger());
        if (options.replay) options.replay->after_step(i + 1, engine, energy.ledger());
        if (options.after_each_step) options.after_each_step(engine);
        if (options.progress && seconds_since(start) >= next_report) {
            next_report += 2.0;
            *options.progress << "plastic-sim: step " << i + 1 << " of " << result.steps << " (t = " << engine.time()
                              << " s, " << (100 * (i + 1)) / result.steps << " %)" << std::endl;
        }
    }
    result.time = engine.time();
    result.wall_seconds = seconds_since(start);
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) result.bodies.push_back(engine.body(i));
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        result.joints.push_back(summarise(engine.joint_law(j)));
        result.joints.back().unbooked = unbooked_work(engine, j);
    }
    for (const SceneNode& n : scene.nodes) result.nodes.push_back(world_point(engine.body(n.at.body), n.at.local));
    result.energy = energy.ledger();
    result.warnings = engine.warnings();
    if (const std::optional<std::string> w = energy_created_warning(scene, result)) result.warnings.push_back(*w);
    return result;
}

}  // namespace plascap
