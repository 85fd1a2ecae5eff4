// The exact coupled yield condition of a section (docs/yield-surface.md): the N–Mx–Mz surface
// reduced by shear and torsion, U = √(u_NM² + η²); utilisation of a load, and cuts through the
// surface (N–Mx, N–Mz, Mx–Mz) for interaction diagrams.
#include <pybind11/stl.h>

#include <sstream>

#include "bindings.hpp"
#include "plascap/input_error.hpp"
#include "plascap/sections/interaction_curves.hpp"
#include "plascap/sections/section_yield.hpp"
#include "plascap/sections/yield_surface.hpp"

namespace plascap::python {
namespace {

struct PyYieldCondition {
    SectionYield condition;
    std::string torsion;
};

SectionLoads loads(double N, double Qx, double Qz, double Mx, double Mz, double T) { return {N, Qx, Qz, Mx, Mz, T}; }

py::dict evaluate(const PyYieldCondition& y, double N, double Qx, double Qz, double Mx, double Mz, double T) {
    const SectionYieldState s = y.condition.evaluate(loads(N, Qx, Qz, Mx, Mz, T));
    py::dict gradient;
    gradient["N"] = s.gradient.N, gradient["Qx"] = s.gradient.Qx, gradient["Qz"] = s.gradient.Qz;
    gradient["Mx"] = s.gradient.Mx, gradient["Mz"] = s.gradient.Mz, gradient["T"] = s.gradient.T;
    py::dict d;
    d["utilisation"] = s.utilisation, d["nm_utilisation"] = s.nm_utilisation;
    d["shear_torsion_share"] = s.shear_torsion_share, d["gradient"] = gradient;
    return d;
}

constexpr std::size_t kMinSamples = 8, kMaxSamples = 100000;  // as section-calc --samples

std::vector<std::pair<double, double>> curve(const PySection& s, const std::string& cut, std::size_t samples, double N) {
    if (samples < kMinSamples || samples > kMaxSamples)
        throw InputError("samples must be 8 to 100000 (got " + std::to_string(samples) + ")");
    if (N != 0.0 && cut != "Mx-Mz") throw InputError("N goes with the 'Mx-Mz' cut");
    const YieldSurface surface(s.valid);
    std::vector<std::pair<double, double>> points;
    if (cut == "N-Mx") {
        for (const SectionResultant& p : n_mx_curve(surface, samples)) points.emplace_back(p.N, p.Mx);
    } else if (cut == "N-Mz") {
        for (const SectionResultant& p : n_mz_curve(surface, samples)) points.emplace_back(p.N, p.Mz);
    } else if (cut == "Mx-Mz") {
        for (const SectionResultant& p : mx_mz_curve(surface, N, samples)) points.emplace_back(p.Mx, p.Mz);
    } else {
        throw InputError("cut: 'N-Mx', 'N-Mz' or 'Mx-Mz' (got '" + cut + "')");
    }
    return points;
}

}  // namespace

void bind_yield(py::module_& m) {
    py::class_<PyYieldCondition>(m, "YieldCondition",
                                 "A section's exact yield condition under all six joint loads [N, N*m]: U = 1 on it.")
        .def("utilisation",
             [](const PyYieldCondition& y, double N, double Qx, double Qz, double Mx, double Mz, double T) {
                 return y.condition.utilisation(loads(N, Qx, Qz, Mx, Mz, T));
             },
             py::kw_only(), py::arg("N") = 0.0, py::arg("Qx") = 0.0, py::arg("Qz") = 0.0, py::arg("Mx") = 0.0,
             py::arg("Mz") = 0.0, py::arg("T") = 0.0,
             "U of a load: N tension positive, Mx and Mz in the capacities' senses, T the torque, about the joint "
             "point; U = sqrt(u_NM^2 + eta^2), 1 on the surface, inf for a load never carried.")
        .def("evaluate", &evaluate, py::kw_only(), py::arg("N") = 0.0, py::arg("Qx") = 0.0, py::arg("Qz") = 0.0,
             py::arg("Mx") = 0.0, py::arg("Mz") = 0.0, py::arg("T") = 0.0,
             "{'utilisation', 'nm_utilisation', 'shear_torsion_share', 'gradient': dU/dload}")
        .def_readonly("torsion", &PyYieldCondition::torsion)
        .def("__repr__", [](const PyYieldCondition& y) { return "<plascap.YieldCondition, torsion " + y.torsion + ">"; });

    py::class_<PySection> section = py::reinterpret_borrow<py::class_<PySection>>(m.attr("Section"));
    section
        .def("yield_condition",
             [](const PySection& s, const std::string& torsion) {
                 const TorsionCapacity t = torsion_capacity_from_name(torsion, "torsion");
                 return PyYieldCondition{section_yield(s.valid, t), torsion};
             },
             py::kw_only(), py::arg("torsion") = "fully-plastic",
             "The exact coupled yield condition; torsion capacity 'fully-plastic' (T_p, the sand heap) or 'paper' "
             "(eq. 2.14).")
        .def("_interaction_curve", &curve, py::arg("cut"), py::arg("samples"), py::arg("N"));
}

}  // namespace plascap::python
