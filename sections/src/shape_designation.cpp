#include "plascap/sections/shape_designation.hpp"

#include <cctype>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <vector>

#include "designation_text.hpp"
#include "plascap/input_error.hpp"

namespace plascap {
namespace {

[[noreturn]] void fail(std::string_view text, const std::string& what) {
    throw InputError("shape \"" + std::string(text) + "\": " + what);
}

// A plain decimal number (no sign, no exponent).
double decimal(const std::string& token, std::string_view text, const std::string& what) {
    static const std::regex form(R"(^[0-9]+(\.[0-9]*)?$|^\.[0-9]+$)");
    if (!std::regex_match(token, form)) fail(text, what + ": \"" + token + "\" is not a plain decimal number");
    return std::strtod(token.c_str(), nullptr);
}

// Millimetres → metres.
double millimetres(const std::string& token, std::string_view text, const std::string& what) {
    return decimal(token, text, what + " [mm]") * 1e-3;
}

struct Parametric {
    std::string prefix;
    std::vector<double> dimensions;             // [m]
    std::vector<std::pair<std::string, std::string>> options;  // keyword, value text ("" for flags)
};

Parametric split(std::string_view text) {
    static const std::regex form(R"(^\s*(I|U|L|T|BOX|TUBE|ROUND|FLAT)\s+([0-9.]+(?:\s*X\s*[0-9.]+)*)((?:\s+.*)?)$)");
    const std::string up = detail::designation_upper(text);
    std::smatch m;
    if (!std::regex_match(up, m, form)) return {};
    Parametric p{m[1].str(), {}, {}};
    std::string dims = m[2].str();
    std::size_t start = 0;
    for (std::size_t i = 0; i <= dims.size(); ++i) {
        if (i == dims.size() || dims[i] == 'X') {
            std::string token = dims.substr(start, i - start);
            token.erase(0, token.find_first_not_of(' '));
            token.erase(token.find_last_not_of(' ') + 1);
            p.dimensions.push_back(millimetres(token, text, "dimension " + std::to_string(p.dimensions.size() + 1)));
            start = i + 1;
        }
    }
    static const std::regex option(R"(^(TOE|SLOPE|RO|RI|R)=?([0-9.]+)%?$|^(HOT|COLD)$)");
    std::istringstream rest(m[3].str());
    for (std::string token; rest >> token;) {
        std::smatch o;
        if (!std::regex_match(token, o, option))
            fail(text, "unknown option \"" + token + "\" (options: r<mm>, toe<mm>, slope<%>, ro<mm>, ri<mm>, hot, cold)");
        p.options.push_back(o[3].matched ? std::pair{o[3].str(), std::string()} : std::pair{o[1].str(), o[2].str()});
    }
    return p;
}

void expect_dimensions(const Parametric& p, std::size_t count, const char* names, std::string_view text) {
    if (p.dimensions.size() != count)
        fail(text, "the " + p.prefix + " shape needs " + names + " (" + std::to_string(count) +
                       " dimensions in mm separated by x), got " + std::to_string(p.dimensions.size()));
}

// The options a prefix takes; any other is refused by name.
void allow_options(const Parametric& p, std::initializer_list<const char*> allowed, std::string_view text) {
    for (const auto& [key, value] : p.options) {
        bool ok = false;
        for (const char* a : allowed) ok = ok || key == a;
        if (!ok) fail(text, "option \"" + key + "\" does not apply to the " + p.prefix + " shape");
    }
}

double option(const Parametric& p, const char* key, std::string_view text, double fallback = 0.0) {
    for (const auto& [k, v] : p.options)
        if (k == key) return std::string(key) == "SLOPE" ? decimal(v, text, "slope [%]") / 100.0 : millimetres(v, text, key);
    return fallback;
}

bool flag(const Parametric& p, const char* key) {
    for (const auto& [k, v] : p.options)
        if (k == key) return true;
    return false;
}

ShapeGeometry parametric_shape(const Parametric& p, std::string_view text) {
    const auto& d = p.dimensions;
    if (p.prefix == "I" || p.prefix == "U") {
        expect_dimensions(p, 4, "h x b x tw x tf", text);
        allow_options(p, {"R", "TOE", "SLOPE"}, text);
        const double r = option(p, "R", text), toe = option(p, "TOE", text), slope = option(p, "SLOPE", text);
        if (p.prefix == "I") return IShape{d[0], d[1], d[2], d[3], r, slope, toe};
        return ChannelShape{d[0], d[1], d[2], d[3], r, slope, toe};
    }
    if (p.prefix == "L") {
        expect_dimensions(p, 3, "h x b x t", text);
        allow_options(p, {"R", "TOE"}, text);
        return AngleShape{d[0], d[1], d[2], option(p, "R", text), option(p, "TOE", text)};
    }
    if (p.prefix == "T") {
        expect_dimensions(p, 4, "h x b x tw x tf", text);
        allow_options(p, {"R"}, text);
        return TeeShape{d[0], d[1], d[2], d[3], option(p, "R", text)};
    }
    if (p.prefix == "BOX") {
        expect_dimensions(p, 3, "h x b x t", text);
        allow_options(p, {"HOT", "COLD", "RO", "RI"}, text);
        const bool cold = flag(p, "COLD");
        if (cold && flag(p, "HOT")) fail(text, "give hot or cold, not both");
        RectangularHollowShape s = cold ? cold_formed_hollow(d[0], d[1], d[2]) : hot_finished_hollow(d[0], d[1], d[2]);
        if (flag(p, "RO") || flag(p, "RI")) {
            if (flag(p, "HOT") || cold) fail(text, "give the radii (ro, ri) or hot/cold, not both");
            s.outer_radius = option(p, "RO", text);
            s.inner_radius = option(p, "RI", text);
        }
        return s;
    }
    allow_options(p, {}, text);
    if (p.prefix == "TUBE") {
        expect_dimensions(p, 2, "D x t", text);
        return CircularHollowShape{d[0], d[1]};
    }
    if (p.prefix == "ROUND") {
        expect_dimensions(p, 1, "D", text);
        return RoundBarShape{d[0]};
    }
    expect_dimensions(p, 2, "b x t", text);
    return FlatBarShape{d[0], d[1]};
}

std::string suggestion_text(const std::vector<std::string>& names) {
    if (names.empty()) return "";
    std::string out = "; did you mean ";
    for (std::size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return out + "?";
}

}  // namespace

ShapeGeometry parse_shape_designation(std::string_view text, const ShapeCatalogue& catalogue) {
    if (const CatalogueShape* row = catalogue.find(text)) return row->geometry;
    const Parametric p = split(text);
    if (p.prefix.empty()) {
        std::string hint = suggestion_text(catalogue.suggestions(text));
        if (hint.empty()) hint = " (catalogue names such as \"IPE 300\", or parametric shapes such as \"I 300x150x7.1x10.7 r15\"; see --list-shapes)";
        fail(text, "not a known designation" + hint);
    }
    try {
        const ShapeGeometry shape = parametric_shape(p, text);
        shape_outline(shape);  // checks every dimension
        return shape;
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.rfind("shape \"", 0) == 0) throw;
        fail(text, message);
    }
}

Section shape_section(std::string_view designation, const Material& material, const ShapeOptions& options,
                      const ShapeCatalogue& catalogue) {
    try {
        return shape_section(parse_shape_designation(designation, catalogue), material, options);
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.rfind("shape \"", 0) == 0) throw;
        fail(designation, message);  // e.g. a radius that does not fit, found while discretising
    }
}

}  // namespace plascap
