#include "structure_json.hpp"

#include <algorithm>
#include <boost/geometry/algorithms/simplify.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/ring.hpp>
#include <boost/geometry/strategies/strategies.hpp>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "joint_json.hpp"
#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "scene_json_values.hpp"

namespace plascap {
namespace {

using namespace scene_json;

Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 times(const Vec3& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }

// A member's axes: y along it from `from` to `to`, z the section's depth ("z_axis" across y), x = y × z.
struct Frame {
    Vec3 x, y, z;
    Frame reversed() const { return {x, times(y, -1.0), times(z, -1.0)}; }  // y the other way, still right-handed
};

// The rotation whose columns are the frame's axes, as a unit quaternion (w, x, y, z) (Shepperd,
// J. Guidance and Control 1, 1978: from the largest of the four squared components).
Quaternion quaternion_of(const Frame& f) {
    const double m00 = f.x[0], m11 = f.y[1], m22 = f.z[2];
    const double m21 = f.y[2], m12 = f.z[1], m02 = f.z[0], m20 = f.x[2], m10 = f.x[1], m01 = f.y[0];
    const double trace = m00 + m11 + m22;
    Quaternion q;
    if (trace > 0) {
        const double s = 2.0 * std::sqrt(1.0 + trace);
        q = {0.25 * s, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s};
    } else if (m00 > m11 && m00 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m00 - m11 - m22);
        q = {(m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s};
    } else if (m11 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m11 - m00 - m22);
        q = {(m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + m22 - m00 - m11);
        q = {(m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s};
    }
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= n;
    return q;
}

struct Member {
    std::string name;
    std::string from, to;
    Vec3 start{}, end{};
    Frame frame;
    int segments = 1;
    double segment_length = 0.0;
    std::optional<double> removed_at;  // [s]: its joints to the rest of the structure break then
    std::size_t first_body = 0;
    PlasticJointSettings joint;  // between consecutive segments: a beam segment of segment_length
    std::string where;
    std::size_t end_body(bool at_start) const { return first_body + (at_start ? 0 : segments - 1); }
    bool owns(std::size_t body) const { return body >= first_body && body < first_body + static_cast<std::size_t>(segments); }
    Frame away_from(bool at_start) const { return at_start ? frame : frame.reversed(); }
};

// The same joint standing for a beam segment of another length: EA/L, EI/L, GJ/L scale with 1/L,
// 12EI/L³ with 1/L³ (joint_stiffness.hpp), the breaking displacement ε_u·L with L.
PlasticJointSettings at_length(PlasticJointSettings s, double from, double to) {
    for (Dof dof : kAllDofs) {
        std::optional<double>& k = s.laws[index(dof)].stiffness;
        if (!k) continue;
        const bool shear = dof == Dof::Qx || dof == Dof::Qz;
        *k *= shear ? std::pow(from / to, 3) : from / to;
    }
    if (std::isfinite(s.max_plastic_displacement)) s.max_plastic_displacement *= to / from;
    return s;
}

Frame member_frame(const Json& m, const std::string& where, const Vec3& along, const Vec3& gravity) {
    Vec3 z_raw;
    if (m.contains("z_axis")) {
        z_raw = vec3(m["z_axis"], where + ".z_axis");
    } else {  // default: up (against gravity), or world x for a member along it
        z_raw = norm(gravity) > 0 ? times(gravity, -1.0) : Vec3{0, 1, 0};
        if (norm(cross(normalised(z_raw), along)) < 1e-6) z_raw = {1, 0, 0};
    }
    const Vec3 across = difference(z_raw, times(along, dot(z_raw, along)));
    if (!(norm(across) > 1e-6 * norm(z_raw))) throw InputError(where + ".z_axis: is zero or along the member");
    Frame f;
    f.y = along;
    f.z = normalised(across);
    f.x = cross(f.y, f.z);
    return f;
}

// Mass per length Σ ρ·A [kg/m]; every material needs a density.
double mass_per_length(const ValidSection& section, const std::string& where) {
    double mu = 0.0;
    for (std::size_t p = 0; p < section.parts().size(); ++p) {
        const Part& part = section.parts()[p];
        if (!part.material.density) throw InputError(where + ": the material \"" + part.material.name + "\" needs a density (the member's mass)");
        mu += *part.material.density * section.part_moments()[p].area;
        for (const Bar& bar : part.bars) {
            if (!bar.material.density) throw InputError(where + ": the bars' material needs a density");
            mu += (*bar.material.density - *part.material.density) * bar.area;
        }
    }
    return mu;
}

// The section's extent across x and z (for the segment's collision box) [m].
std::pair<double, double> section_extent(const ValidSection& section) {
    double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
    for (const Part& part : section.parts())
        for (const Point& p : part.outer) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
    return {x1 - x0, z1 - z0};
}

// The section as drawn on the member's line, which passes through its joint point (the reference
// point, else the centroid), its rings simplified (Douglas–Peucker, Boost.Geometry) to 1 % of the
// section's size: a rolled shape's root arcs come as hundreds of chords, which a replay of a
// thousand segments cannot draw. The same section drawn twice is kept once.
std::size_t section_outline(const ValidSection& section, const ElasticProperties& elastic, Scene& scene) {
    namespace bg = boost::geometry;
    using Xz = bg::model::d2::point_xy<double>;
    using DrawnRing = bg::model::ring<Xz, false, false>;  // counter-clockwise, open, as ValidSection keeps them
    const Point line = section.reference() ? *section.reference() : elastic.centroid;
    const auto [width, depth] = section_extent(section);
    const double tolerance = 0.01 * std::max(width, depth);
    const auto drawn = [&](const Ring& ring) {
        DrawnRing full, simple;
        for (const Point& local : ring) {
            const Point p = section.to_section(local);
            full.push_back(Xz(p.x - line.x, p.z - line.z));
        }
        bg::simplify(full, simple, tolerance);
        if (simple.size() < 3) simple = full;
        Outline o;
        for (const Xz& p : simple) o.push_back({p.x(), p.y()});
        return o;
    };
    SectionOutline outline;
    for (const Part& part : section.parts()) {
        OutlinePart drawn_part{drawn(part.outer), {}};
        for (const Ring& hole : part.holes) drawn_part.holes.push_back(drawn(hole));
        outline.push_back(std::move(drawn_part));
    }
    const auto same = std::find(scene.outlines.begin(), scene.outlines.end(), outline);
    if (same != scene.outlines.end()) return static_cast<std::size_t>(same - scene.outlines.begin());
    scene.outlines.push_back(std::move(outline));
    return scene.outlines.size() - 1;
}

const Vec3& node_at(const std::map<std::string, Vec3>& nodes, const Json& name, const std::string& where) {
    const std::string n = text(name, where);
    const auto it = nodes.find(n);
    if (it == nodes.end()) throw InputError(where + ": no node named \"" + n + "\"");
    return it->second;
}

// Members of one section share its joint settings, computed once (T_p and J take a mesh each) for a
// 1 m segment and scaled to each member's segment length.
using SettingsCache = std::map<std::string, PlasticJointSettings>;

Member parse_member(const Json& m, const std::string& where_in, const std::map<std::string, Vec3>& nodes, Scene& scene,
                    const MaterialCatalogue& catalogue, SettingsCache& cache) {
    require_object(m, where_in);
    reject_unknown_keys(m, where_in, {"name", "from", "to", "shape", "section", "material", "z_axis", "segments",
                                      "yield_surface", "torsion", "removed_at"});
    Member member;
    member.name = text(scene_json::member(m, "name", where_in), where_in + ".name");
    member.where = where_in + " (\"" + member.name + "\")";
    const std::string& where = member.where;
    member.from = text(scene_json::member(m, "from", where), where + ".from");
    member.to = text(scene_json::member(m, "to", where), where + ".to");
    member.start = node_at(nodes, m["from"], where + ".from");
    member.end = node_at(nodes, m["to"], where + ".to");
    const Vec3 span = difference(member.end, member.start);
    const double length = norm(span);
    if (!(length > 1e-6)) throw InputError(where + ": has zero length (\"" + member.from + "\" and \"" + member.to + "\" coincide)");
    member.frame = member_frame(m, where, times(span, 1.0 / length), scene.gravity);
    if (m.contains("segments")) {
        const Json& n = m["segments"];
        if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 1000)
            throw InputError(where + ".segments: expected a whole number from 1 to 1000");
        member.segments = static_cast<int>(n.get<long long>());
    } else {
        member.segments = 4;
    }
    member.segment_length = length / member.segments;
    if (m.contains("removed_at")) {
        member.removed_at = finite_number(m["removed_at"], where + ".removed_at");
        if (*member.removed_at < 0.0) throw InputError(where + ".removed_at: must not be negative");
    }
    if (!m.contains("shape") && !m.contains("section")) throw InputError(where + ": a member needs a \"shape\" or a \"section\"");
    if (m.contains("shape") && m.contains("section")) throw InputError(where + ": give one of \"shape\" and \"section\"");
    const ValidSection section = read_joint_section(m, where, catalogue);
    const double mu = mass_per_length(section, where);
    const ElasticProperties elastic = elastic_properties(section);

    SectionJointOptions options;
    read_yield_choice(m, where, true, options);
    // Plastic hinges: the rotations yield, the translations are rigid — their forces still count on the
    // coupled surface and lower the moment capacity. With plastic translations too, the radial row
    // bounds pin the shear and axial rows at the load of the moment the hinge forms, and the next
    // step's redistribution slides them: a portal then collapsed 8 % early (docs/structures.md).
    for (Dof dof : kAllDofs)
        if (!is_rotation(dof)) options.modes[index(dof)] = DofMode::Rigid;
    const std::string key = (m.contains("shape") ? m["shape"] : m["section"]).dump() + (m.contains("material") ? m["material"].dump() : "") +
                            (options.coupled ? "coupled" : "box") + torsion_capacity_name(options.torsion);
    auto cached = cache.find(key);
    if (cached == cache.end()) {
        if (elastic.stiffness) options.segment_length = 1.0;  // without E: rigid-plastic
        try {
            cached = cache.emplace(key, section_joint_settings(section, options)).first;
        } catch (const InputError& e) {
            throw InputError(where + ": " + e.what());
        }
    }
    member.joint = at_length(cached->second, 1.0, member.segment_length);

    // The segments: boxes for contact, with the real member's mass and inertia about their axes:
    // ρ·ℓ·Ixx + m·ℓ²/12 about x, ρ·ℓ·(Ixx + Izz) about the member, ρ·ℓ·Izz + m·ℓ²/12 about z.
    const auto [width, depth] = section_extent(section);
    const double l = member.segment_length, mass = mu * l, rho = mu / elastic.area;
    member.first_body = scene.bodies.size();
    const std::size_t outline = section_outline(section, elastic, scene);
    for (int k = 0; k < member.segments; ++k) {
        SceneBody body;
        body.name = member.name + "#" + std::to_string(k + 1);
        body.size = {width, l, depth};
        body.mass = mass;
        body.position = plus(member.start, times(member.frame.y, l * (k + 0.5)));
        body.orientation = quaternion_of(member.frame);
        body.inertia = Vec3{rho * l * elastic.Ixx + mass * l * l / 12, rho * l * (elastic.Ixx + elastic.Izz),
                            rho * l * elastic.Izz + mass * l * l / 12};
        body.structure = true;
        body.outline = outline;
        scene.bodies.push_back(body);
    }
    for (int k = 0; k + 1 < member.segments; ++k) {
        SceneJoint joint;
        joint.name = member.name + "#" + std::to_string(k + 1) + "-" + std::to_string(k + 2);
        joint.a = member.first_body + k;
        joint.b = member.first_body + k + 1;
        joint.anchor = plus(member.start, times(member.frame.y, l * (k + 1)));
        joint.axes = {member.frame.x, member.frame.y, member.frame.z};
        joint.settings = member.joint;
        scene.joints.push_back(joint);
    }
    return member;
}

struct MemberEnd {
    std::size_t member;
    bool at_start;
};

BodyPoint point_of(const Scene& scene, const Member& m, bool at_start, const Vec3& world) {
    BodyPoint p;
    p.body = m.end_body(at_start);
    const Vec3 d = difference(world, scene.bodies[p.body].position);
    p.local = {dot(d, m.frame.x), dot(d, m.frame.y), dot(d, m.frame.z)};
    return p;
}

SceneJoint joint_at(const std::string& name, std::optional<std::size_t> a, std::size_t b, const Vec3& anchor, const Frame& f,
                    const PlasticJointSettings& settings) {
    SceneJoint j;
    j.name = name;
    j.a = a;
    j.b = b;
    j.anchor = anchor;
    j.axes = {f.x, f.y, f.z};
    j.settings = settings;
    return j;
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

SceneJoint support_joint(const std::string& node, const Json& spec, const std::string& where, const Member& m, bool at_start,
                         const Vec3& at) {
    std::array<bool, 3> translations{true, true, true}, rotations{true, true, true};
    if (spec.is_string()) {
        const std::string kind = spec.get<std::string>();
        if (kind == "pinned") rotations = {false, false, false};
        else if (kind != "fixed") throw InputError(where + ": unknown support \"" + kind + "\" (fixed, pinned, or {\"translations\", \"rotations\"})");
    } else if (spec.is_object()) {
        reject_unknown_keys(spec, where, {"translations", "rotations"});
        translations = spec.contains("translations") ? directions(spec["translations"], where + ".translations") : std::array<bool, 3>{};
        rotations = spec.contains("rotations") ? directions(spec["rotations"], where + ".rotations") : std::array<bool, 3>{};
    } else {
        throw InputError(where + ": expected \"fixed\", \"pinned\" or {\"translations\": \"xyz\", \"rotations\": \"xyz\"}");
    }
    const auto all = [](const std::array<bool, 3>& d) { return d[0] && d[1] && d[2]; };
    const auto none = [](const std::array<bool, 3>& d) { return !d[0] && !d[1] && !d[2]; };
    if (none(translations) && none(rotations)) throw InputError(where + ": restrains nothing");
    const std::size_t b = m.end_body(at_start);
    if (all(translations) && all(rotations)) {
        // Fixed: in the member's frame, so that the support can form a plastic hinge with the
        // section's capacities, as the member's own joints do.
        const PlasticJointSettings s = at_length(m.joint, m.segment_length, m.segment_length / 2);
        return joint_at("support " + node, std::nullopt, b, at, m.away_from(at_start), s);
    }
    // Partly restrained: rigid rows along the world directions named, free elsewhere (no hinge).
    PlasticJointSettings s;
    s.modes[index(Dof::Qx)] = translations[0] ? DofMode::Rigid : DofMode::Free;
    s.modes[index(Dof::N)] = translations[1] ? DofMode::Rigid : DofMode::Free;
    s.modes[index(Dof::Qz)] = translations[2] ? DofMode::Rigid : DofMode::Free;
    s.modes[index(Dof::Mx)] = rotations[0] ? DofMode::Rigid : DofMode::Free;
    s.modes[index(Dof::My)] = rotations[1] ? DofMode::Rigid : DofMode::Free;
    s.modes[index(Dof::Mz)] = rotations[2] ? DofMode::Rigid : DofMode::Free;
    return joint_at("support " + node, std::nullopt, b, at, Frame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, s);
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
    SettingsCache cache;
    std::map<std::string, Vec3> nodes;
    const Json& node_list = scene_json::member(j, "nodes", "scene (with \"members\")");
    require_object(node_list, "nodes");
    for (const auto& item : node_list.items()) nodes[item.key()] = vec3(item.value(), "nodes." + item.key());

    const Json& members = j["members"];
    if (!members.is_array() || members.empty()) throw InputError("members: expected a non-empty array");
    std::vector<Member> parsed;
    std::map<std::string, std::vector<MemberEnd>> ends;  // node → the member ends there, in order
    std::set<std::string> names;
    for (const SceneBody& b : scene.bodies) names.insert(b.name);
    for (std::size_t i = 0; i < members.size(); ++i) {
        parsed.push_back(parse_member(members[i], "members[" + std::to_string(i) + "]", nodes, scene, catalogue, cache));
        const Member& m = parsed.back();
        for (int k = 0; k < m.segments; ++k) {
            if (!names.insert(scene.bodies[m.first_body + k].name).second)
                throw InputError(m.where + ": a second member or body named \"" + m.name + "\"");
        }
        ends[m.from].push_back({i, true});
        ends[m.to].push_back({i, false});
    }

    // Nodes where members meet: each further member end joined to the first one's. A removed member
    // is never the first: the node (its loads, its reported displacement) stays with the structure.
    for (auto& [node, at] : ends)
        std::stable_partition(at.begin(), at.end(), [&](const MemberEnd& e) { return !parsed[e.member].removed_at; });
    std::map<std::string, BodyPoint> points;
    for (const auto& [node, at] : ends) {
        const Vec3& p = nodes[node];
        const Member& first = parsed[at.front().member];
        points[node] = point_of(scene, first, at.front().at_start, p);
        scene.nodes.push_back({node, p, points[node]});
        for (std::size_t e = 1; e < at.size(); ++e) {
            const Member& other = parsed[at[e].member];
            const double length = 0.5 * (first.segment_length + other.segment_length);
            scene.joints.push_back(joint_at("node " + node + ": " + first.name + "-" + other.name, first.end_body(at.front().at_start),
                                            other.end_body(at[e].at_start), p, other.away_from(at[e].at_start),
                                            at_length(other.joint, other.segment_length, length)));
        }
    }

    if (j.contains("supports")) {
        const Json& supports = j["supports"];
        require_object(supports, "supports");
        for (const auto& item : supports.items()) {
            const std::string where = "supports." + item.key();
            const auto it = ends.find(item.key());
            if (it == ends.end())
                throw InputError(where + ": " + (nodes.count(item.key()) ? "no member meets this node" : "no node named \"" + item.key() + "\""));
            const MemberEnd& e = it->second.front();
            scene.joints.push_back(support_joint(item.key(), item.value(), where, parsed[e.member], e.at_start, nodes[item.key()]));
        }
    }
    // A removed member: every joint that holds it to the rest (nodes, supports) is severed then; it
    // falls as one piece (its own joints stay).
    for (const Member& m : parsed) {
        if (!m.removed_at) continue;
        for (SceneJoint& joint : scene.joints) {
            const bool a_in = joint.a && m.owns(*joint.a), b_in = m.owns(joint.b);
            if (a_in != b_in) joint.severed_at = m.removed_at;
        }
    }
    if (j.contains("loads")) {
        const Json& loads = j["loads"];
        if (!loads.is_array()) throw InputError("loads: expected an array");
        for (std::size_t i = 0; i < loads.size(); ++i) scene.loads.push_back(parse_load(loads[i], "loads[" + std::to_string(i) + "]", points));
    }
}

}  // namespace plascap
