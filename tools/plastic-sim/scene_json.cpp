// The scene file: top level and bodies (joints: joint_json.cpp).
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "joint_json.hpp"
#include "structure_json.hpp"
#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"
#include "scene.hpp"
#include "scene_json_values.hpp"

namespace plascap {
namespace {

using namespace scene_json;

// More steps than this is a typo in dt or duration, not a simulation anyone waits for.
constexpr double kMaxSteps = 1e7;
// Beyond these a scene is a unit mistake, and an engine's bounding boxes and inertias overflow.
constexpr double kMaxSize = 1e4;       // box edge [m]
constexpr double kMaxMass = 1e12;      // [kg]
constexpr double kMaxCoordinate = 1e6; // |position| [m]
constexpr double kMaxSpeed = 1e5;      // |velocity| [m/s], |angular velocity| [rad/s]

// `limit_text` says the limit with its unit, e.g. "1e4 m".
void within(const Vec3& v, double limit, const std::string& where, const char* limit_text) {
    for (std::size_t i = 0; i < 3; ++i) {
        if (std::abs(v[i]) > limit) {
            throw InputError(where + "[" + std::to_string(i) + "]: beyond the supported " + limit_text);
        }
    }
}

SceneBody parse_body(const Json& j, const std::string& where) {
    require_object(j, where);
    reject_unknown_keys(j, where, {"name", "box", "mass", "density", "position", "orientation", "velocity",
                                   "angular_velocity", "static"});
    SceneBody body;
    body.name = text(member(j, "name", where), where + ".name");
    if (body.name.empty() || body.name == "world") {
        throw InputError(where + ".name: \"" + body.name + "\" is reserved or empty");
    }
    const std::string at = where + " (\"" + body.name + "\")";
    body.size = vec3(member(j, "box", at), at + ".box");
    for (std::size_t i = 0; i < 3; ++i) {
        if (!(body.size[i] > 0.0)) throw InputError(at + ".box[" + std::to_string(i) + "]: must be positive");
    }
    within(body.size, kMaxSize, at + ".box", "1e4 m");
    const bool has_mass = j.contains("mass"), has_density = j.contains("density");
    if (has_mass == has_density) throw InputError(at + ": give exactly one of \"mass\" and \"density\"");
    body.mass = has_mass ? positive_number(j["mass"], at + ".mass")
                         : positive_number(j["density"], at + ".density") * body.size[0] * body.size[1] * body.size[2];
    if (!(body.mass <= kMaxMass)) throw InputError(at + ": the mass is beyond the supported 1e12 kg");
    if (j.contains("position")) body.position = vec3(j["position"], at + ".position");
    within(body.position, kMaxCoordinate, at + ".position", "1e6 m");
    if (j.contains("orientation")) body.orientation = unit_quaternion(j["orientation"], at + ".orientation");
    if (j.contains("velocity")) body.velocity = vec3(j["velocity"], at + ".velocity");
    if (j.contains("angular_velocity")) body.angular_velocity = vec3(j["angular_velocity"], at + ".angular_velocity");
    within(body.velocity, kMaxSpeed, at + ".velocity", "1e5 m/s");
    within(body.angular_velocity, kMaxSpeed, at + ".angular_velocity", "1e5 rad/s");
    if (j.contains("static")) {
        if (!j["static"].is_boolean()) throw InputError(at + ".static: expected true or false");
        body.is_static = j["static"].get<bool>();
    }
    return body;
}

int parse_iterations(const Json& j) {
    if (!j.is_number_integer() || j.get<long long>() < 1 || j.get<long long>() > 10000) {
        throw InputError("iterations: expected a whole number from 1 to 10000");
    }
    return static_cast<int>(j.get<long long>());
}

Scene parse_scene(const Json& j, const MaterialCatalogue& catalogue) {
    require_object(j, "scene");
    reject_unknown_keys(j, "scene", {"name", "description", "dt", "duration", "iterations", "gravity", "bodies", "joints",
                                     "nodes", "members", "supports", "loads"});
    Scene scene;
    scene.dt = positive_number(member(j, "dt", "scene"), "dt");
    scene.duration = positive_number(member(j, "duration", "scene"), "duration");
    if (scene.duration / scene.dt > kMaxSteps) {
        throw InputError("duration/dt: " + std::to_string(scene.duration / scene.dt) + " steps is more than the 1e7 allowed");
    }
    if (j.contains("iterations")) scene.iterations = parse_iterations(j["iterations"]);
    if (j.contains("gravity")) scene.gravity = vec3(j["gravity"], "gravity");
    within(scene.gravity, kMaxSpeed, "gravity", "1e5 m/s²");

    check_structure_keys(j);
    if (!j.contains("bodies") && !j.contains("members")) throw InputError("scene: give \"bodies\" or a structure's \"members\"");
    const Json& bodies = j.contains("bodies") ? j["bodies"] : Json::array();
    if (!bodies.is_array() || (bodies.empty() && !j.contains("members"))) throw InputError("bodies: expected a non-empty array");
    std::set<std::string> names;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        scene.bodies.push_back(parse_body(bodies[i], "bodies[" + std::to_string(i) + "]"));
        if (!names.insert(scene.bodies.back().name).second) {
            throw InputError("bodies[" + std::to_string(i) + "]: a second body named \"" + scene.bodies.back().name + "\"");
        }
    }
    add_structure(j, scene, catalogue);  // segments after the bodies: joints may name neither
    if (j.contains("joints")) {
        const Json& joints = j["joints"];
        if (!joints.is_array()) throw InputError("joints: expected an array");
        std::set<std::string> joint_names;
        for (std::size_t i = 0; i < joints.size(); ++i) {
            const std::string where = "joints[" + std::to_string(i) + "]";
            scene.joints.push_back(parse_joint(joints[i], where, scene.bodies, catalogue));
            if (!joint_names.insert(scene.joints.back().name).second) {
                throw InputError(where + ": a second joint named \"" + scene.joints.back().name + "\"");
            }
        }
    }
    return scene;
}

}  // namespace

std::size_t Scene::steps() const {
    return static_cast<std::size_t>(std::max(1.0, std::round(duration / dt)));
}

Scene parse_scene_json(std::string_view text, const MaterialCatalogue& catalogue) {
    Json j;
    try {
        j = Json::parse(text);
    } catch (const Json::exception& e) {  // syntax, and numbers beyond a double (out_of_range)
        throw InputError("not valid JSON: " + readable_json_message(e.what()));
    }
    return parse_scene(j, catalogue);
}

Scene read_scene_file(const std::string& path, const MaterialCatalogue& catalogue) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return parse_scene_json(text.str(), catalogue);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
}

}  // namespace plascap
