#include "joint_json.hpp"

#include <cmath>
#include <optional>

#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"
#include "plascap/materials/material_json.hpp"
#include "plascap/adapters/section_yield_condition.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/joint_stiffness.hpp"
#include "plascap/sections/section_json.hpp"
#include "plascap/sections/torsion_constant.hpp"
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

// EA/L, 12EI/L³, EI/L, GJ/L of the section's beam segment (joint_stiffness.hpp).
PerDof<std::optional<double>> beam_stiffness(const ValidSection& section, double length, const std::string& where) {
    const ElasticProperties elastic = elastic_properties(section);
    if (!elastic.stiffness) throw InputError(where + ": the stiffness needs E for every material of the section");
    const TorsionConstant torsion = saint_venant_torsion(section);
    const JointStiffness s = joint_stiffness(*elastic.stiffness, torsion.GJ, length);
    return {s.shear_x, s.axial, s.shear_z, s.bending_x, s.torsion, s.bending_z};
}

struct Strength {
    Capacities capacities;
    PerDof<std::optional<double>> stiffness;
    std::optional<double> length;
    std::shared_ptr<const YieldCondition> yield_condition;  // "yield_surface": "coupled"
};

// "yield_surface" (coupled | box) and "torsion" (fully-plastic | paper) of a section joint.
struct YieldChoice {
    bool coupled = true;
    TorsionCapacity torsion = TorsionCapacity::FullyPlastic;
};

YieldChoice yield_choice(const Json& j, const std::string& where, bool from_section) {
    YieldChoice c;
    if (j.contains("yield_surface")) {
        const std::string name = text(j["yield_surface"], where + ".yield_surface");
        if (name != "coupled" && name != "box")
            throw InputError(where + ".yield_surface: unknown \"" + name + "\" (available: coupled, box)");
        c.coupled = name == "coupled";
        if (c.coupled && !from_section)
            throw InputError(where + ".yield_surface: \"coupled\" needs the section (\"section\" or \"shape\"), not \"capacities\"");
    }
    if (j.contains("torsion")) {
        if (!from_section) throw InputError(where + ".torsion: chooses a section's torsion capacity; \"capacities\" give My directly");
        c.torsion = torsion_capacity_from_name(text(j["torsion"], where + ".torsion"), where + ".torsion");
    }
    if (!from_section) c.coupled = false;
    return c;
}

// The section's coupled condition, and the box capacities that go with the choice: My the
// torsion capacity chosen; with the coupled surface, N, Mx, Mz where it meets each axis.
void apply_yield_choice(const ValidSection& valid, const YieldChoice& choice, bool needs_torsion, Strength& s) {
    if (choice.torsion == TorsionCapacity::FullyPlastic && (needs_torsion || choice.coupled))
        s.capacities.My = plastic_torsion(valid).T;
    if (!choice.coupled) return;
    s.yield_condition = section_yield_condition(SectionYield(YieldSurface(valid), {*s.capacities.Qx, *s.capacities.Qz, *s.capacities.My}));
    const PerDof<double> up = s.yield_condition->axis_capacity(true), down = s.yield_condition->axis_capacity(false);
    s.capacities.N = up[index(Dof::N)], s.capacities.N_neg = down[index(Dof::N)];
    s.capacities.Mx = up[index(Dof::Mx)], s.capacities.Mx_neg = down[index(Dof::Mx)];
    s.capacities.Mz = up[index(Dof::Mz)], s.capacities.Mz_neg = down[index(Dof::Mz)];
}

bool my_is_plastic(const Json& j) {
    if (!j.contains("dofs") || !j["dofs"].is_object() || !j["dofs"].contains("My")) return true;  // default: plastic
    return j["dofs"]["My"].is_string() && j["dofs"]["My"].get<std::string>() == "plastic";
}

