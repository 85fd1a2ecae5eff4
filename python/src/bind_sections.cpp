// Sections: plascap.Section from a standard shape by name, a rectangle, a polygon with holes, or a
// section file (docs/section-format.md), validated once when made.
#include <pybind11/stl.h>

#include <sstream>

#include "bindings.hpp"
#include "plascap/input_error.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/materials/shear_criterion.hpp"
#include "plascap/sections/section_json.hpp"
#include "plascap/sections/shape_catalogue.hpp"
#include "plascap/sections/shape_designation.hpp"
#include "plascap/sections/shapes.hpp"

namespace plascap::python {

PySection::PySection(Section given, std::string how) : section(std::move(given)), valid(validate_section(section)), origin(std::move(how)) {}

namespace {

using Vertex = std::pair<double, double>;  // (x, z) [m]

Ring ring_of(const std::vector<Vertex>& vertices) {
    Ring ring;
    ring.reserve(vertices.size());
    for (const auto& [x, z] : vertices) ring.push_back({x, z});
    return ring;
}

void apply_options(Section& s, const std::optional<std::string>& shear, const std::optional<Vertex>& reference) {
    if (shear) s.shear = parse_shear_criterion(*shear);
    if (reference) s.reference = Point{reference->first, reference->second};
}

PySection shape(const std::string& designation, const std::optional<MaterialArgument>& material, std::optional<double> fy,
                std::optional<double> arc_tolerance) {
    ShapeOptions options;
    if (arc_tolerance) options.area_tolerance = *arc_tolerance;
    validate_shape_options(options);
    return PySection(shape_section(designation, resolve_material(material, fy, "Section.shape"), options),
                     "Section.shape('" + designation + "')");
}

PySection rectangle(double b, double h, const std::optional<MaterialArgument>& material, std::optional<double> fy,
                    const std::optional<std::string>& shear) {
    const Material mat = resolve_material(material, fy, "Section.rectangle");
    Section s = rectangle_section(b, h, mat.fy > 0.0 ? mat.fy : 1.0);
    s.parts[0].material = mat;
    apply_options(s, shear, std::nullopt);
    std::ostringstream how;
    how << "Section.rectangle(" << b << ", " << h << ")";
    return PySection(std::move(s), how.str());
}

PySection polygon(const std::vector<Vertex>& outer, const std::vector<std::vector<Vertex>>& holes,
                  const std::optional<MaterialArgument>& material, std::optional<double> fy,
                  const std::optional<std::string>& shear, const std::optional<Vertex>& reference) {
    Section s;
    Part part;
    part.outer = ring_of(outer);
    for (const auto& hole : holes) part.holes.push_back(ring_of(hole));
    part.material = resolve_material(material, fy, "Section.polygon");
    s.parts.push_back(std::move(part));
    apply_options(s, shear, reference);
    return PySection(std::move(s), "Section.polygon(" + std::to_string(outer.size()) + " vertices)");
}

PySection from_file(const std::string& path) {
    Section s = read_section_file(path);
    try {
        return PySection(std::move(s), "Section.from_file('" + path + "')");
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());  // as section-calc names the file
    }
}

std::string section_repr(const PySection& s) {
    std::ostringstream out;
    out << "<plascap.Section " << s.origin << ": " << s.valid.parts().size() << " part(s), " << s.valid.vertex_count()
        << " vertices, shear " << to_string(s.valid.shear()) << ">";
    return out.str();
}

std::vector<std::string> shapes(const std::optional<std::string>& family) {
    const ShapeCatalogue& catalogue = ShapeCatalogue::built_in();
    std::vector<std::string> names;
    for (const ShapeFamily& f : catalogue.families()) {
        if (family && catalogue.family(*family) != &f) continue;
        for (const CatalogueShape& shape : f.shapes) names.push_back(shape.designation);
    }
    if (family && names.empty()) throw InputError("shapes: no family \"" + *family + "\" in the catalogue (see shape_families())");
    return names;
}

}  // namespace

void bind_sections(py::module_& m) {
    py::class_<PySection>(m, "Section",
                          "A cross section: parts (polygons with holes, each of one material, with bars), coordinates "
                          "x (width) and z (depth) in m. Make one with Section.shape, .rectangle, .polygon, .from_json "
                          "or .from_file; bad geometry raises InputError naming the part and vertex.")
        .def_static("shape", &shape, py::arg("designation"), py::kw_only(), py::arg("material") = py::none(),
                    py::arg("fy") = py::none(), py::arg("arc_tolerance") = py::none(),
                    "A standard shape by name, e.g. 'IPE 300', 'HE 200 B', 'CHS 168.3x8', or parametric "
                    "'I 300x150x7.1x10.7 r15' (docs/shapes.md); depth h along z, so Mx is the strong-axis moment. "
                    "material: a catalogue name or Material; or fy [Pa]. arc_tolerance: the area the arcs' chords may "
                    "miss, relative (default 1e-6).")
        .def_static("rectangle", &rectangle, py::arg("b"), py::arg("h"), py::kw_only(), py::arg("material") = py::none(),
                    py::arg("fy") = py::none(), py::arg("shear") = py::none(),
                    "A b x h rectangle [m] centred on the origin, b along x and h along z.")
        .def_static("polygon", &polygon, py::arg("outer"), py::arg("holes") = std::vector<std::vector<Vertex>>{},
                    py::kw_only(), py::arg("material") = py::none(), py::arg("fy") = py::none(),
                    py::arg("shear") = py::none(), py::arg("reference") = py::none(),
                    "One part: the outer ring and any holes as [(x, z), ...] in m (either winding); shear 'tresca' "
                    "or 'von-mises'; reference (x, z): the joint point for My (default the centroid).")
        .def_static("from_json", [](const std::string& text) { return PySection(parse_section_json(text), "Section.from_json"); },
                    py::arg("text"), "A section in plascap's JSON format (docs/section-format.md).")
        .def_static("from_file", &from_file, py::arg("path"), "A section file (docs/section-format.md).")
        .def_property_readonly("parts", [](const PySection& s) { return s.valid.parts().size(); }, "number of parts")
        .def_property_readonly("vertices", [](const PySection& s) { return s.valid.vertex_count(); }, "number of vertices")
        .def_property_readonly("shear", [](const PySection& s) { return to_string(s.valid.shear()); },
                               "shear criterion: 'tresca' or 'von-mises'")
        .def("__repr__", &section_repr);

    m.def("shapes", &shapes, py::arg("family") = py::none(),
          "Designations in the shape catalogue, of one family (e.g. 'IPE') or all.");
    m.def("shape_families", [] {
        std::vector<std::string> names;
        for (const ShapeFamily& f : ShapeCatalogue::built_in().families()) names.push_back(f.name);
        return names;
    }, "The catalogue's shape families, e.g. IPE, HEA, HEB, CHS.");
}

}  // namespace plascap::python
