#include "joint_json.hpp"

#include <cmath>
#include <optional>

#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"
#include "plascap/materials/material_json.hpp"
#include "plascap/adapters/section_joint_settings.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/section_json.hpp"
#include "plascap/sections/valid_section.hpp"
#include "scene_json_values.hpp"

namespace plascap {
namespace {

using namespace scene_json;

// Runs `read` and puts `where` in front of the message of any InputError it throws.
template <class Read>
auto located(const std::string& where, Read read) {
    try {
        return read();
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
    }
}

std::optional<std::size_t> body_ref(const Json& j, const std::string& where, const std::vector<SceneBody>& bodies) {
    const std::string name = text(j, where);
    if (name == "world") return std::nullopt;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i].name == name) return i;
    }
    throw InputError(where + ": no body named \"" + name + "\"");
}

// The joint frame: y along "axis"; x the part of "x_axis" across y (default: the world axis most
// across y); z = x × y, so (x, y, z) is right-handed.
std::array<Vec3, 3> joint_axes(const Json& j, const std::string& where) {
    const Vec3 y = unit_vec3(member(j, "axis", where), where + ".axis");
    Vec3 raw{};
    if (j.contains("x_axis")) {
        raw = vec3(j["x_axis"], where + ".x_axis");
    } else {
        const std::size_t least = std::abs(y[0]) <= std::abs(y[1]) && std::abs(y[0]) <= std::abs(y[2]) ? 0
                                  : std::abs(y[1]) <= std::abs(y[2])                                 ? 1
                                                                                                     : 2;
        raw[least] = 1.0;
    }
    const double along = raw[0] * y[0] + raw[1] * y[1] + raw[2] * y[2];
    Vec3 x = {raw[0] - along * y[0], raw[1] - along * y[1], raw[2] - along * y[2]};
    const double across = std::hypot(x[0], x[1], x[2]);
    if (!(across > 1e-6 * std::hypot(raw[0], raw[1], raw[2]))) {
        throw InputError(where + ".x_axis: is zero or parallel to axis");
    }
    for (double& c : x) c /= across;
    return {x, y, cross(x, y)};
}

std::optional<Material> joint_material(const Json& j, const std::string& where, const MaterialCatalogue& catalogue) {
    if (!j.contains("material")) return std::nullopt;
    const Json& m = j["material"];
    if (m.is_string()) return catalogue.get(m.get<std::string>(), where + ".material");
    if (m.is_object()) return parse_material_json(m.dump(), where + ".material");
    throw InputError(where + ".material: expected a catalogue name or an object");
}

Capacities given_capacities(const Json& j, const std::string& where) {
    require_object(j, where);
    reject_unknown_keys(j, where, {"N", "Qx", "Qz", "Mx", "My", "Mz", "N_neg", "Mx_neg", "Mz_neg"});
    Capacities c;
    auto read = [&](const char* key) -> std::optional<double> {
        if (!j.contains(key)) return std::nullopt;
        return positive_number(j[key], where + "." + key);
    };
    c.N = read("N"), c.Qx = read("Qx"), c.Qz = read("Qz"), c.Mx = read("Mx"), c.My = read("My"), c.Mz = read("Mz");
    c.N_neg = read("N_neg"), c.Mx_neg = read("Mx_neg"), c.Mz_neg = read("Mz_neg");
    if (!c.N_neg) c.N_neg = c.N;  // symmetric unless told
    if (!c.Mx_neg) c.Mx_neg = c.Mx;
    if (!c.Mz_neg) c.Mz_neg = c.Mz;
    return c;
}

bool has_capacity(const Capacities& c, Dof dof) {
    switch (dof) {
        case Dof::Qx: return c.Qx.has_value();
        case Dof::N: return c.N.has_value();
        case Dof::Qz: return c.Qz.has_value();
        case Dof::Mx: return c.Mx.has_value();
        case Dof::My: return c.My.has_value();
        case Dof::Mz: return c.Mz.has_value();
    }
    return false;
}

PerDof<std::optional<double>> given_stiffness(const Json& j, const std::string& where) {
    require_object(j, where);
    reject_unknown_keys(j, where, {"N", "Qx", "Qz", "Mx", "My", "Mz"});
    PerDof<std::optional<double>> k;
    for (const auto& item : j.items()) {
        k[index(dof_from_name(item.key(), where))] = positive_number(item.value(), where + "." + item.key());
    }
    return k;
}

// "yield_surface" (coupled | box) and "torsion" (fully-plastic | paper): checked for every joint,
// meaningful for section joints only.
void yield_choice(const Json& j, const std::string& where, bool from_section, SectionJointOptions& o) {
    o.coupled = from_section;
    if (j.contains("yield_surface")) {
        const std::string name = text(j["yield_surface"], where + ".yield_surface");
        if (name != "coupled" && name != "box")
            throw InputError(where + ".yield_surface: unknown \"" + name + "\" (available: coupled, box)");
        o.coupled = name == "coupled";
        if (o.coupled && !from_section)
            throw InputError(where + ".yield_surface: \"coupled\" needs the section (\"section\" or \"shape\"), not \"capacities\"");
    }
    if (j.contains("torsion")) {
        if (!from_section) throw InputError(where + ".torsion: chooses a section's torsion capacity; \"capacities\" give My directly");
        o.torsion = torsion_capacity_from_name(text(j["torsion"], where + ".torsion"), where + ".torsion");
    }
}

// "section" or "shape" (short for "section": {"shape": ...}, docs/shapes.md), with the joint's
// material where the section names none.
ValidSection joint_section(const Json& j, const std::string& where, const MaterialCatalogue& catalogue) {
    const std::string key = j.contains("shape") ? "shape" : "section";
    Json section = key == "shape" ? Json{{"shape", j["shape"]}} : j["section"];
    require_object(section, where + "." + key);
    if (!section.contains("material") && j.contains("material")) section["material"] = j["material"];
    return located(where + "." + key, [&] { return validate_section(parse_section_json(section.dump(), catalogue)); });
}

