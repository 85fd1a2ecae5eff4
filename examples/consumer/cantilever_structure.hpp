#pragma once
// The structure of structure_main.cpp (Bullet) and ode_structure_main.cpp (ODE): a 2 m IPE 200 S355
// cantilever A–C, fixed at A, in four segments. Rigid-plastic theory puts its collapse under a tip
// load at P_c = M_p/L (a hinge at the support; e.g. Neal, "The Plastic Methods of Structural
// Analysis", ch. 2), M_p = W_pl·fy = 220.6 cm³ × 355 MPa = 78.3 kN·m (W_pl from the IPE tables).
#include <memory>

#include "plascap/adapters/structure_model.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/shape_designation.hpp"

constexpr double kCantileverLength = 2.0, kCantileverMp = 220.6e-6 * 355e6;  // [m], [N·m]

// The cantilever as members and nodes, built into segments and joints.
inline plascap::StructureModel cantilever_model() {
    const double L = kCantileverLength;
    plascap::Structure cantilever;
    cantilever.nodes = {{"A", {0, 0, 0}}, {"C", {L, 0, 0}}};
    plascap::StructureMember m;
    m.name = "AC", m.from = "A", m.to = "C", m.z_axis = plascap::Vec3{0, 1, 0}, m.segments = 4;
    m.section = std::make_shared<const plascap::ValidSection>(plascap::validate_section(
        plascap::shape_section("IPE 200", plascap::MaterialCatalogue::built_in().get("S355", "example"))));
    cantilever.members.push_back(m);
    cantilever.supports["A"] = plascap::StructureSupport::fixed();
    const plascap::StructureModel model = plascap::build_structure(cantilever);  // 4 segments, 3 joints + the support
    return model;
}
