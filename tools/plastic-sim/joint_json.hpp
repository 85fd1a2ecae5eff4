#pragma once
// One joint of a scene file: its bodies, frame, capacities (given, or from a section and material),
// stiffness (given, or from the section's beam segment of a given length), dof modes and limits.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "plascap/adapters/section_joint_settings.hpp"
#include "plascap/materials/catalogue.hpp"
#include "scene.hpp"

namespace plascap {

SceneJoint parse_joint(const nlohmann::json& j, const std::string& where, const std::vector<SceneBody>& bodies,
                       const MaterialCatalogue& catalogue);

// The "section" or "shape" of a joint or member (with its "material" where the section names none).
ValidSection read_joint_section(const nlohmann::json& j, const std::string& where, const MaterialCatalogue& catalogue);

// "yield_surface" (coupled | box) and "torsion" (fully-plastic | paper) into `options`.
void read_yield_choice(const nlohmann::json& j, const std::string& where, bool from_section, SectionJointOptions& options);

}  // namespace plascap
