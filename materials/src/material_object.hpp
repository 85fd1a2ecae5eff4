#pragma once
// The material reader on an already parsed JSON value (internal: nlohmann stays out of the
// public headers). Used by parse_material_json() and the catalogue reader.
#include <nlohmann/json.hpp>
#include <string>

#include "plascap/materials/material.hpp"

namespace plascap::detail {

Material read_material_object(const nlohmann::json& value, const std::string& where);

}  // namespace plascap::detail
