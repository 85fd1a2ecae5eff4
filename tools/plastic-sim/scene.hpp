#pragma once
// A plastic-sim scene: rigid boxes joined to each other or to the world by plastic joints. The JSON
// form is documented in docs/plastic-sim.md; parse_scene_json() checks everything an engine would
// otherwise crash on or silently mis-simulate.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "plascap/adapters/vec3.hpp"
#include "plascap/adapters/plastic_joint_settings.hpp"
#include "plascap/materials/catalogue.hpp"

namespace plascap {

using Quaternion = std::array<double, 4>;  // w, x, y, z; unit length

// A structure member's cross section as a replay draws it (the segment extruded along its y):
// each part's outer ring and holes in the segment's x–z plane, from the member's line [m].
using Outline = std::vector<std::array<double, 2>>;  // (x, z)
struct OutlinePart {
    Outline outer;
    std::vector<Outline> holes;
    bool operator==(const OutlinePart& o) const { return outer == o.outer && holes == o.holes; }
};
using SectionOutline = std::vector<OutlinePart>;

struct SceneBody {
    std::string name;
    Vec3 size{};          // full box edges along the body's x, y, z [m]
    double mass = 0.0;         // [kg]; static bodies keep theirs for reports only
    Vec3 position{};      // centre [m]
    Quaternion orientation{1, 0, 0, 0};
    Vec3 velocity{};          // initial [m/s]
    Vec3 angular_velocity{};  // initial [rad/s]
    bool is_static = false;
    // Principal moments of inertia about the body's own x, y, z through its centre [kg·m²]; none:
    // the box's, m(b² + c²)/12, … (a structure's segment has its section's, not a box's).
    std::optional<Vec3> inertia;
    bool structure = false;  // a structure's segment: collides with other bodies, not with other segments
    std::optional<std::size_t> outline;  // a structure's segment: its section, in Scene::outlines
};

// A point of a body that a structure names (a node), or where a load acts.
struct BodyPoint {
    std::size_t body = 0;
    Vec3 local{};  // in the body's frame, from its centre [m]
};

// An external force and moment on a body, in world directions, scaled by a piecewise-linear
// factor of time (constant beyond its ends; none: 1).
struct SceneLoad {
    std::string node;
    BodyPoint at;
    Vec3 force{};   // [N]
    Vec3 moment{};  // [N·m]
    std::vector<std::pair<double, double>> history;  // (t [s], factor), t strictly increasing
    double factor(double time) const;
};

struct SceneNode {
    std::string name;
    Vec3 position{};  // where it starts [m]
    BodyPoint at;     // the material point that carries it: of the first segment that meets it
};

struct SceneJoint {
    std::string name;
    std::optional<std::size_t> a;  // index into Scene::bodies; empty = the world
    std::size_t b = 0;
    Vec3 anchor{};             // [m], world
    std::array<Vec3, 3> axes{};  // joint x, y (beam axis), z in world: orthonormal, right-handed
    PlasticJointSettings settings;
    double engage_at = 0.0;  // [s]: the joint joins the world at the step starting nearest this time
    // [s]: the joint breaks in the step starting nearest this time, whatever its load (a structure's
    // member "removed_at" then)
    std::optional<double> severed_at;
};

struct Scene {
    double dt = 1.0 / 60;       // [s]
    double duration = 1.0;      // [s]
    int iterations = 10;        // solver iterations per step
    Vec3 gravity{0, -9.81, 0};
    std::vector<SceneBody> bodies;
    std::vector<SceneJoint> joints;
    std::vector<SceneNode> nodes;  // from a structure ("nodes", "members"; docs/structures.md)
    std::vector<SceneLoad> loads;
    std::vector<SectionOutline> outlines;  // the structure's sections, for drawing

    std::size_t steps() const;  // duration/dt, rounded to the nearest whole step (at least 1)
};

// Every problem throws InputError naming where it is, e.g. "joints[1] (\"hinge\").axis: ...".
Scene parse_scene_json(std::string_view text, const MaterialCatalogue& catalogue = MaterialCatalogue::built_in());
Scene read_scene_file(const std::string& path, const MaterialCatalogue& catalogue = MaterialCatalogue::built_in());

}  // namespace plascap
