// The energy ledger's `contacts`: the work the contacts' impulses did (impulse_work.hpp), measured on
// Bullet (BulletWorld) and ODE (OdePlasticJoints::collide), against closed forms where the contacts
// take all the energy there is, and on an example whose pieces fall onto the ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "energy_ledger.hpp"
#include "scene.hpp"
#include "simulation.hpp"

namespace plascap {
namespace {

// A 0.5 m cube of 1,000 kg/m³ (125 kg) resting on a static ground, with `motion` (a JSON member).
std::string cube_on_ground(const std::string& motion, double height = 0.25) {
    return R"({"dt": 0.004, "duration": 2.0, "iterations": 50, "gravity": [0, -9.81, 0], "bodies": [
        {"name": "ground", "box": [40, 1, 40], "mass": 1, "position": [0, -0.5, 0], "static": true},
        {"name": "cube", "box": [0.5, 0.5, 0.5], "density": 1000, "position": [0, )" +
           std::to_string(height) + R"(, 0])" + (motion.empty() ? "" : ", " + motion) + R"(}], "joints": []})";
}

constexpr double kMass = 125.0, kGravity = 9.81;

SimulationResult run(const std::string& json, const std::string& engine) {
    const Scene scene = parse_scene_json(json);
    const std::unique_ptr<SceneEngine> e = make_engine(engine, scene);
    return run_simulation(scene, *e, {});
}

std::vector<std::string> engines() {
    std::vector<std::string> wanted;
    for (const std::string& name : available_engines())
        if (name == "bullet" || name == "ode" || name == "ode-step") wanted.push_back(name);
    return wanted;
}

// Sliding at 3 m/s, the cube stops by friction (0.25 on both engines: Bullet's 0.5 per body,
// multiplied; ODE's surface): the contacts took all of ½mv² = 562.5 J, over v²/(2μg) = 1.835 m.
TEST(ContactEnergy, FrictionTakesTheKineticEnergyOfASlidingCube) {
    ASSERT_FALSE(engines().empty());
    for (const std::string& engine : engines()) {
        const SimulationResult r = run(cube_on_ground(R"("velocity": [3, 0, 0])"), engine);
        const EnergyLedger& l = r.energy;
        EXPECT_NEAR(l.kinetic, 0.0, 1e-6) << engine;
        EXPECT_NEAR(l.contacts, -0.5 * kMass * 9.0, 0.005 * 562.5) << engine;
        EXPECT_NEAR(l.remainder() - l.contacts, 0.0, 0.005 * l.handled) << engine;
    }
}

// Spinning at 4 rad/s about the vertical, the cube stops by friction's torque: the contacts took
// ½Iω² with I = m(a² + a²)/12 — the angular part of the contacts' impulses, through their lever arms.
TEST(ContactEnergy, FrictionTakesTheKineticEnergyOfASpinningCube) {
    const double inertia = kMass * 2 * 0.25 / 12, expected = -0.5 * inertia * 16.0;
    for (const std::string& engine : engines()) {
        const EnergyLedger l = run(cube_on_ground(R"("angular_velocity": [0, 4, 0])"), engine).energy;
        EXPECT_NEAR(l.kinetic, 0.0, 1e-6) << engine;
        EXPECT_NEAR(l.contacts, expected, 0.005 * std::abs(expected)) << engine;
        EXPECT_NEAR(l.remainder() - l.contacts, 0.0, 0.005 * l.handled) << engine;
    }
}

// Dropped from 1 m onto the ground without bounce, the cube comes to rest: the impact took m·g·h.
TEST(ContactEnergy, AnImpactWithoutBounceTakesTheFall) {
    for (const std::string& engine : engines()) {
        const EnergyLedger l = run(cube_on_ground("", 1.25), engine).energy;
        EXPECT_NEAR(l.kinetic, 0.0, 1e-6) << engine;
        EXPECT_NEAR(l.contacts, -kMass * kGravity * 1.0, 0.005 * kMass * kGravity) << engine;
        EXPECT_NEAR(l.remainder() - l.contacts, 0.0, 0.005 * l.handled) << engine;
    }
}

// The example stack: its storeys yield, break and fall onto the ground and onto each other (contacts
// between moving bodies). Nearly all the energy handled goes into the contacts; what the ledger cannot
// place — its remainder less the contacts and the position corrections — stays within 2 %.
TEST(ContactEnergy, TheCollapsingStackBalancesOnceTheContactsAreCounted) {
    const Scene scene = read_scene_file(PLASCAP_SOURCE_DIR "/examples/scenes/collapsing-stack.json");
    for (const std::string& engine : engines()) {
        const std::unique_ptr<SceneEngine> e = make_engine(engine, scene);
        const EnergyLedger l = run_simulation(scene, *e, {}).energy;
        EXPECT_LT(l.contacts, -0.8 * l.handled) << engine;
        EXPECT_NEAR(l.remainder() - l.contacts - l.corrections, 0.0, 0.02 * l.handled) << engine;
    }
}

}  // namespace
}  // namespace plascap
