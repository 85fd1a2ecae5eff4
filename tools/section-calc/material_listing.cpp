#include "material_listing.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "text_columns.hpp"

namespace plascap::tools {
namespace {

// A value scaled to the column's unit, or "—" when the material does not give it.
std::string cell(const std::optional<double>& value, double unit, const char* pattern) {
    if (!value) return "—";
    char text[32];
    std::snprintf(text, sizeof text, pattern, *value / unit);
    return text;
}

}  // namespace

std::string material_table(const MaterialCatalogue& catalogue) {
    std::ostringstream out;
    out << padded("name", 15) << padded("fy MPa", 8) << padded("fc MPa", 8) << padded("E GPa", 7) << padded("ν", 6)
        << padded("G GPa", 7) << padded("ρ kg/m³", 9) << padded("εu", 8) << "description\n";
    for (const Material& m : catalogue.materials()) {
        out << padded(m.name, 15) << padded(cell(m.fy, 1e6, "%g"), 8) << padded(cell(m.compression_strength(), 1e6, "%g"), 8)
            << padded(cell(m.E, 1e9, "%g"), 7) << padded(cell(m.nu, 1.0, "%g"), 6) << padded(cell(m.shear_modulus(), 1e9, "%.3g"), 7)
            << padded(cell(m.density, 1.0, "%g"), 9) << padded(cell(m.ultimate_strain, 1.0, "%g"), 8) << m.description << "\n";
    }
    out << "\nfy: tension, fc: compression, εu: strain at fracture (a breaking limit); G: given, or E/(2(1 + ν)).\n"
        << "Every value's source: section-calc --list-materials --json, or materials/data/materials.json.\n";
    return out.str();
}

std::string material_json(const MaterialCatalogue& catalogue) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const Material& m : catalogue.materials()) {
        nlohmann::ordered_json entry;
        entry["name"] = m.name;
        entry["description"] = m.description;
        entry["fy"] = m.fy;
        entry["fc"] = m.compression_strength();
        const auto optional = [&](const char* key, const std::optional<double>& value) {
            if (value) entry[key] = *value;
        };
        optional("E", m.E);
        optional("nu", m.nu);
        optional("G", m.shear_modulus());
        optional("density", m.density);
        optional("ultimate_strain", m.ultimate_strain);
        optional("max_plastic_rotation", m.max_plastic_rotation);
        if (m.shear) entry["shear"] = to_string(*m.shear);
        entry["sources"] = m.sources;
        list.push_back(entry);
    }
    return list.dump(2) + "\n";
}

}  // namespace plascap::tools
