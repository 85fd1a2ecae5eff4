#include "structure_json.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "joint_json.hpp"
#include "plascap/adapters/structure_model.hpp"
#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"
#include "scene_json_values.hpp"

namespace plascap {
namespace {

using namespace scene_json;

// Members of one "shape" or "section" and "material" share one section object, so that the
// builder computes its joint settings once (structure.hpp).
using SectionCache = std::map<std::string, std::shared_ptr<const ValidSection>>;

StructureMember parse_member(const Json& m, const std::string& where_in, const MaterialCatalogue& catalogue, SectionCache& sections) {
    require_object(m, where_in);
    reject_unknown_keys(m, where_in, {"name", "from", "to", "shape", "section", "material", "z_axis", "segments",
                                      "yield_surface", "torsion", "removed_at"});
    StructureMember member;
    member.name = text(scene_json::member(m, "name", where_in), where_in + ".name");
    member.where = where_in + " (\"" + member.name + "\")";
    const std::string& where = member.where;
    member.from = text(scene_json::member(m, "from", where), where + ".from");
    member.to = text(scene_json::member(m, "to", where), where + ".to");
    if (m.contains("z_axis")) member.z_axis = vec3(m["z_axis"], where + ".z_axis");
    if (m.contains("segments")) {  // anything but a whole number in range: 0, which the builder refuses with its message
        const Json& n = m["segments"];
        member.segments = n.is_number_integer() ? static_cast<int>(std::clamp<long long>(n.get<long long>(), 0, kMaxMemberSegments + 1)) : 0;
    }
    if (m.contains("removed_at")) member.removed_at = finite_number(m["removed_at"], where + ".removed_at");
    if (!m.contains("shape") && !m.contains("section")) throw InputError(where + ": a member needs a \"shape\" or a \"section\"");
    if (m.contains("shape") && m.contains("section")) throw InputError(where + ": give one of \"shape\" and \"section\"");
    const std::string key = (m.contains("shape") ? m["shape"] : m["section"]).dump() + (m.contains("material") ? m["material"].dump() : "");
    std::shared_ptr<const ValidSection>& section = sections[key];
    if (!section) section = std::make_shared<const ValidSection>(read_joint_section(m, where, catalogue));
    member.section = section;
    read_yield_choice(m, where, true, member.options);
    return member;
}

// "xz" → the restrained world directions.
std::array<bool, 3> directions(const Json& j, const std::string& where) {
    std::array<bool, 3> r{};
    for (char c : text(j, where)) {
        if (c < 'x' || c > 'z') throw InputError(where + ": \"" + text(j, where) + "\" is not made of x, y and z");
        r[c - 'x'] = true;
    }
    return r;
}

StructureSupport parse_support(const Json& spec, const std::string& where) {
    if (spec.is_string()) {
        const std::string kind = spec.get<std::string>();
        if (kind == "fixed") return StructureSupport::fixed();
        if (kind == "pinned") return StructureSupport::pinned();
        throw InputError(where + ": unknown support \"" + kind + "\" (fixed, pinned, or {\"translations\", \"rotations\"})");
    }
    if (!spec.is_object())
        throw InputError(where + ": expected \"fixed\", \"pinned\" or {\"translations\": \"xyz\", \"rotations\": \"xyz\"}");
    reject_unknown_keys(spec, where, {"translations", "rotations"});
    StructureSupport s;
    s.translations = spec.contains("translations") ? directions(spec["translations"], where + ".translations") : std::array<bool, 3>{};
    s.rotations = spec.contains("rotations") ? directions(spec["rotations"], where + ".rotations") : std::array<bool, 3>{};
    return s;
}

SceneLoad parse_load(const Json& l, const std::string& where, const std::map<std::string, BodyPoint>& points) {
    require_object(l, where);
    reject_unknown_keys(l, where, {"node", "force", "moment", "history"});
    SceneLoad load;
    load.node = text(scene_json::member(l, "node", where), where + ".node");
    const auto it = points.find(load.node);
    if (it == points.end()) throw InputError(where + ".node: no node named \"" + load.node + "\" that a member meets");
    load.at = it->second;
    if (l.contains("force")) load.force = vec3(l["force"], where + ".force");
    if (l.contains("moment")) load.moment = vec3(l["moment"], where + ".moment");
    if (l.contains("history")) {
        const Json& h = l["history"];
        if (!h.is_array() || h.empty()) throw InputError(where + ".history: expected [[t, factor], ...]");
        for (std::size_t i = 0; i < h.size(); ++i) {
            const std::string at = where + ".history[" + std::to_string(i) + "]";
            if (!h[i].is_array() || h[i].size() != 2) throw InputError(at + ": expected [t, factor]");
            const double t = finite_number(h[i][0], at + "[0]"), f = finite_number(h[i][1], at + "[1]");
            if (!load.history.empty() && !(t > load.history.back().first))
                throw InputError(at + ": t = " + std::to_string(t) + " s is not after the previous entry's");
            load.history.push_back({t, f});
        }
    }
    return load;
}

Structure parse_structure(const Json& j, const Scene& scene, const MaterialCatalogue& catalogue) {
    Structure s;
    s.gravity = scene.gravity;
    const Json& node_list = scene_json::member(j, "nodes", "scene (with \"members\")");
    require_object(node_list, "nodes");
    for (const auto& item : node_list.items()) s.nodes[item.key()] = vec3(item.value(), "nodes." + item.key());
    const Json& members = j["members"];
    if (!members.is_array() || members.empty()) throw InputError("members: expected a non-empty array");
    SectionCache sections;
    for (std::size_t i = 0; i < members.size(); ++i)
        s.members.push_back(parse_member(members[i], "members[" + std::to_string(i) + "]", catalogue, sections));
    if (j.contains("supports")) {
        const Json& supports = j["supports"];
        require_object(supports, "supports");
        for (const auto& item : supports.items()) s.supports[item.key()] = parse_support(item.value(), "supports." + item.key());
    }
    return s;
}

// The model's segments, joints, nodes and outlines after the scene's own bodies.
void add_model(const Structure& s, StructureModel model, Scene& scene) {
    const std::size_t first_body = scene.bodies.size(), first_outline = scene.outlines.size();
    std::set<std::string> names;
    for (const SceneBody& b : scene.bodies) names.insert(b.name);
    for (const StructureSegment& segment : model.segments) {
        if (!names.insert(segment.name).second)
            throw InputError(s.members[segment.member].where + ": a second member or body named \"" + s.members[segment.member].name + "\"");
        SceneBody body;
        body.name = segment.name;
        body.size = segment.size;
        body.mass = segment.mass;
        body.position = segment.position;
        body.orientation = segment.orientation;
        body.inertia = segment.inertia;
        body.structure = true;
        body.outline = first_outline + segment.outline;
        scene.bodies.push_back(std::move(body));
    }
    for (StructureJoint& joint : model.joints) {
        if (joint.a) *joint.a += first_body;
        joint.b += first_body;
        scene.joints.push_back(SceneJoint{std::move(joint)});
    }
    for (StructureNode& node : model.nodes) {
        node.at.body += first_body;
        scene.nodes.push_back(std::move(node));
    }
    for (SectionOutline& outline : model.outlines) scene.outlines.push_back(std::move(outline));
}

}  // namespace

void check_structure_keys(const Json& j) {
    if (j.contains("members")) return;
    for (const char* key : {"nodes", "supports", "loads"})
        if (j.contains(key)) throw InputError(std::string(key) + ": needs \"members\" (docs/structures.md)");
}

double SceneLoad::factor(double time) const {
    if (history.empty()) return 1.0;
    if (time <= history.front().first) return history.front().second;
    for (std::size_t i = 1; i < history.size(); ++i) {
        const auto& [t1, f1] = history[i];
        if (time <= t1) {
            const auto& [t0, f0] = history[i - 1];
            return f0 + (f1 - f0) * (time - t0) / (t1 - t0);  // piecewise linear
        }
    }
    return history.back().second;
}

void add_structure(const Json& j, Scene& scene, const MaterialCatalogue& catalogue) {
    check_structure_keys(j);
    if (!j.contains("members")) return;
    const Structure structure = parse_structure(j, scene, catalogue);
    add_model(structure, build_structure(structure), scene);
    if (j.contains("loads")) {
        std::map<std::string, BodyPoint> points;
        for (const SceneNode& node : scene.nodes) points[node.name] = node.at;
        const Json& loads = j["loads"];
        if (!loads.is_array()) throw InputError("loads: expected an array");
        for (std::size_t i = 0; i < loads.size(); ++i) scene.loads.push_back(parse_load(loads[i], "loads[" + std::to_string(i) + "]", points));
    }
}

}  // namespace plascap
