#pragma once
// A structure as bodies and plastic joints, for any engine (docs/structures.md): each member
// becomes `segments` rigid bodies with the real member's mass and inertia (not a box's), joined by
// plastic hinges whose capacities and stiffness come from the section and the segment's length;
// members meeting at a node and supports are joined the same way. Make each segment a body of your
// engine, then each joint a BulletPlasticJoint or an OdePlasticJoints::add with its frame().
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/plastic_joint_settings.hpp"
#include "plascap/adapters/structure.hpp"
#include "plascap/adapters/vec3.hpp"

namespace plascap {

using Quaternion = std::array<double, 4>;  // w, x, y, z; unit length

// A member's cross section as drawn on its line (the segment extruded along its y): each part's
// outer ring and holes in the segment's x–z plane, from the member's line [m].
using Outline = std::vector<std::array<double, 2>>;  // (x, z)
struct OutlinePart {
    Outline outer;
    std::vector<Outline> holes;
    bool operator==(const OutlinePart& o) const { return outer == o.outer && holes == o.holes; }
};
using SectionOutline = std::vector<OutlinePart>;

// A point of a body: where a node is carried, or where a load acts.
struct BodyPoint {
    std::size_t body = 0;
    Vec3 local{};  // in the body's frame, from its centre [m]
};

struct StructureSegment {
    std::string name;        // "member#k", k from 1 at the member's `from` end
    std::size_t member = 0;  // index into Structure::members
    Vec3 size{};             // a box around it: the section's extent across x and z, its length along y [m]
    double mass = 0.0;       // Σ ρ·A · length [kg]
    Vec3 position{};         // its centre [m]
    Quaternion orientation{1, 0, 0, 0};  // its axes: y along the member, z the section's depth
    Vec3 inertia{};          // principal moments about its own x, y, z through its centre [kg·m²]
    std::size_t outline = 0;  // index into StructureModel::outlines
};

struct StructureJoint {
    std::string name;
    std::optional<std::size_t> a;  // index into StructureModel::segments; empty: the world (a support)
    std::size_t b = 0;
    Vec3 anchor{};               // [m], world
    std::array<Vec3, 3> axes{};  // joint x, y (beam axis), z in world: orthonormal, right-handed
    PlasticJointSettings settings;
    std::optional<double> severed_at;  // [s]: it breaks then, whatever its load (a removed member)

    // Its frame in the world, origin the anchor: what OdePlasticJoints::add takes, and
    // BulletPlasticJoint as to_transform(frame()) (bullet_vec3.hpp).
    Pose frame() const {
        Pose p;
        p.origin = anchor;
        for (int r = 0; r < 3; ++r) p.rotation[r] = {axes[0][r], axes[1][r], axes[2][r]};  // columns x, y, z
        return p;
    }
};

struct StructureNode {
    std::string name;
    Vec3 position{};  // where it starts [m]
    BodyPoint at;     // the material point that carries it: of the first segment that meets it
};

struct StructureModel {
    std::vector<StructureSegment> segments;
    std::vector<StructureJoint> joints;  // inside members, then at nodes, then supports
    std::vector<StructureNode> nodes;    // the nodes a member meets, by name
    std::vector<SectionOutline> outlines;  // each distinct section once, simplified for drawing
};

// Throws InputError naming the member, node or support at fault: a node not finite, an unknown node,
// a zero-length member, a z_axis along the member or not finite, segments out of range, a removal
// time not finite or negative, a member without a section or with a material without density, two
// members of one name, a support that restrains nothing or holds a node no member meets.
StructureModel build_structure(const Structure& structure);

}  // namespace plascap
