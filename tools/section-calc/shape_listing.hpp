#pragma once
// section-calc --list-shapes and --table: the shape catalogue, and one row of properties per
// shape, as a table for people, CSV or JSON for programs.
#include <string>
#include <vector>

#include "plascap/materials/material.hpp"
#include "plascap/sections/shape_catalogue.hpp"
#include "plascap/sections/shape_table.hpp"

namespace plascap::tools {

// `family` empty: every family. Throws InputError for an unknown family, naming the known ones.
std::string shape_list(const ShapeCatalogue& catalogue, const std::string& family);
std::string shape_list_json(const ShapeCatalogue& catalogue, const std::string& family);

// The shapes of `family` ("all": every family), in catalogue order.
std::vector<const CatalogueShape*> shapes_of(const ShapeCatalogue& catalogue, const std::string& family);

enum class TableFormat { Text, Csv, Json };
std::string shape_table_text(const std::vector<ShapeTableRow>& rows, const Material& material, TableFormat format,
                             double seconds);

}  // namespace plascap::tools
