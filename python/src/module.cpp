// PYBIND11_MODULE: the extension plascap._plascap, re-exported by plascap/__init__.py.
#include "bindings.hpp"

PYBIND11_MODULE(_plascap, m) {
    m.doc() = "Plastic capacities of structural cross sections (plascap). SI units throughout: m, N, N*m, Pa.";
    m.attr("__version__") = PLASCAP_VERSION;
    plascap::python::bind_errors(m);
    plascap::python::bind_materials(m);
    plascap::python::bind_sections(m);
    plascap::python::bind_capacities(m);
    plascap::python::bind_properties(m);
    plascap::python::bind_yield(m);
    plascap::python::bind_scenes(m);
}
