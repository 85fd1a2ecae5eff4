#pragma once
// One joint of a scene file: its bodies, frame, capacities (given, or from a section and material),
// stiffness (given, or from the section's beam segment of a given length), dof modes and limits.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "plascap/materials/catalogue.hpp"
#include "scene.hpp"

namespace plascap {

SceneJoint parse_joint(const nlohmann::json& j, const std::string& where, const std::vector<SceneBody>& bodies,
                       const MaterialCatalogue& catalogue);

}  // namespace plascap
