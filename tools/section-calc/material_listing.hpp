#pragma once
// section-calc --list-materials: the catalogue as a table for people or JSON for programs.
#include <string>

#include "plascap/materials/catalogue.hpp"

namespace plascap::tools {

std::string material_table(const MaterialCatalogue& catalogue);
std::string material_json(const MaterialCatalogue& catalogue);  // every property and its source

}  // namespace plascap::tools
