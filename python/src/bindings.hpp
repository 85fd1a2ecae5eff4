#pragma once
// The plascap Python module's parts, one per concept (docs/python.md).
#include <pybind11/pybind11.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <variant>

#include "plascap/materials/material.hpp"
#include "plascap/sections/geometry.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap::python {

namespace py = pybind11;

// A section as Python holds it: the geometry and materials as given, and their validated form
// (validation happens once, when the section is made, and names the part and vertex at fault).
struct PySection {
    explicit PySection(Section given, std::string origin);
    Section section;
    ValidSection valid;
    std::string origin;  // how it was made, for __repr__
};

// A material argument: a catalogue name or a Material.
using MaterialArgument = std::variant<std::string, Material>;

// "Type(name=value, ...)" with the values as a stream prints them (6 significant digits), for __repr__.
std::string repr(const std::string& type, std::initializer_list<std::pair<const char*, double>> fields);

// The material of `material` or `fy` (exactly one of them); `what` names the call in messages.
Material resolve_material(const std::optional<MaterialArgument>& material, std::optional<double> fy, const std::string& what);

void bind_errors(py::module_& m);
void bind_materials(py::module_& m);
void bind_sections(py::module_& m);
void bind_capacities(py::module_& m);
void bind_properties(py::module_& m);
void bind_yield(py::module_& m);
void bind_scenes(py::module_& m);

}  // namespace plascap::python
