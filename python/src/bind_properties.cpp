// Elastic properties (Ixx, Izz, moduli, EA, EI), Saint-Venant's J and the fully plastic torque T_p
// (Nadai's sand heap) of a section (docs/elastic-and-torsion.md).
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/torsion_constant.hpp"

namespace plascap::python {
namespace {

std::pair<double, double> xz(Point p) { return {p.x, p.z}; }

TorsionOptions torsion_options(double relative_tolerance) {
    TorsionOptions o;
    o.relative_tolerance = relative_tolerance;
    return o;
}

}  // namespace

void bind_properties(py::module_& m) {
    py::class_<ElasticProperties>(m, "ElasticProperties", "Elastic section properties about the area centroid.")
        .def_readonly("area", &ElasticProperties::area, "[m^2]")
        .def_property_readonly("centroid", [](const ElasticProperties& e) { return xz(e.centroid); }, "(x, z) [m]")
        .def_readonly("Ixx", &ElasticProperties::Ixx, "second moment about x [m^4]")
        .def_readonly("Izz", &ElasticProperties::Izz, "second moment about z [m^4]")
        .def_readonly("Ixz", &ElasticProperties::Ixz, "product moment [m^4]")
        .def_readonly("I1", &ElasticProperties::I1, "larger principal second moment [m^4]")
        .def_readonly("I2", &ElasticProperties::I2, "smaller principal second moment [m^4]")
        .def_readonly("principal_angle", &ElasticProperties::principal_angle, "axis of I1 from x towards z [rad]")
        .def_readonly("Wx", &ElasticProperties::Wx, "elastic modulus Ixx / max|z| [m^3]")
        .def_readonly("Wz", &ElasticProperties::Wz, "elastic modulus Izz / max|x| [m^3]")
        .def_readonly("rx", &ElasticProperties::rx, "radius of gyration sqrt(Ixx/A) [m]")
        .def_readonly("rz", &ElasticProperties::rz, "radius of gyration sqrt(Izz/A) [m]")
        .def_property_readonly("EA", [](const ElasticProperties& e) { return e.stiffness ? std::optional(e.stiffness->EA) : std::nullopt; },
                               "axial stiffness [N] (None unless every material gives E)")
        .def_property_readonly("EIxx", [](const ElasticProperties& e) { return e.stiffness ? std::optional(e.stiffness->EIxx) : std::nullopt; },
                               "bending stiffness about x [N*m^2]")
        .def_property_readonly("EIzz", [](const ElasticProperties& e) { return e.stiffness ? std::optional(e.stiffness->EIzz) : std::nullopt; },
                               "bending stiffness about z [N*m^2]")
        .def("__repr__", [](const ElasticProperties& e) {
            return repr("ElasticProperties", {{"area", e.area}, {"Ixx", e.Ixx}, {"Izz", e.Izz}, {"Wx", e.Wx}, {"Wz", e.Wz}});
        });

    py::class_<TorsionConstant>(m, "TorsionConstant", "Saint-Venant torsion constant by finite elements, with its error.")
        .def_readonly("J", &TorsionConstant::J, "[m^4]")
        .def_readonly("GJ", &TorsionConstant::GJ, "[N*m^2], when every part has the same G")
        .def_readonly("error", &TorsionConstant::error, "estimated absolute error of J [m^4]")
        .def_readonly("triangles", &TorsionConstant::triangles)
        .def_readonly("converged", &TorsionConstant::converged)
        .def("__repr__", [](const TorsionConstant& t) { return repr("TorsionConstant", {{"J", t.J}, {"error", t.error}}); });

    py::class_<PlasticTorsion>(m, "PlasticTorsion", "Fully plastic torque (Nadai's sand heap), with its error.")
        .def_readonly("T", &PlasticTorsion::T, "[N*m]")
        .def_readonly("error", &PlasticTorsion::error, "estimated absolute error [N*m]")
        .def_readonly("triangles", &PlasticTorsion::triangles)
        .def_readonly("converged", &PlasticTorsion::converged)
        .def("__repr__", [](const PlasticTorsion& t) { return repr("PlasticTorsion", {{"T", t.T}, {"error", t.error}}); });

    py::class_<PySection> section = py::reinterpret_borrow<py::class_<PySection>>(m.attr("Section"));
    section
        .def("elastic_properties", [](const PySection& s) { return elastic_properties(s.valid); },
             "Area, centroid, second moments, principal axes, moduli, radii of gyration; EA and EI when every "
             "material gives E.")
        .def("torsion_constant", [](const PySection& s, double tol) { return saint_venant_torsion(s.valid, torsion_options(tol)); },
             py::kw_only(), py::arg("relative_tolerance") = 1e-4, "Saint-Venant's J [m^4] to this relative error.")
        .def("plastic_torque", [](const PySection& s, double tol) { return plastic_torsion(s.valid, torsion_options(tol)); },
             py::kw_only(), py::arg("relative_tolerance") = 1e-4,
             "The fully plastic torque T_p [N*m] (sand heap, tau_y from the shear criterion).");
}

}  // namespace plascap::python
