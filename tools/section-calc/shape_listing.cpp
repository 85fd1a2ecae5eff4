#include "shape_listing.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <variant>

#include "plascap/input_error.hpp"
#include "text_columns.hpp"

namespace plascap::tools {
namespace {

using nlohmann::ordered_json;

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

const ShapeFamily& family_named(const ShapeCatalogue& catalogue, const std::string& name) {
    if (const ShapeFamily* f = catalogue.family(name)) return *f;
    std::string known;
    for (const ShapeFamily& f : catalogue.families()) known += (known.empty() ? "" : ", ") + f.name;
    throw InputError("unknown shape family \"" + name + "\" (known: " + known + ", or all)");
}

// "IPE", "IPE,HEA,HEB" or "all" (also "" for all).
std::vector<const ShapeFamily*> families_of(const ShapeCatalogue& catalogue, const std::string& names) {
    std::vector<const ShapeFamily*> out;
    if (names.empty() || names == "all" || names == "ALL") {
        for (const ShapeFamily& f : catalogue.families()) out.push_back(&f);
        return out;
    }
    std::size_t start = 0;
    while (start <= names.size()) {
        const std::size_t comma = std::min(names.find(',', start), names.size());
        out.push_back(&family_named(catalogue, names.substr(start, comma - start)));
        start = comma + 1;
    }
    return out;
}

ordered_json geometry_json(const ShapeGeometry& shape) {
    return std::visit(
        Overloaded{[](const IShape& s) { return ordered_json{{"kind", "I"}, {"h", s.h}, {"b", s.b}, {"tw", s.tw}, {"tf", s.tf}, {"r", s.r}}; },
                   [](const ChannelShape& s) { return ordered_json{{"kind", "channel"}, {"h", s.h}, {"b", s.b}, {"tw", s.tw}, {"tf", s.tf}, {"r", s.r}}; },
                   [](const AngleShape& s) { return ordered_json{{"kind", "angle"}, {"h", s.h}, {"b", s.b}, {"t", s.t}, {"r", s.r}, {"toe_radius", s.toe_radius}}; },
                   [](const TeeShape& s) { return ordered_json{{"kind", "tee"}, {"h", s.h}, {"b", s.b}, {"tw", s.tw}, {"tf", s.tf}, {"r", s.r}}; },
                   [](const RectangularHollowShape& s) {
                       return ordered_json{{"kind", "rectangular_hollow"}, {"h", s.h}, {"b", s.b}, {"t", s.t},
                                           {"outer_radius", s.outer_radius}, {"inner_radius", s.inner_radius}};
                   },
                   [](const CircularHollowShape& s) { return ordered_json{{"kind", "circular_hollow"}, {"D", s.D}, {"t", s.t}}; },
                   [](const RoundBarShape& s) { return ordered_json{{"kind", "round_bar"}, {"D", s.D}}; },
                   [](const FlatBarShape& s) { return ordered_json{{"kind", "flat_bar"}, {"b", s.b}, {"t", s.t}}; }},
        shape);
}

std::string g5(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.5g", value);
    return text;
}

}  // namespace

std::string shape_list(const ShapeCatalogue& catalogue, const std::string& family) {
    std::ostringstream out;
    for (const ShapeFamily* f : families_of(catalogue, family)) {
        out << f->name << " — " << f->description << " (" << f->standard << "), " << f->shapes.size() << " shapes:\n ";
        std::size_t column = 1;
        for (const CatalogueShape& s : f->shapes) {
            if (column + s.designation.size() + 2 > 100) {
                out << "\n ";
                column = 1;
            }
            out << " " << s.designation;
            column += s.designation.size() + 1;
        }
        out << "\n\n";
    }
    out << "Parametric shapes (dimensions in mm): I hxbxtwxtf [rR] [toeR] [slopeS%], U hxbxtwxtf [...], L hxbxt [rR] [toeR],\n"
           "T hxbxtwxtf [rR], BOX hxbxt [hot|cold|roR riR], TUBE Dxt, ROUND D, FLAT bxt — e.g. \"I 300x150x7.1x10.7 r15\".\n"
           "Axes: depth h along z, width b along x: Mx is the strong-axis (EN y–y) moment. Sources: --list-shapes --json.\n";
    return out.str();
}

std::string shape_list_json(const ShapeCatalogue& catalogue, const std::string& family) {
    ordered_json families = ordered_json::array();
    for (const ShapeFamily* f : families_of(catalogue, family)) {
        ordered_json shapes = ordered_json::array();
        for (const CatalogueShape& s : f->shapes) {
            ordered_json published = ordered_json::object();
            for (const auto& [key, value] : s.published) published[key] = value.value;
            shapes.push_back({{"designation", s.designation}, {"geometry", geometry_json(s.geometry)}, {"published", published}});
        }
        families.push_back({{"name", f->name}, {"kind", f->kind}, {"standard", f->standard}, {"description", f->description},
                            {"source", f->source}, {"shapes", shapes}});
    }
    return ordered_json{{"units", "SI (m, m², m⁴, m³, m⁶)"}, {"families", families}}.dump(2) + "\n";
}

std::vector<const CatalogueShape*> shapes_of(const ShapeCatalogue& catalogue, const std::string& family) {
    std::vector<const CatalogueShape*> out;
    for (const ShapeFamily* f : families_of(catalogue, family))
        for (const CatalogueShape& s : f->shapes) out.push_back(&s);
    return out;
}

std::string shape_table_text(const std::vector<ShapeTableRow>& rows, const Material& material, TableFormat format,
                             double seconds) {
    struct Column {
        const char* name;
        const char* unit;
        double (*value)(const ShapeTableRow&);
    };
    static const Column columns[] = {
        {"A", "m²", [](const ShapeTableRow& r) { return r.elastic.area; }},
        {"Ixx", "m⁴", [](const ShapeTableRow& r) { return r.elastic.Ixx; }},
        {"Izz", "m⁴", [](const ShapeTableRow& r) { return r.elastic.Izz; }},
        {"Wel_x", "m³", [](const ShapeTableRow& r) { return r.elastic.Wx; }},
        {"Wel_z", "m³", [](const ShapeTableRow& r) { return r.elastic.Wz; }},
        {"Wpl_x", "m³", [](const ShapeTableRow& r) { return r.Wpl_x; }},
        {"Wpl_z", "m³", [](const ShapeTableRow& r) { return r.Wpl_z; }},
        {"J", "m⁴", [](const ShapeTableRow& r) { return r.J ? r.J->J : 0.0; }},
        {"T_p", "N·m", [](const ShapeTableRow& r) { return r.T_p ? r.T_p->T : 0.0; }},
        {"N", "N", [](const ShapeTableRow& r) { return *r.capacities.N; }},
        {"Qx", "N", [](const ShapeTableRow& r) { return *r.capacities.Qx; }},
        {"Qz", "N", [](const ShapeTableRow& r) { return *r.capacities.Qz; }},
        {"Mx", "N·m", [](const ShapeTableRow& r) { return *r.capacities.Mx; }},
        {"Mz", "N·m", [](const ShapeTableRow& r) { return *r.capacities.Mz; }},
        {"My", "N·m", [](const ShapeTableRow& r) { return *r.capacities.My; }},
    };
    const bool torsion = !rows.empty() && rows.front().J.has_value();
    const auto shown = [torsion](const Column& c) { return torsion || (std::string(c.name) != "J" && std::string(c.name) != "T_p"); };
    std::ostringstream out;
    if (format == TableFormat::Json) {
        ordered_json list = ordered_json::array();
        for (const ShapeTableRow& r : rows) {
            ordered_json row{{"designation", r.shape->designation}, {"family", r.shape->family}};
            for (const Column& c : columns)
                if (shown(c)) row[c.name] = c.value(r);
            if (torsion) row["J_error"] = r.J->error, row["T_p_error"] = r.T_p->error;
            row["vertices"] = r.vertices;
            list.push_back(row);
        }
        out << ordered_json{{"material", material.name.empty() ? "fy = " + g5(material.fy) + " Pa" : material.name},
                            {"fy", material.fy}, {"units", "SI"}, {"seconds", seconds}, {"rows", list}}.dump(2) << "\n";
        return out.str();
    }
    if (format == TableFormat::Csv) {
        out << "designation";
        for (const Column& c : columns)
            if (shown(c)) out << "," << c.name;
        out << (torsion ? ",J_error,T_p_error" : "") << "\n";
        for (const ShapeTableRow& r : rows) {
            out << r.shape->designation;
            for (const Column& c : columns)
                if (shown(c)) out << "," << g5(c.value(r));
            if (torsion) out << "," << g5(r.J->error) << "," << g5(r.T_p->error);
            out << "\n";
        }
        return out.str();
    }
    out << "material " << (material.name.empty() ? "fy = " + g5(material.fy) + " Pa" : material.name) << ", exact route"
        << (torsion ? "; J by FEM to 1e-4, T_p by the sand heap to 1e-3" : "") << "; " << rows.size() << " shapes in "
        << g5(seconds) << " s\n";
    out << padded("designation", 16);
    for (const Column& c : columns)
        if (shown(c)) out << padded(std::string(c.name) + " " + c.unit, 12);
    out << "\n";
    for (const ShapeTableRow& r : rows) {
        out << padded(r.shape->designation, 16);
        for (const Column& c : columns)
            if (shown(c)) out << padded(g5(c.value(r)), 12);
        out << "\n";
    }
    return out.str();
}

}  // namespace plascap::tools
