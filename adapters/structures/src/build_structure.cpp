#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "member_frame.hpp"
#include "plascap/adapters/structure_model.hpp"
#include "plascap/input_error.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "section_outline.hpp"

namespace plascap {
namespace {

using detail::MemberFrame;

// A member as built: where its segments are, and the joint that stands for one of its segments.
struct BuiltMember {
    const StructureMember* input = nullptr;
    std::string where;
    Vec3 start{};
    MemberFrame frame;
    double segment_length = 0.0;
    std::size_t first_segment = 0;
    PlasticJointSettings joint;  // between consecutive segments: a beam segment of segment_length
    std::size_t end_segment(bool at_start) const { return first_segment + (at_start ? 0 : input->segments - 1); }
    bool owns(std::size_t s) const { return s >= first_segment && s < first_segment + static_cast<std::size_t>(input->segments); }
    MemberFrame away_from(bool at_start) const { return at_start ? frame : frame.reversed(); }
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

const Vec3& node_at(const Structure& s, const std::string& name, const std::string& where) {
    const auto it = s.nodes.find(name);
    if (it == s.nodes.end()) throw InputError(where + ": no node named \"" + name + "\"");
    return it->second;
}

bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// Members of one section share its joint settings, computed once for a 1 m segment and scaled to
// each member's segment length: by section object, yield surface and torsion capacity.
using SettingsKey = std::tuple<const ValidSection*, bool, TorsionCapacity>;

class Builder {
public:
    explicit Builder(const Structure& s) : structure_(s) {}

    StructureModel build() {
        for (const auto& [name, at] : structure_.nodes)
            if (!finite(at)) throw InputError("node \"" + name + "\": its position is not finite");
        std::set<std::string> names;
        for (std::size_t i = 0; i < structure_.members.size(); ++i) {
            add_member(structure_.members[i], i);
            if (!names.insert(structure_.members[i].name).second)
                throw InputError(members_.back().where + ": a second member named \"" + structure_.members[i].name + "\"");
        }
        join_at_nodes();
        add_supports();
        sever_removed_members();
        return std::move(model_);
    }

private:
    struct MemberEnd {
        std::size_t member;
        bool at_start;
    };

    const PlasticJointSettings& joint_settings(const StructureMember& m, const ValidSection& section, bool elastic, const std::string& where) {
        const SettingsKey key{&section, m.options.coupled, m.options.torsion};
        auto cached = settings_.find(key);
        if (cached != settings_.end()) return cached->second;
        SectionJointOptions options = m.options;
        // Plastic hinges: the rotations yield, the translations are rigid — their forces still count on the
        // coupled surface and lower the moment capacity. With plastic translations too, the radial row
        // bounds pin the shear and axial rows at the load of the moment the hinge forms, and the next
        // step's redistribution slides them: a portal then collapsed 8 % early (docs/structures.md).
        for (Dof dof : kAllDofs) options.modes[index(dof)] = is_rotation(dof) ? DofMode::Plastic : DofMode::Rigid;
        options.segment_length = elastic ? std::optional<double>(1.0) : std::nullopt;  // without E: rigid-plastic
        try {
            return settings_.emplace(key, section_joint_settings(section, options)).first->second;
        } catch (const InputError& e) {
            throw InputError(where + ": " + e.what());
        }
    }

    std::size_t outline_of(const ValidSection& section, const ElasticProperties& elastic) {
        SectionOutline outline = detail::section_outline(section, elastic);
        const auto same = std::find(model_.outlines.begin(), model_.outlines.end(), outline);
        if (same != model_.outlines.end()) return static_cast<std::size_t>(same - model_.outlines.begin());
        model_.outlines.push_back(std::move(outline));
        return model_.outlines.size() - 1;
    }

