#include "plascap/materials/catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "material_object.hpp"
#include "plascap/edit_distance.hpp"
#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"

namespace plascap {
namespace detail {
extern const char* const kBuiltInCatalogue;
}  // namespace detail

namespace {

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

}  // namespace

const MaterialCatalogue& MaterialCatalogue::built_in() {
    static const MaterialCatalogue catalogue = parse(detail::kBuiltInCatalogue, "built-in materials catalogue");
    return catalogue;
}

MaterialCatalogue MaterialCatalogue::parse(std::string_view json_text, const std::string& origin) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(json_text.begin(), json_text.end());
    } catch (const nlohmann::json::exception& e) {
        throw InputError(origin + ": malformed JSON: " + readable_json_message(e.what()));
    }
    if (!root.is_object() || !root.contains("materials") || !root["materials"].is_array())
        throw InputError(origin + ": expected {\"format\": \"plascap-materials-1\", \"materials\": [...]}");
    if (root.contains("format") && root["format"] != "plascap-materials-1")
        throw InputError(origin + ": unknown format " + root["format"].dump() + " (expected \"plascap-materials-1\")");
    MaterialCatalogue catalogue;
    const nlohmann::json& list = root["materials"];
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string where = origin + ": materials[" + std::to_string(i) + "]";
        Material m = detail::read_material_object(list[i], where);
        if (m.name.empty()) throw InputError(where + ": a catalogue material needs a \"name\"");
        if (catalogue.find(m.name) != nullptr)
            throw InputError(where + ": the name \"" + m.name + "\" is given twice in this file");
        catalogue.materials_.push_back(std::move(m));
    }
    return catalogue;
}

MaterialCatalogue MaterialCatalogue::read_file(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path + ": cannot open the materials file");
    std::ostringstream text;
    text << file.rdbuf();
    return parse(text.str(), path);
}

void MaterialCatalogue::add(const MaterialCatalogue& other) {
    for (const Material& m : other.materials_) {
        const auto same = std::find_if(materials_.begin(), materials_.end(),
                                       [&](const Material& mine) { return lower(mine.name) == lower(m.name); });
        if (same != materials_.end()) *same = m;
        else materials_.push_back(m);
    }
}

const Material* MaterialCatalogue::find(std::string_view name) const {
    const std::string key = lower(name);
    for (const Material& m : materials_)
        if (lower(m.name) == key) return &m;
    return nullptr;
}

const Material& MaterialCatalogue::get(std::string_view name, const std::string& where) const {
    if (const Material* m = find(name)) return *m;
    const std::vector<std::string> close = similar_names(name);
    std::string hint;
    for (const std::string& s : close) hint += (hint.empty() ? "" : ", ") + s;
    throw InputError(where + ": unknown material \"" + std::string(name) + "\"" +
                     (hint.empty() ? " (section-calc --list-materials shows them all)" : " (did you mean " + hint + "?)"));
}

std::vector<std::string> MaterialCatalogue::similar_names(std::string_view name, std::size_t most) const {
    const std::string key = lower(name);
    std::vector<std::pair<std::size_t, std::string>> scored;
    for (const Material& m : materials_) {
        const std::string candidate = lower(m.name);
        std::size_t distance = edit_distance(key, candidate);
        if (!key.empty() && candidate.find(key) != std::string::npos) distance = std::min<std::size_t>(distance, 1);
        if (distance <= std::max<std::size_t>(2, key.size() / 3)) scored.emplace_back(distance, m.name);
    }
    std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> names;
    for (std::size_t i = 0; i < scored.size() && i < most; ++i) names.push_back(scored[i].second);
    return names;
}

}  // namespace plascap