// Plastic where a capacity is known (every dof of a section: `capacities` nullptr), else rigid,
// unless "dofs" says otherwise.
PerDof<DofMode> dof_modes(const Json& j, const std::string& where, const Capacities* capacities) {
    PerDof<DofMode> modes{};
    for (Dof dof : kAllDofs)
        modes[index(dof)] = !capacities || has_capacity(*capacities, dof) ? DofMode::Plastic : DofMode::Rigid;
    if (!j.contains("dofs")) return modes;
    const Json& dofs = j["dofs"];
    require_object(dofs, where + ".dofs");
    for (const auto& item : dofs.items()) {
        const std::string at = where + ".dofs." + item.key();
        const Dof dof = dof_from_name(item.key(), where + ".dofs");
        modes[index(dof)] = dof_mode_from_name(text(item.value(), at), at);
        if (modes[index(dof)] == DofMode::Plastic && capacities && !has_capacity(*capacities, dof)) {
            throw InputError(at + ": a plastic dof needs its capacity");
        }
    }
    return modes;
}

// A "capacities" joint breaks at its material's max_plastic_rotation (no length: no displacement limit).
void breaking_limits(const std::optional<Material>& material, PlasticJointSettings& settings) {
    if (material && material->max_plastic_rotation) settings.max_plastic_rotation = *material->max_plastic_rotation;
}

}  // namespace

ValidSection read_joint_section(const Json& j, const std::string& where, const MaterialCatalogue& catalogue) {
    return joint_section(j, where, catalogue);
}

void read_yield_choice(const Json& j, const std::string& where, bool from_section, SectionJointOptions& options) {
    yield_choice(j, where, from_section, options);
}

SceneJoint parse_joint(const Json& j, const std::string& where_in, const std::vector<SceneBody>& bodies,
                       const MaterialCatalogue& catalogue) {
    require_object(j, where_in);
    reject_unknown_keys(j, where_in, {"name", "a", "b", "anchor", "axis", "x_axis", "capacities", "section", "shape", "material",
                                      "stiffness", "length", "dofs", "max_plastic_displacement",
                                      "max_plastic_rotation", "engage_at", "yield_surface", "torsion"});
    SceneJoint joint;
    joint.name = text(member(j, "name", where_in), where_in + ".name");
    const std::string where = where_in + " (\"" + joint.name + "\")";
    joint.a = body_ref(member(j, "a", where), where + ".a", bodies);
    const std::optional<std::size_t> b = body_ref(member(j, "b", where), where + ".b", bodies);
    if (!b) throw InputError(where + ".b: must be a body (put \"world\" in \"a\")");
    if (joint.a == b) throw InputError(where + ": a and b are the same body");
    joint.b = *b;
    if (bodies[joint.b].is_static && (!joint.a || bodies[*joint.a].is_static)) {
        throw InputError(where + ": joins two static things; one side must move");
    }
    joint.anchor = vec3(member(j, "anchor", where), where + ".anchor");
    joint.axes = joint_axes(j, where);
    if (j.contains("engage_at")) {
        joint.engage_at = finite_number(j["engage_at"], where + ".engage_at");
        if (joint.engage_at < 0.0) throw InputError(where + ".engage_at: must not be negative");
    }

    const std::optional<Material> material = joint_material(j, where, catalogue);
    if (int(j.contains("capacities")) + int(j.contains("section")) + int(j.contains("shape")) != 1) {
        throw InputError(where + ": give exactly one of \"capacities\", \"section\" and \"shape\"");
    }
    if (j.contains("stiffness") && j.contains("length")) {
        throw InputError(where + ": give at most one of \"stiffness\" and \"length\"");
    }
    const bool from_section = !j.contains("capacities");
    SectionJointOptions options;
    yield_choice(j, where, from_section, options);
    if (j.contains("length")) {
        if (!from_section) throw InputError(where + ".length: a stiffness from a length needs a \"section\" or \"shape\"");
        options.segment_length = positive_number(j["length"], where + ".length");
    }
    if (from_section) {
        const ValidSection section = joint_section(j, where, catalogue);
        options.modes = dof_modes(j, where, nullptr);
        joint.settings = located(where, [&] { return section_joint_settings(section, options); });
    } else {
        const Capacities capacities = given_capacities(j["capacities"], where + ".capacities");
        joint.settings.modes = dof_modes(j, where, &capacities);
        for (Dof dof : kAllDofs) {
            if (joint.settings.modes[index(dof)] != DofMode::Plastic) continue;
            joint.settings.laws[index(dof)] =
                located(where + ", dof " + dof_name(dof), [&] { return dof_law_from_section(dof, capacities); });
        }
        breaking_limits(material, joint.settings);
    }
    if (j.contains("stiffness")) {
        const PerDof<std::optional<double>> k = given_stiffness(j["stiffness"], where + ".stiffness");
        for (Dof dof : kAllDofs) joint.settings.laws[index(dof)].stiffness = k[index(dof)];
    }
    if (j.contains("max_plastic_displacement")) {
        joint.settings.max_plastic_displacement = positive_number(j["max_plastic_displacement"], where + ".max_plastic_displacement");
    }
    if (j.contains("max_plastic_rotation")) {
        joint.settings.max_plastic_rotation = positive_number(j["max_plastic_rotation"], where + ".max_plastic_rotation");
    }
    validate_joint_settings(joint.settings, where);
    return joint;
}

}  // namespace plascap
