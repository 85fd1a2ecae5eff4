#include "plascap/materials/material_json.hpp"

#include <initializer_list>

#include "material_object.hpp"
#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"

namespace plascap {
namespace detail {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

constexpr std::initializer_list<const char*> kKeys = {"name", "description", "fy", "fc", "E", "nu", "G", "density",
                                                       "ultimate_strain", "max_plastic_rotation", "shear", "sources"};

double read_number(const json& object, const char* key, const std::string& where) {
    const json& value = object.at(key);
    if (!value.is_number()) fail(where + "." + key, std::string("expected a number, got ") + value.type_name());
    return value.get<double>();
}

std::optional<double> optional_number(const json& object, const char* key, const std::string& where) {
    if (!object.contains(key)) return std::nullopt;
    return read_number(object, key, where);
}

std::string read_text(const json& object, const char* key, const std::string& where) {
    const json& value = object.at(key);
    if (!value.is_string()) fail(where + "." + key, std::string("expected a string, got ") + value.type_name());
    return value.get<std::string>();
}

}  // namespace

Material read_material_object(const json& value, const std::string& where) {
    if (!value.is_object()) fail(where, std::string("expected a material object such as {\"fy\": 355e6}, got ") + value.type_name());
    reject_unknown_keys(value, where, kKeys, " in a material");
    if (!value.contains("fy")) fail(where, "the material has no yield stress \"fy\" [Pa]");
    Material m;
    m.fy = read_number(value, "fy", where);
    m.fc = optional_number(value, "fc", where);
    m.E = optional_number(value, "E", where);
    m.nu = optional_number(value, "nu", where);
    m.G = optional_number(value, "G", where);
    m.density = optional_number(value, "density", where);
    m.ultimate_strain = optional_number(value, "ultimate_strain", where);
    m.max_plastic_rotation = optional_number(value, "max_plastic_rotation", where);
    if (value.contains("name")) m.name = read_text(value, "name", where);
    if (value.contains("description")) m.description = read_text(value, "description", where);
    if (value.contains("shear")) {
        try {
            m.shear = parse_shear_criterion(read_text(value, "shear", where));
        } catch (const InputError& e) {
            fail(where + ".shear", e.what());
        }
    }
    if (value.contains("sources")) {
        const json& sources = value["sources"];
        if (!sources.is_object()) fail(where + ".sources", std::string("expected an object {property: source}, got ") + sources.type_name());
        for (const auto& item : sources.items()) m.sources[item.key()] = read_text(sources, item.key().c_str(), where + ".sources");
    }
    validate_material(m, where);
    return m;
}

}  // namespace detail

Material parse_material_json(std::string_view object_text, const std::string& where) {
    nlohmann::json value;
    try {
        value = nlohmann::json::parse(object_text.begin(), object_text.end());
    } catch (const nlohmann::json::exception& e) {
        throw InputError(where + ": malformed JSON: " + readable_json_message(e.what()));
    }
    return detail::read_material_object(value, where);
}

}  // namespace plascap