Strength joint_strength(const Json& j, const std::string& where, const MaterialCatalogue& catalogue) {
    if (int(j.contains("capacities")) + int(j.contains("section")) + int(j.contains("shape")) != 1) {
        throw InputError(where + ": give exactly one of \"capacities\", \"section\" and \"shape\"");
    }
    if (j.contains("stiffness") && j.contains("length")) {
        throw InputError(where + ": give at most one of \"stiffness\" and \"length\"");
    }
    Strength s;
    if (j.contains("length")) s.length = positive_number(j["length"], where + ".length");
    if (j.contains("capacities")) {
        s.capacities = given_capacities(j["capacities"], where + ".capacities");
        yield_choice(j, where, false);
        if (s.length) throw InputError(where + ".length: a stiffness from a length needs a \"section\" or \"shape\"");
    } else {
        // "shape": "HEB 200" is short for "section": {"shape": "HEB 200"} (docs/shapes.md).
        const std::string key = j.contains("shape") ? "shape" : "section";
        Json section = key == "shape" ? Json{{"shape", j["shape"]}} : j["section"];
        require_object(section, where + "." + key);
        if (!section.contains("material") && j.contains("material")) section["material"] = j["material"];
        const ValidSection valid = located(where + "." + key, [&] {
            return validate_section(parse_section_json(section.dump(), catalogue));
        });
        s.capacities = compute_capacities(valid);
        apply_yield_choice(valid, yield_choice(j, where, true), my_is_plastic(j), s);
        if (s.length) s.stiffness = located(where + ".length", [&] { return beam_stiffness(valid, *s.length, where); });
    }
    if (j.contains("stiffness")) s.stiffness = given_stiffness(j["stiffness"], where + ".stiffness");
    return s;
}

PerDof<DofMode> dof_modes(const Json& j, const std::string& where, const Capacities& capacities) {
    PerDof<DofMode> modes{};
    for (Dof dof : kAllDofs) modes[index(dof)] = has_capacity(capacities, dof) ? DofMode::Plastic : DofMode::Rigid;
    if (!j.contains("dofs")) return modes;
    const Json& dofs = j["dofs"];
    require_object(dofs, where + ".dofs");
    for (const auto& item : dofs.items()) {
        const std::string at = where + ".dofs." + item.key();
        const Dof dof = dof_from_name(item.key(), where + ".dofs");
        modes[index(dof)] = dof_mode_from_name(text(item.value(), at), at);
        if (modes[index(dof)] == DofMode::Plastic && !has_capacity(capacities, dof)) {
            throw InputError(at + ": a plastic dof needs its capacity");
        }
    }
    return modes;
}

void breaking_limits(const Json& j, const std::string& where, const std::optional<Material>& material,
                     const std::optional<double>& length, PlasticJointSettings& settings) {
    if (material && material->ultimate_strain && length) {
        settings.max_plastic_displacement = *material->ultimate_strain * *length;  // ε_u·L
    }
    if (material && material->max_plastic_rotation) settings.max_plastic_rotation = *material->max_plastic_rotation;
    if (j.contains("max_plastic_displacement")) {
        settings.max_plastic_displacement = positive_number(j["max_plastic_displacement"], where + ".max_plastic_displacement");
    }
    if (j.contains("max_plastic_rotation")) {
        settings.max_plastic_rotation = positive_number(j["max_plastic_rotation"], where + ".max_plastic_rotation");
    }
}

}  // namespace

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
    const Strength strength = joint_strength(j, where, catalogue);
    joint.settings.modes = dof_modes(j, where, strength.capacities);
    for (Dof dof : kAllDofs) {
        if (joint.settings.modes[index(dof)] != DofMode::Plastic) continue;
        DofLaw law = located(where + ", dof " + dof_name(dof),
                             [&] { return dof_law_from_section(dof, strength.capacities); });
        law.stiffness = strength.stiffness[index(dof)];
        joint.settings.laws[index(dof)] = law;
    }
    joint.settings.yield_condition = strength.yield_condition;
    breaking_limits(j, where, material, strength.length, joint.settings);
    validate_joint_settings(joint.settings, where);
    return joint;
}

}  // namespace plascap
