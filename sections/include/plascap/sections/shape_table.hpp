#pragma once
// One row of properties per catalogue shape — the catalogue table of section-calc --table — with
// the rows computed in parallel on std::thread workers (the rows are independent and of similar
// cost, so an atomic row counter balances them; no task library is needed for that).
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "plascap/materials/material.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/shape_catalogue.hpp"
#include "plascap/sections/torsion_constant.hpp"

namespace plascap {

struct ShapeTableRow {
    const CatalogueShape* shape = nullptr;
    std::size_t vertices = 0;            // of the generated polygon
    ElasticProperties elastic;           // A, Ixx, Izz, Wx, Wz, ...
    Capacities capacities;               // all six, exact route
    double Wpl_x = 0.0, Wpl_z = 0.0;     // plastic moduli Mx/fy, Mz/fy [m³] (EN Wpl,y and Wpl,z)
    // With ShapeTableOptions::torsion: J by FEM and T_p by the sand heap, except for circular tubes
    // and bars, whose closed forms are exact for the true circle (error 0).
    std::optional<TorsionConstant> J;
    std::optional<PlasticTorsion> T_p;
};

struct ShapeTableOptions {
    ShapeOptions shape;
    bool torsion = true;                  // compute J (FEM) and T_p (sand heap)
    TorsionOptions J_options{1e-4};       // J to 1e-4 relative
    TorsionOptions T_p_options{1e-3};     // T_p to 1e-3 relative
    // J and T_p are computed on the shape drawn with coarser arcs: their cost grows with the vertex
    // count, and coarser arcs move them little against arcs drawn to 1e-6 (measured on IPE 300,
    // HEB 200, HEM 1000, UPE 200, L 60x40x5, SHS 200x200x10; docs/shapes.md): arcs to 1e-5 move J
    // by at most 5e-5, arcs to 1e-4 move T_p by at most 2.5e-4 — inside J's 1e-4 and T_p's 1e-3
    // together with the estimates.
    ShapeOptions J_shape{1e-5};
    ShapeOptions T_p_shape{1e-4};
    unsigned threads = 0;                 // 0: std::thread::hardware_concurrency()
    // Called after each finished row (from a worker thread, one call at a time).
    std::function<void(std::size_t done, std::size_t total)> progress;
};

ShapeTableRow shape_table_row(const CatalogueShape& shape, const Material& material, const ShapeTableOptions& options = {});

// The rows in the order given. The first InputError or other exception of any row is rethrown
// after every worker has stopped.
std::vector<ShapeTableRow> shape_table(const std::vector<const CatalogueShape*>& shapes, const Material& material,
                                       const ShapeTableOptions& options = {});

}  // namespace plascap
