// Materials: plascap.Material and the built-in catalogue of sourced grades (docs/materials.md).
#include <pybind11/stl.h>

#include <sstream>

#include "bindings.hpp"
#include "plascap/input_error.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/materials/shear_criterion.hpp"

namespace plascap::python {

Material resolve_material(const std::optional<MaterialArgument>& material, std::optional<double> fy, const std::string& what) {
    if (material && fy) throw InputError(what + ": give fy or material, not both");
    if (fy) {
        const Material given{"", *fy};
        validate_material(given, what);
        return given;
    }
    if (!material) throw InputError(what + ": needs material (a catalogue name, e.g. \"S355\", or a Material) or fy [Pa]");
    if (const auto* name = std::get_if<std::string>(&*material)) return MaterialCatalogue::built_in().get(*name, what);
    return std::get<Material>(*material);
}

namespace {

std::string material_repr(const Material& m) {
    std::ostringstream out;
    out << "Material(" << (m.name.empty() ? "" : "'" + m.name + "', ") << "fy=" << m.fy;
    if (m.fc) out << ", fc=" << *m.fc;
    if (m.E) out << ", E=" << *m.E;
    out << ")";
    return out.str();
}

Material make_material(double fy, const std::string& name, std::optional<double> fc, std::optional<double> E,
                       std::optional<double> nu, std::optional<double> density, std::optional<std::string> shear) {
    Material m{name, fy};
    m.fc = fc, m.E = E, m.nu = nu, m.density = density;
    if (shear) m.shear = parse_shear_criterion(*shear);
    validate_material(m, "Material");  // the ranges a section file's material must keep
    return m;
}

}  // namespace

void bind_materials(py::module_& m) {
    py::class_<Material>(m, "Material", "A material: strengths in Pa, moduli in Pa, density in kg/m^3.")
        .def(py::init(&make_material), py::arg("fy"), py::kw_only(), py::arg("name") = "", py::arg("fc") = py::none(),
             py::arg("E") = py::none(), py::arg("nu") = py::none(), py::arg("density") = py::none(),
             py::arg("shear") = py::none(),
             "A material of yield stress fy [Pa] (tension); fc [Pa], the compression strength, defaults to fy; "
             "E [Pa], nu [-], density [kg/m^3]; shear: 'tresca' (tau_y = fy/2) or 'von-mises' (fy/sqrt(3)).")
        .def_readonly("name", &Material::name)
        .def_readonly("fy", &Material::fy, "yield stress in tension [Pa]")
        .def_readonly("fc", &Material::fc, "strength in compression [Pa], None: fy")
        .def_readonly("E", &Material::E, "Young's modulus [Pa]")
        .def_readonly("nu", &Material::nu, "Poisson's ratio [-]")
        .def_property_readonly("G", &Material::shear_modulus, "shear modulus [Pa]: given, or E/(2(1 + nu))")
        .def_readonly("density", &Material::density, "[kg/m^3]")
        .def_readonly("ultimate_strain", &Material::ultimate_strain, "plastic strain at fracture [-]")
        .def_readonly("description", &Material::description)
        .def_readonly("sources", &Material::sources, "property name -> where its number comes from")
        .def("__repr__", &material_repr);

    m.def("materials", [] { return MaterialCatalogue::built_in().materials(); },
          "The built-in catalogue (docs/materials.md): every grade with its values and their sources.");
    m.def("material", [](const std::string& name) { return MaterialCatalogue::built_in().get(name, "material"); },
          py::arg("name"), "A catalogue grade by name, e.g. 'S355'; unknown names raise InputError with suggestions.");
}

}  // namespace plascap::python
