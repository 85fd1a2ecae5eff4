#include "section_page.hpp"

#include "html_page.hpp"

namespace plascap::tools {

void write_section_page(const std::string& path, const std::string& source, const nlohmann::ordered_json& report,
                        const std::string& svg, const std::string& note) {
    nlohmann::ordered_json data;
    data["format"] = "plascap-section";
    data["version"] = 1;
    data["title"] = source;
    data["version_of_tool"] = "section-calc (plascap) " PLASCAP_VERSION;
    data["report"] = report;
    data["svg"] = svg;
    data["note"] = note;
    html::write_page(path, html::Page{html::PageKind::Section, source + " — section-calc", html::json_text(data)}, "--html");
}

}  // namespace plascap::tools