    void add_member(const StructureMember& m, std::size_t i) {
        BuiltMember b;
        b.input = &m;
        b.where = m.where.empty() ? "member \"" + m.name + "\"" : m.where;
        const std::string& where = b.where;
        b.start = node_at(structure_, m.from, where + ".from");
        const Vec3 span = difference(node_at(structure_, m.to, where + ".to"), b.start);
        const double length = norm(span);
        if (!(length > 1e-6)) throw InputError(where + ": has zero length (\"" + m.from + "\" and \"" + m.to + "\" coincide)");
        if (m.z_axis && !finite(*m.z_axis)) throw InputError(where + ".z_axis: is not finite");
        b.frame = detail::member_frame(m.z_axis, scaled(span, 1.0 / length), structure_.gravity, where);
        if (m.segments < 1 || m.segments > kMaxMemberSegments)
            throw InputError(where + ".segments: expected a whole number from 1 to " + std::to_string(kMaxMemberSegments));
        if (m.removed_at && !std::isfinite(*m.removed_at)) throw InputError(where + ".removed_at: is not a finite time");
        if (m.removed_at && *m.removed_at < 0.0) throw InputError(where + ".removed_at: must not be negative");
        if (!m.section) throw InputError(where + ": a member needs a section");
        const ValidSection& section = *m.section;
        const double mu = mass_per_length(section, where);
        const ElasticProperties elastic = elastic_properties(section);
        b.segment_length = length / m.segments;
        b.joint = at_length(joint_settings(m, section, elastic.stiffness.has_value(), where), 1.0, b.segment_length);

        // Boxes for contact, with the real member's mass and inertia about their axes:
        // ρ·ℓ·Ixx + m·ℓ²/12 about x, ρ·ℓ·(Ixx + Izz) about the member, ρ·ℓ·Izz + m·ℓ²/12 about z
        // (the section's second moments; the parallel-axis and slender-rod terms, e.g. Meriam & Kraige, Dynamics, App. B).
        const auto [width, depth] = detail::section_extent(section);
        const double l = b.segment_length, mass = mu * l, rho = mu / elastic.area;
        b.first_segment = model_.segments.size();
        const std::size_t outline = outline_of(section, elastic);
        for (int k = 0; k < m.segments; ++k) {
            StructureSegment s;
            s.name = m.name + "#" + std::to_string(k + 1);
            s.member = i;
            s.size = {width, l, depth};
            s.mass = mass;
            s.position = b.start;
            add_scaled(s.position, b.frame.y, l * (k + 0.5));
            s.orientation = detail::quaternion_of(b.frame);
            s.inertia = {rho * l * elastic.Ixx + mass * l * l / 12, rho * l * (elastic.Ixx + elastic.Izz), rho * l * elastic.Izz + mass * l * l / 12};
            s.outline = outline;
            model_.segments.push_back(std::move(s));
        }
        for (int k = 0; k + 1 < m.segments; ++k) {
            Vec3 anchor = b.start;
            add_scaled(anchor, b.frame.y, l * (k + 1));
            model_.joints.push_back(joint(m.name + "#" + std::to_string(k + 1) + "-" + std::to_string(k + 2), b.first_segment + k,
                                          b.first_segment + k + 1, anchor, b.frame, b.joint));
        }
        members_.push_back(std::move(b));
        ends_[m.from].push_back({i, true});
        ends_[m.to].push_back({i, false});
    }

    static StructureJoint joint(std::string name, std::optional<std::size_t> a, std::size_t b, const Vec3& anchor, const MemberFrame& f,
                                PlasticJointSettings settings) {
        return {std::move(name), a, b, anchor, {f.x, f.y, f.z}, std::move(settings), std::nullopt};
    }

    BodyPoint point_of(const BuiltMember& m, bool at_start, const Vec3& world) const {
        BodyPoint p;
        p.body = m.end_segment(at_start);
        const Vec3 d = difference(world, model_.segments[p.body].position);
        p.local = {dot(d, m.frame.x), dot(d, m.frame.y), dot(d, m.frame.z)};
        return p;
    }

