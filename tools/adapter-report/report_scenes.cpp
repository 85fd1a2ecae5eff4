#include "report_scenes.hpp"

#include <algorithm>
#include <cmath>

namespace plascap::report {

double OscillatorCase::omega() const { return std::sqrt(stiffness / load_mass); }
double OscillatorCase::peak() const { return capacity() * capacity() / (2 * stiffness * (capacity() - weight())); }
double OscillatorCase::residual() const { return peak() - capacity() / stiffness; }  // values.md
double OscillatorCase::duration() const { return std::max(periods * 2 * M_PI / omega(), 30 * dt); }

Scene oscillator_scene(const OscillatorCase& c) {
    Scene s;
    s.dt = c.dt;
    s.duration = c.duration();
    s.iterations = c.iterations;
    s.gravity = {0, -c.g, 0};
    SceneBody anchor;
    anchor.name = "anchor";
    anchor.size = {0.2, 0.2, 0.2};
    anchor.mass = c.load_mass / c.mass_ratio;
    anchor.position = {0, -0.1, 0};
    SceneBody load = anchor;
    load.name = "load";
    load.mass = c.load_mass;
    load.position = {0, -1.0, 0};
    s.bodies = {anchor, load};

    SceneJoint hold;  // the world holds the anchor: every dof rigid
    hold.name = "hold";
    hold.b = 0;
    hold.anchor = {0, 0, 0};
    hold.axes = {Vec3{1, 0, 0}, Vec3{0, -1, 0}, Vec3{0, 0, -1}};
    hold.settings.modes.fill(DofMode::Rigid);
    SceneJoint spring = hold;  // anchor → load: axial dof plastic, y pointing from a to b
    spring.name = "spring";
    spring.a = 0;
    spring.b = 1;
    spring.anchor = {0, -0.2, 0};
    spring.settings.modes[index(Dof::N)] = DofMode::Plastic;
    spring.settings.laws[index(Dof::N)] = DofLaw{c.capacity(), c.capacity(), c.stiffness};
    s.joints = {hold, spring};
    return s;
}

}  // namespace plascap::report
