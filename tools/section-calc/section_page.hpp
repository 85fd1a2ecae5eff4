#pragma once
// section-calc --html: one self-contained page with the section drawing, the capacity table and
// the interaction diagrams of the exact surface (docs/replay.md, "The section page").
#include <nlohmann/json.hpp>
#include <string>

namespace plascap::tools {

// `report` is the --json object (capacities, and the load check and curves when there); `svg` the
// --svg drawing; `note` a line the page shows under the diagrams (e.g. why there are none).
// Throws InputError when the file cannot be written.
void write_section_page(const std::string& path, const std::string& source, const nlohmann::ordered_json& report,
                        const std::string& svg, const std::string& note);

}  // namespace plascap::tools
