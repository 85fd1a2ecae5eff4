#include "trace_csv.hpp"

#include "body_energy.hpp"

#include <ostream>

namespace plascap {

void write_trace_header(std::ostream& out, const Scene& scene) {
    out << "time";
    for (const SceneBody& b : scene.bodies) {
        for (const char* c : {"x", "y", "z", "vx", "vy", "vz", "qw", "qx", "qy", "qz"}) out << ',' << b.name << '.' << c;
    }
    for (const SceneJoint& j : scene.joints) {
        for (Dof dof : kAllDofs) {
            if (j.settings.modes[index(dof)] != DofMode::Plastic) continue;
            out << ',' << j.name << '.' << dof_name(dof) << ".force," << j.name << '.' << dof_name(dof) << ".offset";
        }
        out << ',' << j.name << ".plastic_displacement," << j.name << ".plastic_rotation," << j.name << ".dissipated,"
            << j.name << ".broken";
    }
    for (const SceneNode& n : scene.nodes) {
        for (const char* c : {"dx", "dy", "dz"}) out << ",node." << n.name << '.' << c;
    }
    out << ",energy.kinetic,energy.gravitational,energy.elastic,energy.dissipated,energy.external_work,energy.remainder,energy.corrections,energy.contacts,energy.joints_unbooked";
    out << '\n';
}

void write_trace_row(std::ostream& out, const Scene& scene, const SceneEngine& engine, const EnergyLedger& e) {
    out << engine.time();
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyState s = engine.body(i);
        for (double v : s.position) out << ',' << v;
        for (double v : s.velocity) out << ',' << v;
        for (double v : s.orientation) out << ',' << v;  // unit quaternion w, x, y, z (for replays)
    }
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        const PlasticJointLaw* law = engine.joint_law(j);
        const PerDof<double> forces = engine.joint_forces(j);
        for (Dof dof : kAllDofs) {
            if (scene.joints[j].settings.modes[index(dof)] != DofMode::Plastic) continue;
            const bool live = law && !law->broken();
            out << ',' << (live ? forces[index(dof)] : 0.0) << ',' << (law ? law->law(dof)->plastic_offset() : 0.0);
        }
        out << ',' << (law ? law->plastic_displacement() : 0.0) << ',' << (law ? law->plastic_rotation() : 0.0) << ','
            << (law ? law->dissipated() : 0.0) << ',' << (law && law->broken() ? 1 : 0);
    }
    for (const SceneNode& n : scene.nodes) {
        const Vec3 p = world_point(engine.body(n.at.body), n.at.local);
        for (int i = 0; i < 3; ++i) out << ',' << p[i] - n.position[i];
    }
    out << ',' << e.kinetic << ',' << e.gravitational << ',' << e.elastic << ',' << e.dissipated << ',' << e.external_work << ','
        << e.remainder() << ',' << e.corrections << ',' << e.contacts << ',' << e.joints_unbooked;
    out << '\n';
}

}  // namespace plascap
