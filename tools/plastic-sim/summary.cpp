// The end-of-run summaries: JSON (--json) and a readable table.
#include <nlohmann/json.hpp>

#include <iomanip>
#include <ostream>
#include <sstream>

#include "simulation.hpp"

namespace plascap {
namespace {

nlohmann::json regimes_json(const SceneJoint& joint, const JointSummary& s) {
    nlohmann::json dofs = nlohmann::json::object();
    for (Dof dof : kAllDofs) {
        const DofMode mode = joint.settings.modes[index(dof)];
        if (mode == DofMode::Free) continue;
        nlohmann::json d = {{"mode", dof_mode_name(mode)}};
        if (s.regimes[index(dof)]) {
            d["regime"] = regime_name(*s.regimes[index(dof)]);
            if (joint.settings.laws[index(dof)].stiffness) d["omega_dt"] = s.omega_dt[index(dof)];
        }
        dofs[dof_name(dof)] = d;
    }
    return dofs;
}

std::string regimes_text(const SceneJoint& joint, const JointSummary& s) {
    std::ostringstream out;
    for (Dof dof : kAllDofs) {
        const DofMode mode = joint.settings.modes[index(dof)];
        if (mode == DofMode::Free) continue;
        out << ' ' << dof_name(dof) << ':';
        if (!s.regimes[index(dof)]) {
            out << dof_mode_name(mode);
            continue;
        }
        out << regime_name(*s.regimes[index(dof)]);
        if (joint.settings.laws[index(dof)].stiffness) out << " (ω·dt " << std::setprecision(3) << s.omega_dt[index(dof)] << ')';
    }
    return out.str();
}

void write_energy(std::ostream& out, const EnergyLedger& e) {
    out << "\nenergy [J]: kinetic " << std::setprecision(6) << e.kinetic << ", gravitational " << e.gravitational << ", elastic "
        << e.elastic << ", dissipated " << e.dissipated << ", external work " << e.external_work << ", initial " << e.initial
        << "; remainder (contacts, solver) " << e.remainder() << " = " << std::setprecision(3)
        << (e.handled > 0 ? 100.0 * e.remainder() / e.handled : 0.0) << " % of the " << std::setprecision(6) << e.handled
        << " J handled";
    out << ", of which contacts " << e.contacts << ", position corrections " << e.corrections
        << " and the joints' rows' work unbooked by their laws " << e.joints_unbooked << "; left (the integrator's error) "
        << e.remainder() - e.contacts - e.corrections - e.joints_unbooked;
    out << '\n';
}

void write_nodes(std::ostream& out, const Scene& scene, const SimulationResult& r) {
    if (scene.nodes.empty()) return;
    out << "\nnodes                 position [m]                              displacement [m]\n";
    for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
        out << "  " << std::left << std::setw(18) << scene.nodes[n].name << std::right;
        for (double v : r.nodes[n]) out << std::setw(13) << std::setprecision(6) << v;
        out << "  ";
        for (double v : difference(r.nodes[n], scene.nodes[n].position)) out << std::setw(13) << std::setprecision(6) << v;
        out << '\n';
    }
}

}  // namespace

nlohmann::json json_summary(const Scene& scene, const SimulationResult& r, const std::string& engine) {
    nlohmann::json j;
    j["time"] = r.time;
    j["steps"] = r.steps;
    j["engine"] = engine;
    j["wall_seconds"] = r.wall_seconds;
    j["warnings"] = r.warnings;
    j["bodies"] = nlohmann::json::object();
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        j["bodies"][scene.bodies[i].name] = {{"position", r.bodies[i].position}, {"velocity", r.bodies[i].velocity},
                                             {"angular_velocity", r.bodies[i].angular_velocity}};
    }
    j["joints"] = nlohmann::json::object();
    for (std::size_t k = 0; k < scene.joints.size(); ++k) {
        const JointSummary& s = r.joints[k];
        j["joints"][scene.joints[k].name] = {
            {"engaged", s.engaged},
            {"broken", s.broken_at.has_value()},
            {"broken_at", s.broken_at ? nlohmann::json(*s.broken_at) : nlohmann::json(nullptr)},
            {"plastic_displacement", s.plastic_displacement},
            {"plastic_rotation", s.plastic_rotation},
            {"dissipated", s.dissipated},
            {"unbooked", s.unbooked},
            {"dofs", regimes_json(scene.joints[k], s)}};
    }
    if (!scene.nodes.empty()) {
        j["nodes"] = nlohmann::json::object();
        for (std::size_t n = 0; n < scene.nodes.size(); ++n)
            j["nodes"][scene.nodes[n].name] = {{"position", r.nodes[n]}, {"displacement", difference(r.nodes[n], scene.nodes[n].position)}};
    }
    const EnergyLedger& e = r.energy;
    j["energy"] = {{"kinetic", e.kinetic},         {"gravitational", e.gravitational}, {"elastic", e.elastic},
                   {"dissipated", e.dissipated},   {"external_work", e.external_work}, {"initial", e.initial},
                   {"remainder", e.remainder()},   {"corrections", e.corrections}, {"contacts", e.contacts},
                   {"joints_unbooked", e.joints_unbooked}, {"handled", e.handled}};
    return j;
}

void write_json_summary(std::ostream& out, const Scene& scene, const SimulationResult& r, const std::string& engine) {
    out << json_summary(scene, r, engine).dump(2) << '\n';
}

void write_text_summary(std::ostream& out, const Scene& scene, const SimulationResult& r, const std::string& engine) {
    out << "engine: " << engine << "\n";
    out << "time: " << r.time << " s in " << r.steps << " steps of " << scene.dt << " s (" << std::fixed
        << std::setprecision(3) << r.wall_seconds << " s of wall time)\n"
        << std::defaultfloat;
    for (const std::string& w : r.warnings) out << "warning: " << w << '\n';
    out << "\nbodies                position [m]                              velocity [m/s]\n";
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        out << "  " << std::left << std::setw(18) << scene.bodies[i].name << std::right;
        for (double v : r.bodies[i].position) out << std::setw(13) << std::setprecision(6) << v;
        out << "  ";
        for (double v : r.bodies[i].velocity) out << std::setw(13) << std::setprecision(6) << v;
        out << '\n';
    }
    write_energy(out, r.energy);
    write_nodes(out, scene, r);
    if (scene.joints.empty()) return;
    out << "\njoints                state               plastic [m]  plastic [rad]  dissipated [J]  dofs\n";
    for (std::size_t k = 0; k < scene.joints.size(); ++k) {
        const JointSummary& s = r.joints[k];
        std::ostringstream state;
        if (!s.engaged) {
            state << "not engaged";
        } else if (s.broken_at) {
            state << "broken at " << std::setprecision(4) << *s.broken_at << " s";
        } else {
            state << "intact";
        }
        out << "  " << std::left << std::setw(18) << scene.joints[k].name << "  " << std::setw(18) << state.str()
            << std::right << std::setw(13) << std::setprecision(5) << s.plastic_displacement << std::setw(15)
            << s.plastic_rotation << std::setw(16) << s.dissipated << ' ' << regimes_text(scene.joints[k], s) << '\n';
    }
}

}  // namespace plascap
