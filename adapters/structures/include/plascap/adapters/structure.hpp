#pragma once
// A structure of members and nodes (docs/structures.md), as a library user or a scene file gives it:
// nodes by name, members between two nodes with a section and a number of rigid segments, and the
// supports that hold nodes to the world. build_structure() (structure_model.hpp) turns it into
// bodies and plastic joints for any engine.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "plascap/adapters/section_joint_settings.hpp"
#include "plascap/adapters/vec3.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

constexpr int kMaxMemberSegments = 1000;  // a member's segments: 1 to this

struct StructureMember {
    std::string name;
    std::string from, to;  // node names; the member's axis y runs from `from` to `to`
    // Its section, with a material that gives a density (the segments' mass). Members that share
    // one section object share its joint settings, computed once (T_p and J take a mesh each).
    std::shared_ptr<const ValidSection> section;
    std::optional<Vec3> z_axis;  // the section's z (its depth) in the world; none: against gravity (world x for a member along it)
    int segments = 4;            // rigid bodies, joined by plastic joints at their ends (1 to kMaxMemberSegments)
    // The joints' yield surface (coupled or box) and torsion capacity; their modes are set here:
    // rotations plastic (hinges), translations rigid.
    SectionJointOptions options;
    std::optional<double> removed_at;  // [s]: its joints to the rest of the structure break then
    std::string where;                 // how messages name it; empty: member "name"
};

// The world directions restrained at a node: fixed (all six), pinned (the translations), or any set.
struct StructureSupport {
    std::array<bool, 3> translations{true, true, true};  // along world x, y, z
    std::array<bool, 3> rotations{true, true, true};     // about world x, y, z
    static StructureSupport fixed() { return {}; }
    static StructureSupport pinned() { return {{true, true, true}, {false, false, false}}; }
};

struct Structure {
    std::map<std::string, Vec3> nodes;  // [m], world
    std::vector<StructureMember> members;
    std::map<std::string, StructureSupport> supports;  // by node
    Vec3 gravity{0, -9.81, 0};  // [m/s²]: only for the default z_axis
};

}  // namespace plascap
