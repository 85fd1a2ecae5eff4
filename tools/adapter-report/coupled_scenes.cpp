#include "coupled_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plascap/adapters/section_yield_condition.hpp"
#include "plascap/sections/shapes.hpp"
#include "body_energy.hpp"
#include "scene.hpp"

namespace plascap::coupled {

std::string scene_json(const Case& c, double mass, const std::string& extra_joint_keys, double duration, double dt) {
    char body[300];
    std::snprintf(body, sizeof body, R"({"name": "block", "box": [1, 1, 1], "mass": %.17g, "position": [%.17g, %.17g, %.17g]})",
                  mass, c.centre[0], c.centre[1], c.centre[2]);
    char material[120];
    std::snprintf(material, sizeof material, R"({"fy": %.17g, "E": 2e11, "nu": 0.3, "density": 7850})", c.fy);
    char timing[120];
    std::snprintf(timing, sizeof timing, R"({"dt": %.17g, "duration": %.17g)", dt, duration);
    return std::string(timing) +
           R"(, "iterations": 50, "gravity": [0, -10, 0], "bodies": [)" + body +
           R"(], "joints": [{"name": "j", "a": "world", "b": "block", "anchor": [0, 0, 0], "axis": )" + c.axis +
           R"(, "x_axis": )" + c.x_axis + R"(, "section": )" + c.section + R"(, "material": )" + material +
           R"(, "dofs": )" + c.dofs + extra_joint_keys + "}]}";
}

// The block's mass at which the static load reaches the exact onset, U = 1.
double onset_mass(const Case& c) {
    const ValidSection v = validate_section(c.cpp_section);
    const auto condition = section_yield_condition(section_yield(v));
    YieldHint hint;
    return 1.0 / condition->evaluate(c.load_per_kg, hint).utilisation;
}

namespace {

// A b × h rectangle centred on the joint point (b along the section's x, h along z).
std::string rectangle_json(double b, double h) {
    char text[200];
    std::snprintf(text, sizeof text, R"({"parts": [{"outer": [[%g, %g], [%g, %g], [%g, %g], [%g, %g]]}]})", -b / 2, -h / 2,
                  b / 2, -h / 2, b / 2, h / 2, -b / 2, h / 2);
    return text;
}

Section rectangle_with(double b, double h, double fy) {
    Section s = rectangle_section(b, h, fy);
    s.parts[0].material.E = 2e11;
    s.parts[0].material.nu = 0.3;
    return s;
}

}  // namespace

// Axial force and bending: the block hangs under the anchor, its centre 0.075 m aside, so gravity
// gives N = m·g (tension) and Mz = m·g·0.075 m; a 0.2 × 0.1 m rectangle with fy = 1e5 Pa has
// Np = 2000 N and Mzp = fy·h·b²/4 = 100 N·m: on the surface (n² + m = 1) at n = 0.5 for 100 kg.
Case axial_and_bending() {
    Case c;
    c.name = "axial_and_bending";
    c.axis = "[0, -1, 0]", c.x_axis = "[1, 0, 0]";  // y from the world to the block; z = x × y = −world z
    c.centre = {0.075, -0.6, 0};
    c.section = rectangle_json(0.2, 0.1);
    c.dofs = R"({"N": "plastic", "Mz": "plastic", "Qx": "rigid", "Qz": "rigid", "Mx": "rigid", "My": "rigid"})";
    c.fy = 1e5;
    c.load_per_kg = {};
    c.load_per_kg[index(Dof::N)] = kG;
    c.load_per_kg[index(Dof::Mz)] = kG * 0.075;  // r × F = (0.075, −0.6, 0) × (0, −m·g, 0) = −0.075·m·g world z
    c.cpp_section = rectangle_with(0.2, 0.1, 1e5);
    return c;
}

// Bending about the diagonal of a 0.1 m square: a horizontal cantilever (beam axis world x) with the
// joint's x axis turned 45° about it, so Mx = Mz = m·g·L/√2 (L = 1 m); exact M = a³·fy/(3√2) about
// the diagonal, i.e. each component a³·fy/6 (the box allows a³·fy/4 each). fy = 6e5 Pa: 100 N·m per
// component at the onset, m ≈ 14 kg; the shear m·g through the rigid rows adds η ≈ 0.005·u.
Case diagonal_bending() {
    Case c;
    c.name = "diagonal_bending";
    c.axis = "[1, 0, 0]", c.x_axis = "[0, 0.7071067811865476, 0.7071067811865476]";
    c.centre = {1.0, 0, 0};
    c.section = rectangle_json(0.1, 0.1);
    c.dofs = R"({"Mx": "plastic", "Mz": "plastic", "N": "rigid", "Qx": "rigid", "Qz": "rigid", "My": "rigid"})";
    c.fy = 6e5;
    // x = (0, 1, 1)/√2, y = (1, 0, 0), z = x × y = (0, 1, −1)/√2; the moment on b from gravity about
    // the anchor is (0, 0, −m·g·L), the force (0, −m·g, 0): Mx = −g/√2, Mz = +g/√2, Qx = Qz = −g/√2 per kg.
    const double r = kG / std::sqrt(2.0);
    c.load_per_kg = {};
    c.load_per_kg[index(Dof::Mx)] = -r, c.load_per_kg[index(Dof::Mz)] = r;
    c.load_per_kg[index(Dof::Qx)] = -r, c.load_per_kg[index(Dof::Qz)] = -r;
    c.cpp_section = rectangle_with(0.1, 0.1, 6e5);
    return c;
}

// Pure torsion: the beam axis is world x, the block's centre 0.5 m to its side (world z), so
// gravity twists the joint by m·g·0.5 about y (and shears it by m·g through a rigid row). The
// capacity is the sand heap's T_p of the 0.2 × 0.1 m rectangle, τy = fy/2: τy·b²(3h − b)/6.
Case pure_torsion() {
    Case c;
    c.name = "pure_torsion";
    c.axis = "[1, 0, 0]", c.x_axis = "[0, 0, 1]";  // z = x × y = world y
    c.centre = {0, 0, 0.5};
    c.section = rectangle_json(0.2, 0.1);
    c.dofs = R"({"My": "plastic", "N": "rigid", "Qx": "rigid", "Qz": "rigid", "Mx": "rigid", "Mz": "rigid"})";
    c.fy = 1e5;
    c.load_per_kg = {};
    // r × F = (0, 0, 0.5) × (0, −g, 0) = (0.5·g, 0, 0): +My; the force (0, −g, 0) along z = world y: Qz = −g.
    c.load_per_kg[index(Dof::My)] = 0.5 * kG;
    c.load_per_kg[index(Dof::Qz)] = -kG;
    c.cpp_section = rectangle_with(0.2, 0.1, 1e5);
    return c;
}


SceneRun run_scene(const std::string& engine_name, const std::string& json) {
    const Scene scene = parse_scene_json(json);
    const std::unique_ptr<SceneEngine> engine = make_engine(engine_name, scene);
    const double y0 = scene.bodies[0].position[1], m = scene.bodies[0].mass;
    SceneRun r;
    for (std::size_t i = 0; i < scene.steps(); ++i) {
        engine->step();
        const PlasticJointLaw* law = engine->joint_law(0);
        const BodyState s = engine->body(0);
        const double potential = m * kG * (s.position[1] - y0);
        const double ledger = kinetic_energy(scene.bodies[0], s) + potential + law->elastic_energy(engine->joint_positions(0)) +
                              law->dissipated();
        r.worst_ledger = std::max(r.worst_ledger, std::abs(ledger));
        r.handled = std::max(r.handled, std::abs(potential));
        const double plastic = law->plastic_displacement() + law->plastic_rotation();
        if (plastic > r.plastic && !law->broken()) {  // a step of flow: where on the condition did it happen?
            PerDof<double> loads = engine->joint_forces(0);
            for (double& l : loads) l = -l;
            YieldHint hint;
            const double u = law->settings().yield_condition ? law->settings().yield_condition->evaluate(loads, hint).utilisation : 0.0;
            r.flow_u_min = r.flow_steps == 0 ? u : std::min(r.flow_u_min, u);
            r.flow_u_max = std::max(r.flow_u_max, u);
            r.flow_u_mean += u;
            ++r.flow_steps;
        }
        r.plastic = plastic;
        r.broken = law->broken();
    }
    if (r.flow_steps > 0) r.flow_u_mean /= static_cast<double>(r.flow_steps);
    return r;
}


}  // namespace plascap::coupled
