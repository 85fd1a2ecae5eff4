#pragma once
// A scene's structure (docs/structures.md): "nodes", "members", "supports" and "loads" become rigid
// segments with the real member's mass and inertia, plastic joints between consecutive segments, at
// nodes where members meet and at supports, nodes (material points to report) and loads.
#include <nlohmann/json.hpp>

#include "plascap/materials/catalogue.hpp"
#include "scene.hpp"

namespace plascap {

// Adds the structure in `j` (a whole scene object) to `scene`; nothing when it has no "members".
// Throws InputError naming the member, node, support or load at fault.
void add_structure(const nlohmann::json& j, Scene& scene, const MaterialCatalogue& catalogue);

// Throws InputError for "nodes", "supports" or "loads" without "members".
void check_structure_keys(const nlohmann::json& j);

}  // namespace plascap
