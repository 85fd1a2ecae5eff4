#include "plascap/sections/shape_table.hpp"

#include <atomic>
#include <cmath>
#include <variant>
#include <exception>
#include <mutex>
#include <thread>

#include "plascap/sections/valid_section.hpp"

namespace plascap {
namespace {

// A tube (or a bar, d = 0) has both in closed form, exact for the true circle rather than for its
// polygon: J = π(D⁴ − d⁴)/32 (Timoshenko & Goodier, Theory of Elasticity, §104) and the sand heap's
// T_p = (2/3)·π·(R³ − r³)·τy (Nadai, Theory of Flow and Fracture of Solids, ch. 35: the heap is a
// cone frustum over the wall).
bool circular(const ShapeGeometry& g) {
    return std::holds_alternative<CircularHollowShape>(g) || std::holds_alternative<RoundBarShape>(g);
}

void circular_torsion(const ShapeGeometry& g, const Material& material, ShearCriterion shear, ShapeTableRow& row) {
    const double pi = std::acos(-1.0);
    const auto* tube = std::get_if<CircularHollowShape>(&g);
    const double D = tube ? tube->D : std::get<RoundBarShape>(g).D, d = tube ? tube->D - 2.0 * tube->t : 0.0;
    TorsionConstant J;
    J.J = pi * (std::pow(D, 4) - std::pow(d, 4)) / 32.0;
    J.converged = true;
    if (const std::optional<double> G = material.shear_modulus()) J.GJ = *G * J.J;
    row.J = J;
    PlasticTorsion T;
    T.T = 2.0 / 3.0 * pi * (std::pow(D / 2, 3) - std::pow(d / 2, 3)) * shear_yield_stress(material.fy, shear);
    T.converged = true;
    row.T_p = T;
}

}  // namespace

ShapeTableRow shape_table_row(const CatalogueShape& shape, const Material& material, const ShapeTableOptions& options) {
    const ValidSection section = validate_section(shape_section(shape.geometry, material, options.shape));
    ShapeTableRow row;
    row.shape = &shape;
    row.vertices = section.vertex_count();
    row.elastic = elastic_properties(section);
    row.capacities = compute_capacities(section);
    row.Wpl_x = *row.capacities.Mx / material.fy;  // Mx = fy·Wpl for one material (eq. 2.12)
    row.Wpl_z = *row.capacities.Mz / material.fy;
    if (options.torsion && circular(shape.geometry)) {
        circular_torsion(shape.geometry, material, section.shear(), row);
    } else if (options.torsion) {
        row.J = saint_venant_torsion(validate_section(shape_section(shape.geometry, material, options.J_shape)),
                                     options.J_options);
        row.T_p = plastic_torsion(validate_section(shape_section(shape.geometry, material, options.T_p_shape)),
                                  options.T_p_options);
    }
    return row;
}

std::vector<ShapeTableRow> shape_table(const std::vector<const CatalogueShape*>& shapes, const Material& material,
                                       const ShapeTableOptions& options) {
    std::vector<ShapeTableRow> rows(shapes.size());
    std::atomic<std::size_t> next{0};
    std::size_t done = 0;
    std::mutex report;
    std::exception_ptr failure;
    const auto work = [&] {
        for (std::size_t i; (i = next++) < shapes.size();) {
            try {
                rows[i] = shape_table_row(*shapes[i], material, options);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(report);
                if (!failure) failure = std::current_exception();
                next = shapes.size();  // the others stop after their current row
                return;
            }
            const std::lock_guard<std::mutex> lock(report);
            ++done;
            if (options.progress) options.progress(done, shapes.size());
        }
    };
    unsigned threads = options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, shapes.size())));
    std::vector<std::thread> workers;
    for (unsigned t = 1; t < threads; ++t) workers.emplace_back(work);
    work();
    for (std::thread& w : workers) w.join();
    if (failure) std::rethrow_exception(failure);
    return rows;
}

}  // namespace plascap
