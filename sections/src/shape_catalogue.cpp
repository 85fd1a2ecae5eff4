#include "plascap/sections/shape_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <regex>

#include "designation_text.hpp"
#include "plascap/edit_distance.hpp"
#include "plascap/input_error.hpp"
#include "plascap/json_message.hpp"

namespace plascap {
namespace detail {
extern const char* const kBuiltInShapes;
}  // namespace detail

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

double length(const json& row, const char* key, const std::string& where, bool required = true) {
    if (!row.contains(key)) {
        if (required) fail(where, std::string("has no \"") + key + "\"");
        return 0.0;
    }
    if (!row[key].is_number()) fail(where + "." + key, "expected a length in metres");
    return row[key].get<double>();
}

// "53.81e-4" → {53.81e-4, 0.01e-4}: the resolution is one unit of the last printed digit.
PublishedValue published_value(const json& value, const std::string& where) {
    static const std::regex form(R"(^([0-9]+)(?:\.([0-9]+))?(?:[eE]([-+]?[0-9]+))?$)");
    std::smatch m;
    const std::string text = value.is_string() ? value.get<std::string>() : std::string();
    if (!std::regex_match(text, m, form))
        fail(where, "expected the printed value as a string such as \"53.81e-4\", got " + value.dump());
    const int decimals = static_cast<int>(m[2].length());
    const int exponent = m[3].matched ? std::stoi(m[3].str()) : 0;
    return {std::strtod(text.c_str(), nullptr), std::pow(10.0, exponent - decimals)};
}

ShapeGeometry geometry_of(const std::string& kind, const json& row, const std::string& where) {
    const auto L = [&](const char* key, bool required = true) { return length(row, key, where, required); };
    if (kind == "I") return IShape{L("h"), L("b"), L("tw"), L("tf"), L("r"), 0.0, L("toe_radius", false)};
    if (kind == "channel") return ChannelShape{L("h"), L("b"), L("tw"), L("tf"), L("r"), 0.0, L("toe_radius", false)};
    if (kind == "angle") return AngleShape{L("h"), L("b"), L("t"), L("r"), L("toe_radius", false)};
    if (kind == "tee") return TeeShape{L("h"), L("b"), L("tw"), L("tf"), L("r")};
    if (kind == "rectangular_hollow")
        return RectangularHollowShape{L("h"), L("b"), L("t"), L("outer_radius"), L("inner_radius")};
    if (kind == "circular_hollow") return CircularHollowShape{L("D"), L("t")};
    fail(where, "unknown shape kind \"" + kind + "\" (known: I, channel, angle, tee, rectangular_hollow, circular_hollow)");
}

std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

std::string designation_key(std::string_view designation) {
    std::string key;
    for (char c : detail::designation_upper(designation))
        if (!std::isspace(static_cast<unsigned char>(c)) && c != '-' && c != '_') key += c;
    static const std::regex he(R"(^HE([0-9]+)(A|B|M)$)");
    std::smatch m;
    if (std::regex_match(key, m, he)) key = "HE" + m[2].str() + m[1].str();
    return key;
}

const ShapeCatalogue& ShapeCatalogue::built_in() {
    static const ShapeCatalogue catalogue = parse(detail::kBuiltInShapes, "built-in shape catalogue");
    return catalogue;
}

ShapeCatalogue ShapeCatalogue::parse(std::string_view json_text, const std::string& origin) {
    json root;
    try {
        root = json::parse(json_text.begin(), json_text.end());
    } catch (const json::exception& e) {
        throw InputError(origin + ": malformed JSON: " + readable_json_message(e.what()));
    }
    if (!root.is_object() || root.value("format", "") != "plascap-shapes-1" || !root.contains("families") ||
        !root["families"].is_array())
        throw InputError(origin + ": expected {\"format\": \"plascap-shapes-1\", \"families\": [...]}");
    ShapeCatalogue catalogue;
    for (std::size_t f = 0; f < root["families"].size(); ++f) {
        const json& item = root["families"][f];
        const std::string where = origin + ": families[" + std::to_string(f) + "]";
        ShapeFamily family;
        for (auto [field, key] : {std::pair{&family.name, "name"}, {&family.kind, "kind"}, {&family.standard, "standard"},
                                  {&family.description, "description"}, {&family.source, "source"}}) {
            if (!item.contains(key) || !item[key].is_string()) fail(where, std::string("needs a string \"") + key + "\"");
            *field = item[key].get<std::string>();
        }
        if (!item.contains("shapes") || !item["shapes"].is_array()) fail(where, "needs an array \"shapes\"");
        for (std::size_t s = 0; s < item["shapes"].size(); ++s) {
            const json& row = item["shapes"][s];
            const std::string at = where + ".shapes[" + std::to_string(s) + "]";
            if (!row.is_object() || !row.contains("designation") || !row["designation"].is_string())
                fail(at, "needs a string \"designation\"");
            CatalogueShape shape{row["designation"].get<std::string>(), family.name, geometry_of(family.kind, row, at), {}};
            if (row.contains("published"))
                for (const auto& p : row["published"].items())
                    shape.published[p.key()] = published_value(p.value(), at + ".published." + p.key());
            const std::string key = designation_key(shape.designation);
            if (catalogue.index_.count(key) != 0) fail(at, "the designation \"" + shape.designation + "\" is given twice");
            catalogue.index_[key] = {catalogue.families_.size(), family.shapes.size()};
            family.shapes.push_back(std::move(shape));
        }
        catalogue.families_.push_back(std::move(family));
    }
    return catalogue;
}

const ShapeFamily* ShapeCatalogue::family(std::string_view name) const {
    for (const ShapeFamily& f : families_)
        if (lower(f.name) == lower(name)) return &f;
    return nullptr;
}

const CatalogueShape* ShapeCatalogue::find(std::string_view designation) const {
    const auto it = index_.find(designation_key(designation));
    return it == index_.end() ? nullptr : &families_[it->second.first].shapes[it->second.second];
}

std::vector<std::string> ShapeCatalogue::suggestions(std::string_view designation, std::size_t count) const {
    const std::string key = designation_key(designation);
    std::vector<std::pair<std::size_t, std::string>> ranked;
    for (const auto& [candidate, at] : index_)
        ranked.push_back({edit_distance(key, candidate), families_[at.first].shapes[at.second].designation});
    std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> out;
    for (std::size_t i = 0; i < ranked.size() && i < count && ranked[i].first <= std::max<std::size_t>(3, key.size() / 2); ++i)
        out.push_back(ranked[i].second);
    return out;
}

std::size_t ShapeCatalogue::size() const { return index_.size(); }

}  // namespace plascap
