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
#include "plascap/adapters/structure_model.hpp"
#include "plascap/materials/catalogue.hpp"

namespace plascap {

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

using SceneNode = StructureNode;  // a structure's node: a material point to report

// A joint: one of a structure's (its bodies then index Scene::bodies) or one placed by hand.
struct SceneJoint : StructureJoint {
    double engage_at = 0.0;  // [s]: the joint joins the world at the step starting nearest this time
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
