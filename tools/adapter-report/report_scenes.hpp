#pragma once
// The scenes the adapter report runs, built in code: a load hanging on a plastic axial joint from an
// anchor body that is itself held rigidly by the world (the suddenly loaded elastic–perfectly-
// plastic oscillator of docs/references.md when the anchor holds still).
#include "scene.hpp"

namespace plascap::report {

struct OscillatorCase {
    double stiffness = 100.0;      // k [N/m]
    double mass_ratio = 1.0;       // load mass / anchor mass
    double dt = 1.0 / 60;          // [s]
    int iterations = 10;
    double load_fraction = 0.75;   // W/F
    double load_mass = 1.0;        // [kg]
    double g = 10.0;               // [m/s²]
    double periods = 3.0;          // simulated time in periods of √(k/m)

    double weight() const { return load_mass * g; }
    double capacity() const { return weight() / load_fraction; }
    double omega() const;                // √(k/m_load) [rad/s]
    double peak() const;                 // F²/(2k(F − W)) [m]
    double residual() const;             // peak − F/k [m]
    double duration() const;
};

Scene oscillator_scene(const OscillatorCase& c);

}  // namespace plascap::report
