#pragma once
// Typed reads from a scene's JSON with messages that name the key: every number must be finite,
// every vector have three components, and so on.
#include <nlohmann/json.hpp>

#include <string>

#include "plascap/adapters/vec3.hpp"
#include "scene.hpp"

namespace plascap::scene_json {

using Json = nlohmann::json;

const Json& member(const Json& object, const char* key, const std::string& where);
void require_object(const Json& value, const std::string& where);
double finite_number(const Json& value, const std::string& where);
double positive_number(const Json& value, const std::string& where);
Vec3 vec3(const Json& value, const std::string& where);
Vec3 unit_vec3(const Json& value, const std::string& where);  // normalised; zero or tiny refused
Quaternion unit_quaternion(const Json& value, const std::string& where);
std::string text(const Json& value, const std::string& where);

}  // namespace plascap::scene_json
