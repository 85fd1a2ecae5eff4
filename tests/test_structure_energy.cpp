// The energy ledger over random small frames (docs/structures.md, "Energy"): a joint law that never
// creates energy keeps the ledger's remainder — kinetic + gravitational + elastic + dissipated − work
// of the loads — at or below zero (the solver's slack only takes energy); here within +2 % of the
// energy handled (less what the engines' split position corrections did, which the ledger measures
// apart). Random trees of 2 to 4 members of standard shapes (S355), 1 to 4 segments each,
// fixed at the first node, under gravity and one random force (8 to 60 kN, ramped on over 0.3 s), for 0.6 s,
// on Bullet, ODE's QuickStep (`ode`) and ODE's exact LCP (`ode-step`).
//
// Every run must meet the bound. Until ODE's rows were warm-started with their corrections split off
// (OdePlasticJoints::Stepper::QuickSplit) one QuickStep run of the sixteen did not: frame 10, a
// four-segment column folding under 23 kN at 13 m/s, read +8.5 %, where QuickStep's iterations left
// the rigid rows (N, Qx, Qz at several MN of capacity) tens of millimetres off and their Baumgarte
// targets pulled the bodies back inside the velocity solve, work no law books (docs/structures.md,
// "Known limits"); it reads −10.9 % now.
//
// Both engines' rotation rows are swing and twist (swing_twist.hpp), without the Euler angles'
// singularity at a 90° twist, where the Euler rows' axes degenerate (e_x ∥ e_z) and ODE's rows, while
// they were Euler axes, created energy (docs/structures.md, "Known limits"): every run is checked,
// and some must have twisted a joint through a quarter turn, where the Euler rows failed.
// scripts/random-frame-energy.py reports every frame.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "scene.hpp"
#include "energy_ledger.hpp"
#include "simulation.hpp"

namespace plascap {
namespace {

std::string random_frame(std::mt19937& rng) {
    const auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const auto integer = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    // No CHS: the Saint-Venant J of a CHS 168.3×8 (for the segments' GJ/ℓ) takes 13 s to mesh and solve.
    const char* shapes[] = {"IPE 200", "HEB 200", "SHS 200x200x10"};
    const int n = integer(3, 5);
    std::ostringstream s;
    s << R"({"dt": 0.002, "duration": 0.6, "iterations": 100, "gravity": [0, -9.81, 0], "nodes": {)";
    for (int i = 0; i < n; ++i)
        s << (i ? ", " : "") << "\"N" << i << "\": [" << uniform(0, 4) << ", " << uniform(0, 3) << ", " << uniform(-0.5, 0.5) << "]";
    s << R"(}, "members": [)";
    for (int i = 1; i < n; ++i)
        s << (i > 1 ? ", " : "") << R"({"name": "m)" << i << R"(", "from": "N)" << integer(0, i - 1) << R"(", "to": "N)" << i
          << R"(", "shape": ")" << shapes[integer(0, 2)] << R"(", "material": "S355", "segments": )" << integer(1, 4) << "}";
    // A random direction, and a magnitude from 8 to 60 kN, uniform in its logarithm: from frames that stay
    // elastic to frames that fold.
    const double magnitude = 8e3 * std::pow(7.5, uniform(0, 1));
    double d[3] = {uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    s << R"(], "supports": {"N0": "fixed"}, "loads": [{"node": "N)" << integer(1, n - 1) << R"(", "force": [)"
      << magnitude * d[0] / length << ", " << magnitude * d[1] / length << ", " << magnitude * d[2] / length
      << R"(], "history": [[0, 0], [0.3, 1]]}]})";
    return s.str();
}

struct FrameRun {
    EnergyLedger energy;
    double closest_to_quarter_twist = INFINITY;  // the least |90° − |My position|| any joint reached [rad]
};

// Runs the scene as plastic-sim does, watching every joint's twist.
FrameRun run_frame(const Scene& scene, const std::string& engine) {
    const std::unique_ptr<SceneEngine> e = make_engine(engine, scene);
    FrameRun r;
    SimulationOptions watch;
    watch.after_each_step = [&](SceneEngine& stepped) {
        for (std::size_t j = 0; j < scene.joints.size(); ++j) {
            if (!stepped.joint_law(j)) continue;
            const double twist = std::abs(stepped.joint_positions(j)[index(Dof::My)]);
            r.closest_to_quarter_twist = std::min(r.closest_to_quarter_twist, std::abs(M_PI / 2 - twist));
        }
    };
    r.energy = run_simulation(scene, *e, watch).energy;
    return r;
}

TEST(StructureEnergy, RandomFramesCreateNoEnergy) {
    std::mt19937 rng(20261201);
    int checked = 0, yielded = 0, quarter_twists = 0;
    for (int frame = 0; frame < 16; ++frame) {
        const std::string json = random_frame(rng);
        const Scene scene = parse_scene_json(json);
        for (const std::string engine : {"bullet", "ode", "ode-step"}) {
            const FrameRun r = run_frame(scene, engine);
            const EnergyLedger& l = r.energy;
            std::printf("frame %d %s: dissipated %.2f, remainder %+.3f (position corrections %+.3f, joints unbooked %+.3f) of %.0f J; closest to a 90-degree twist %.1f deg\n",
                        frame, engine.c_str(), l.dissipated / l.handled, l.remainder() / l.handled, l.corrections / l.handled,
                        l.joints_unbooked / l.handled, l.handled,
                        r.closest_to_quarter_twist * 180 / M_PI);
            ++checked;
            if (l.dissipated > 0.1 * l.handled) ++yielded;
            if (r.closest_to_quarter_twist < 1 * M_PI / 180) ++quarter_twists;
            // Bullet's split-impulse position corrections do work outside the velocity solve, where
            // the joints act; the ledger measures it (energy_ledger.hpp) and it is left out here.
            const double created = l.remainder() - l.corrections;
            // The same, from the joints' side: their rows' work less what their laws booked (rows_work.hpp).
            const double unbooked = l.joints_unbooked;
            EXPECT_LE(created, 0.02 * l.handled) << "frame " << frame << " on " << engine << ": " << json;
            EXPECT_LE(unbooked, 0.02 * l.handled) << "frame " << frame << " on " << engine << ": " << json;
        }
    }
    // The property must have been tried where it matters: on frames that yielded substantially, and
    // through a 90° twist.
    EXPECT_GE(yielded, 6) << checked << " runs checked";
    EXPECT_GE(quarter_twists, 2) << checked << " runs checked";
    std::printf("random frames: %d runs checked (%d yielded, dissipating > 10 %% of the energy; %d twisted a joint within 1 deg of 90 deg)\n",
                checked, yielded, quarter_twists);
}

}  // namespace
}  // namespace plascap
