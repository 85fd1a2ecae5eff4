// Capacities: Section.capacities() by either route — exact closed forms over the polygons, or the
// CGAL mesh with GSL cubature and its error estimates (docs/exact-route.md, docs/cubature-route.md).
// N, Qx, Qz, Mx, Mz, My are the paper's eqs. 2.10–2.14 ("Handling of plasticity in physics engine").
#include <pybind11/stl.h>

#include <sstream>

#include "bindings.hpp"
#include "plascap/input_error.hpp"
#include "plascap/materials/shear_criterion.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/cubature.hpp"

namespace plascap::python {
namespace {

struct PyCapacities {
    Capacities values;
    std::array<std::optional<double>, kCapacityCount> errors{};  // cubature only
    std::string method;
    std::size_t triangles = 0;
};

PyCapacities capacities(const PySection& s, const std::string& method, const std::optional<std::string>& only,
                        std::optional<double> tolerance, std::optional<int> order, std::optional<double> max_area) {
    const CapacitySet wanted = only ? CapacitySet::parse(*only) : CapacitySet::all();
    PyCapacities r;
    r.method = method;
    if (method == "exact") {
        if (tolerance || order || max_area) throw InputError("tolerance, order and max_area go with method='cubature'");
        r.values = compute_capacities(s.valid, wanted);
        return r;
    }
    if (method != "cubature") throw InputError("method: 'exact' or 'cubature' (got '" + method + "')");
    if (tolerance && order) throw InputError("give tolerance (adaptive rule) or order (fixed rule), not both");
    CubatureOptions options;
    if (tolerance) options.tolerance = *tolerance;
    if (order) options.rule = CubatureRule::Fixed, options.order = *order;
    if (max_area) options.max_area = *max_area;
    validate_cubature_options(options);
    CubatureResult c = cubature_capacities(s.valid, wanted, options);
    r.values = c.capacities;
    r.errors = c.error;
    r.triangles = c.triangles;
    return r;
}

py::dict as_dict(const PyCapacities& c) {
    py::dict d;
    for (Capacity k : kAllCapacities)
        if (const auto v = c.values.get(k)) d[py::str(to_string(k))] = *v;
    return d;
}

py::dict errors(const PyCapacities& c) {
    py::dict d;
    for (Capacity k : kAllCapacities)
        if (const auto e = c.errors[static_cast<std::size_t>(k)]) d[py::str(to_string(k))] = *e;
    return d;
}

std::string capacities_repr(const PyCapacities& c) {
    std::ostringstream out;
    out << "Capacities(";
    const char* sep = "";
    for (Capacity k : kAllCapacities) {
        if (const auto v = c.values.get(k)) {
            out << sep << to_string(k) << "=" << *v;
            sep = ", ";
        }
    }
    out << ", method='" << c.method << "')";
    return out.str();
}

std::optional<std::pair<double, double>> point(const std::optional<Point>& p) {
    if (!p) return std::nullopt;
    return std::pair{p->x, p->z};
}

}  // namespace

void bind_capacities(py::module_& m) {
    auto cls = py::class_<PyCapacities>(m, "Capacities",
                                        "Plastic capacities [N, N*m]: None for those not asked. N, Mx, Mz resist "
                                        "tension and the positive senses; N_neg, Mx_neg, Mz_neg the opposite ones.");
    for (Capacity k : kAllCapacities) {
        cls.def_property_readonly(to_string(k).c_str(), [k](const PyCapacities& c) { return c.values.get(k); });
    }
    cls.def_property_readonly("area", [](const PyCapacities& c) { return c.values.area; }, "[m^2]")
        .def_property_readonly("centroid", [](const PyCapacities& c) { return std::pair{c.values.centroid.x, c.values.centroid.z}; },
                               "area centroid (x, z) [m]")
        .def_property_readonly("z_pna", [](const PyCapacities& c) { return c.values.z_pna; }, "plastic neutral axis of Mx, z [m]")
        .def_property_readonly("x_pna", [](const PyCapacities& c) { return c.values.x_pna; }, "plastic neutral axis of Mz, x [m]")
        .def_property_readonly("reference", [](const PyCapacities& c) { return point(c.values.reference); },
                               "the joint point of My (x, z) [m]")
        .def_property_readonly("shear", [](const PyCapacities& c) { return to_string(c.values.shear); })
        .def_readonly("method", &PyCapacities::method)
        .def_property_readonly("errors", &errors, "cubature: estimated absolute error of each capacity [N, N*m]; exact: {}")
        .def_readonly("triangles", &PyCapacities::triangles, "cubature: triangles integrated")
        .def("as_dict", &as_dict, "{name: value} of the capacities computed")
        .def("__repr__", &capacities_repr);

    py::class_<PySection> section = py::reinterpret_borrow<py::class_<PySection>>(m.attr("Section"));
    section.def("capacities", &capacities, py::kw_only(), py::arg("method") = "exact", py::arg("only") = py::none(),
                py::arg("tolerance") = py::none(), py::arg("order") = py::none(), py::arg("max_area") = py::none(),
                "The plastic capacities (paper eqs. 2.10-2.14). method 'exact' (closed forms) or 'cubature' (CGAL "
                "mesh + GSL: tolerance per triangle 1e-13..0.1, default 1e-10, or a fixed rule of order 1..100; "
                "max_area [m^2] bounds the triangles). only: e.g. 'N,My'.");
}

}  // namespace plascap::python