    // Nodes where members meet: each further member end joined to the first one's. A removed member
    // is never the first: the node (its loads, its reported displacement) stays with the structure.
    void join_at_nodes() {
        for (auto& [node, at] : ends_)
            std::stable_partition(at.begin(), at.end(), [&](const MemberEnd& e) { return !members_[e.member].input->removed_at; });
        for (const auto& [node, at] : ends_) {
            const Vec3& p = structure_.nodes.at(node);
            const BuiltMember& first = members_[at.front().member];
            model_.nodes.push_back({node, p, point_of(first, at.front().at_start, p)});
            for (std::size_t e = 1; e < at.size(); ++e) {
                const BuiltMember& other = members_[at[e].member];
                const double length = 0.5 * (first.segment_length + other.segment_length);
                model_.joints.push_back(joint("node " + node + ": " + first.input->name + "-" + other.input->name,
                                              first.end_segment(at.front().at_start), other.end_segment(at[e].at_start), p,
                                              other.away_from(at[e].at_start), at_length(other.joint, other.segment_length, length)));
            }
        }
    }

    void add_supports() {
        for (const auto& [node, support] : structure_.supports) {
            const std::string where = "supports." + node;
            const auto it = ends_.find(node);
            if (it == ends_.end())
                throw InputError(where + ": " + (structure_.nodes.count(node) ? "no member meets this node" : "no node named \"" + node + "\""));
            model_.joints.push_back(support_joint(node, support, where, members_[it->second.front().member], it->second.front().at_start));
        }
    }

    StructureJoint support_joint(const std::string& node, const StructureSupport& s, const std::string& where, const BuiltMember& m,
                                 bool at_start) const {
        const auto all = [](const std::array<bool, 3>& d) { return d[0] && d[1] && d[2]; };
        const auto none = [](const std::array<bool, 3>& d) { return !d[0] && !d[1] && !d[2]; };
        if (none(s.translations) && none(s.rotations)) throw InputError(where + ": restrains nothing");
        const Vec3& at = structure_.nodes.at(node);
        const std::size_t b = m.end_segment(at_start);
        if (all(s.translations) && all(s.rotations)) {
            // Fixed: in the member's frame, so that the support can form a plastic hinge with the
            // section's capacities, as the member's own joints do (a joint of half a segment's length).
            return joint("support " + node, std::nullopt, b, at, m.away_from(at_start), at_length(m.joint, m.segment_length, m.segment_length / 2));
        }
        // Partly restrained: rigid rows along the world directions named, free elsewhere (no hinge).
        PlasticJointSettings settings;
        const auto mode = [](bool restrained) { return restrained ? DofMode::Rigid : DofMode::Free; };
        settings.modes[index(Dof::Qx)] = mode(s.translations[0]);
        settings.modes[index(Dof::N)] = mode(s.translations[1]);
        settings.modes[index(Dof::Qz)] = mode(s.translations[2]);
        settings.modes[index(Dof::Mx)] = mode(s.rotations[0]);
        settings.modes[index(Dof::My)] = mode(s.rotations[1]);
        settings.modes[index(Dof::Mz)] = mode(s.rotations[2]);
        return joint("support " + node, std::nullopt, b, at, MemberFrame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, settings);
    }

    // A removed member: every joint that holds it to the rest (nodes, supports) is severed then; it
    // falls as one piece (its own joints stay).
    void sever_removed_members() {
        for (const BuiltMember& m : members_) {
            if (!m.input->removed_at) continue;
            for (StructureJoint& joint : model_.joints) {
                const bool a_in = joint.a && m.owns(*joint.a), b_in = m.owns(joint.b);
                if (a_in != b_in) joint.severed_at = m.input->removed_at;
            }
        }
    }

    const Structure& structure_;
    StructureModel model_;
    std::vector<BuiltMember> members_;
    std::map<std::string, std::vector<MemberEnd>> ends_;  // node → the member ends there, in order
    std::map<SettingsKey, PlasticJointSettings> settings_;
};

}  // namespace

StructureModel build_structure(const Structure& structure) { return Builder(structure).build(); }

}  // namespace plascap
