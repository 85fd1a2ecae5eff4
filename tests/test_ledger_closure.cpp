// The energy ledger closes: its remainder (what no term of the ledger's own accounts for) is the sum
// of the parts it measures apart — the contacts' work, Bullet's position corrections and the joints'
// rows' work their laws did not book (energy_ledger.hpp) — up to the integrator's own error, on every
// example and engine. And the joints' unbooked work against a closed form: the paper's tension block.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "energy_ledger.hpp"
#include "scene.hpp"
#include "simulation.hpp"

namespace plascap {
namespace {

SimulationResult run_result(const Scene& scene, const std::string& engine) {
    const std::unique_ptr<SceneEngine> e = make_engine(engine, scene);
    return run_simulation(scene, *e, {});
}

EnergyLedger run(const Scene& scene, const std::string& engine) { return run_result(scene, engine).energy; }

bool warns_of_created_energy(const SimulationResult& r) {
    for (const std::string& w : r.warnings)
        if (w.find("energy was created") != std::string::npos) return true;
    return false;
}

std::vector<std::string> engines() {
    std::vector<std::string> wanted;
    for (const std::string& name : available_engines())
        if (name == "bullet" || name == "ode" || name == "ode-step" || name == "bullet-spring2") wanted.push_back(name);
    return wanted;
}

// What is left after every measured part: the semi-implicit Euler step's own error (gravity and the
// loads do work over each step's mean velocity, the ledger books it over the end velocity), small at
// the examples' time steps. Measured 2026-12-03: at most 0.35 % of the energy handled, but for the
// simply supported beam, which handles next to nothing: on Bullet 0.35 J of 20 J (1.7 %), and on ODE
// since its split corrections (2026-12-07) 0.18 J of 3.9 J, where the corrections and the rows
// each move about 100–200 J to and fro (0.2 % of that). The scale is therefore the energy handled
// plus the corrections' work.
TEST(LedgerClosure, EveryExampleIsAccountedForOnEveryEngine) {
    ASSERT_FALSE(engines().empty());
    for (const char* name : {"cantilever-bending", "charpy-impact", "collapsing-stack", "paper-tension-block", "simply-supported-beam"}) {
        const Scene scene = read_scene_file(std::string(PLASCAP_SOURCE_DIR "/examples/scenes/") + name + ".json");
        for (const std::string& engine : engines()) {
            const SimulationResult r = run_result(scene, engine);
            const EnergyLedger& l = r.energy;
            if (engine != "bullet-spring2") {
                EXPECT_FALSE(warns_of_created_energy(r)) << name << " on " << engine;
            }
            const double left = l.remainder() - l.contacts - l.corrections - l.joints_unbooked;
            const double tolerance = std::string(name) == "simply-supported-beam" ? 0.03 : 0.005;
            EXPECT_NEAR(left, 0.0, tolerance * (l.handled + std::abs(l.corrections))) << name << " on " << engine << ": remainder " << l.remainder()
                                                          << ", contacts " << l.contacts << ", corrections " << l.corrections
                                                          << ", unbooked " << l.joints_unbooked << " of " << l.handled << " J";
        }
    }
}

// The paper's block (6,000 kg) falls freely for one step (dt = 1/60 s) and the 80 kN joint takes hold
// of it at v = g·dt. While its row holds the capacity C, the row takes C·(v0 + v1)/2·dt from the block
// each step, and the law books C·Δx = C·v1·dt (the semi-implicit Euler step moves the block by its end
// velocity): over the stop the two differ by C·Δv·dt/2 with Δv = g·dt, the velocity stopped.
TEST(LedgerClosure, TheTensionBlocksUnbookedWorkIsTheIntegratorsHalfStep) {
    const Scene scene = read_scene_file(PLASCAP_SOURCE_DIR "/examples/scenes/paper-tension-block.json");
    const double capacity = 80e3, g = 10.0, dt = scene.dt;
    const double expected = -capacity * (g * dt) * dt / 2;  // −111.1 J
    for (const std::string& engine : engines()) {
        const EnergyLedger l = run(scene, engine);
        EXPECT_NEAR(l.joints_unbooked, expected, 0.005 * std::abs(expected)) << engine;
    }
}

// plastic-sim warns when the joints' unbooked work exceeds +2 % of the energy handled, naming the joint
// with the most. Bullet's 6-dof spring paths do that in the collapsing stack's break (measured
// 2026-12-03: +7.9 %, joint-2 +1.34 kJ; docs/structures.md, "Known limits") — the case this checks;
// should those paths stop creating energy there, it needs another.
TEST(LedgerClosure, CreatedEnergyIsWarnedOfNamingTheJoint) {
    const Scene scene = read_scene_file(PLASCAP_SOURCE_DIR "/examples/scenes/collapsing-stack.json");
    bool tried = false;
    for (const std::string& engine : available_engines()) {
        if (engine != "bullet-spring2") continue;
        tried = true;
        const SimulationResult r = run_result(scene, engine);
        ASSERT_TRUE(warns_of_created_energy(r)) << "joints_unbooked " << r.energy.joints_unbooked << " of " << r.energy.handled;
        bool named = false;
        for (const std::string& w : r.warnings) named = named || w.find("\"joint-2\"") != std::string::npos;
        EXPECT_TRUE(named);
    }
    EXPECT_TRUE(tried) << "this build has no bullet-spring2 engine";
}

}  // namespace
}  // namespace plascap
