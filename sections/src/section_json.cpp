#include "plascap/sections/section_json.hpp"

#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>

#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"
#include "plascap/materials/material_json.hpp"
#include "plascap/materials/mixture.hpp"
#include "plascap/sections/shape_designation.hpp"

namespace plascap {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

std::string type_name(const json& value) { return value.type_name(); }

double read_number(const json& value, const std::string& where) {
    if (!value.is_number()) fail(where, "expected a number, got " + type_name(value));
    return value.get<double>();
}

Point read_point(const json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 2)
        fail(where, "expected a point [x, z] (two numbers in metres), got " +
                        (value.is_array() ? "an array of " + std::to_string(value.size()) : type_name(value)));
    return {read_number(value[0], where + "[0]"), read_number(value[1], where + "[1]")};
}

Ring read_ring(const json& value, const std::string& where) {
    if (!value.is_array()) fail(where, "expected a ring: an array of [x, z] points, got " + type_name(value));
    Ring ring;
    ring.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) ring.push_back(read_point(value[i], where + "[" + std::to_string(i) + "]"));
    return ring;
}

// A material: a catalogue name ("S355") or an object (materials/material_json.hpp).
Material read_material(const json& value, const std::string& where, const MaterialCatalogue& catalogue) {
    if (value.is_string()) return catalogue.get(value.get<std::string>(), where);
    if (!value.is_object()) fail(where, "expected a material name such as \"S355\" or an object such as {\"fy\": 355e6}, got " + type_name(value));
    return parse_material_json(value.dump(), where);
}

// {"at": [x, z], "area": m², "material": name or object}
Bar read_bar(const json& value, const std::string& where, const MaterialCatalogue& catalogue) {
    if (!value.is_object()) fail(where, "expected a bar {\"at\": [x, z], \"area\": m², \"material\": ...}, got " + type_name(value));
    reject_unknown_keys(value, where, {"at", "area", "material"});
    for (const char* key : {"at", "area", "material"})
        if (!value.contains(key)) fail(where, std::string("the bar has no \"") + key + "\"");
    return Bar{read_point(value["at"], where + ".at"), read_number(value["area"], where + ".area"),
               read_material(value["material"], where + ".material", catalogue)};
}

// The paper's shortcut, {"ratio": ρ, "material": ...}: reinforcement spread evenly over the part.
Material read_reinforcement(const json& value, const std::string& where, const Material& matrix,
                            const MaterialCatalogue& catalogue) {
    if (!value.is_object()) fail(where, "expected {\"ratio\": 0.0004, \"material\": \"B500B\"}, got " + type_name(value));
    reject_unknown_keys(value, where, {"ratio", "material"});
    for (const char* key : {"ratio", "material"})
        if (!value.contains(key)) fail(where, std::string("the reinforcement has no \"") + key + "\"");
    const double ratio = read_number(value["ratio"], where + ".ratio");
    if (!(ratio > 0.0 && ratio < 1.0)) fail(where + ".ratio", "must be between 0 and 1 (exclusive): the steel's share of the area");
    return smeared_mixture(matrix, read_material(value["material"], where + ".material", catalogue), ratio);
}

Part read_part(const json& value, const std::string& where, const std::optional<Material>& default_material,
               const MaterialCatalogue& catalogue) {
    if (!value.is_object()) fail(where, "expected a part object {\"outer\": [...], \"holes\": [...]}, got " + type_name(value));
    reject_unknown_keys(value, where, {"outer", "holes", "material", "bars", "reinforcement", "name"});
    if (!value.contains("outer")) fail(where, "the part has no \"outer\" ring");
    Part part;
    part.outer = read_ring(value["outer"], where + ".outer");
    if (value.contains("holes")) {
        const json& holes = value["holes"];
        if (!holes.is_array()) fail(where + ".holes", "expected an array of rings, got " + type_name(holes));
        for (std::size_t h = 0; h < holes.size(); ++h)
            part.holes.push_back(read_ring(holes[h], where + ".holes[" + std::to_string(h) + "]"));
    }
    if (value.contains("material")) {
        part.material = read_material(value["material"], where + ".material", catalogue);
    } else if (default_material) {
        part.material = *default_material;
    } else {
        fail(where, "no material: give the part a \"material\" or the section a default \"material\"");
    }
    if (value.contains("bars")) {
        const json& bars = value["bars"];
        if (!bars.is_array()) fail(where + ".bars", "expected an array of bars, got " + type_name(bars));
        for (std::size_t b = 0; b < bars.size(); ++b)
            part.bars.push_back(read_bar(bars[b], where + ".bars[" + std::to_string(b) + "]", catalogue));
    }
    if (value.contains("reinforcement"))
        part.material = read_reinforcement(value["reinforcement"], where + ".reinforcement", part.material, catalogue);
    return part;
}

std::string describe(const json::exception& e) { return readable_json_message(e.what()); }

json parse_json(std::string_view text) {
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        throw InputError("malformed JSON: " + describe(e));  // names the line and column
    } catch (const json::exception& e) {
        throw InputError("unreadable JSON: " + describe(e));  // e.g. a number too large for a double
    }
}

}  // namespace

Section parse_section_json(std::string_view text, const MaterialCatalogue& catalogue) {
    const json root = parse_json(text);
    if (!root.is_object()) fail("section", "expected a JSON object with \"parts\", got " + type_name(root));
    reject_unknown_keys(root, "section", {"shear", "reference", "material", "parts", "shape", "name", "description"});

    Section section;
    if (root.contains("shear")) {
        if (!root["shear"].is_string()) fail("shear", "expected \"tresca\" or \"von-mises\", got " + type_name(root["shear"]));
        try {
            section.shear = parse_shear_criterion(root["shear"].get<std::string>());
        } catch (const InputError& e) {
            fail("shear", e.what());
        }
    }
    if (root.contains("reference")) section.reference = read_point(root["reference"], "reference");
    std::optional<Material> default_material;
    if (root.contains("material")) default_material = read_material(root["material"], "material", catalogue);

    if (root.contains("shape")) {  // a standard shape by name instead of parts (docs/shapes.md)
        if (root.contains("parts")) fail("shape", "give \"shape\" or \"parts\", not both");
        if (!root["shape"].is_string()) fail("shape", "expected a designation such as \"HEB 200\", got " + type_name(root["shape"]));
        if (!default_material) fail("shape", "a shape needs a \"material\" (a catalogue name such as \"S355\" or an object)");
        try {
            section.parts = shape_section(root["shape"].get<std::string>(), *default_material).parts;
        } catch (const InputError& e) {
            fail("shape", e.what());
        }
        return section;
    }
    if (!root.contains("parts")) fail("section", "has no \"parts\" (or \"shape\")");
    const json& parts = root["parts"];
    if (!parts.is_array()) fail("parts", "expected an array of parts, got " + type_name(parts));
    for (std::size_t p = 0; p < parts.size(); ++p)
        section.parts.push_back(read_part(parts[p], "parts[" + std::to_string(p) + "]", default_material, catalogue));
    return section;
}

Section read_section_file(const std::string& path, const MaterialCatalogue& catalogue) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path + ": cannot open the file");
    std::ostringstream text;
    text << file.rdbuf();
    try {
        return parse_section_json(text.str(), catalogue);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
}

}  // namespace plascap
