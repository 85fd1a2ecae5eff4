#pragma once
// Small scenes for the analytic tests of every engine adapter, built as plastic-sim Scenes and run
// through SceneEngine, so the same test runs on Bullet (both 6-dof constraints) and ODE: a block
// hanging from the world on a joint whose N dof is plastic (the others rigid), and a rod
// cantilevered from the world whose Mz dof is plastic. `turn` rotates the whole set-up (gravity,
// body, joint frame) for the invariance tests.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "body_energy.hpp"
#include "scene_engine.hpp"

namespace plascap::test {

struct Trace {
    std::vector<double> time, position, force, plastic, dissipated, elastic, energy;
    std::vector<double> body_y;  // the body's centre along the turned "up" axis
    double broken_at = -1.0;
};

struct Turn {
    Vec3 axis{0, 0, 1};  // unit
    double angle = 0.0;  // [rad]
};

struct HangingBlock {
    double mass = 1.0, g = 10.0, capacity = 20.0, dt = 0.01;
    std::optional<double> stiffness;
    double max_plastic_displacement = INFINITY;
    int iterations = 10, steps = 300, engage_after_steps = 0;
    Turn turn;
};

struct Cantilever {
    double mass = 2.0, length = 1.0, thickness = 0.05, g = 10.0, capacity = 20.0, dt = 0.01;
    std::optional<double> stiffness;
    int iterations = 20, steps = 300;
    Turn turn;
    double inertia_about_anchor() const {
        return mass * (length * length + thickness * thickness) / 12.0 + mass * length * length / 4.0;
    }
};

// Two free bodies (no gravity, no world) joined along y by a joint whose N dof is plastic with
// capacities F⁺ (tension) and F⁻ (compression), the others rigid, flying apart (u0 > 0) or together
// (u0 < 0) at relative speed |u0|: the relative coordinate is an oscillator of the reduced mass
// μ = m_a·m_b/(m_a + m_b). `position` in the trace is the N dof (b's elongation from a).
struct TwoBodies {
    double mass_a = 2.0, mass_b = 2.0, u0 = 4.0, capacity_tension = 20.0, capacity_compression = 10.0;
    std::optional<double> stiffness;
    double dt = 1e-3;
    int iterations = 20, steps = 2000;
    double reduced_mass() const { return mass_a * mass_b / (mass_a + mass_b); }
};

Trace run(const std::string& engine, const HangingBlock& scene);
Trace run(const std::string& engine, const TwoBodies& scene);
Trace run(const std::string& engine, const Cantilever& scene);

}  // namespace plascap::test
