#include "plascap/sections/torsion_constant.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "mesh_extrapolation.hpp"
#include "plascap/input_error.hpp"
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/section_mesh.hpp"

namespace plascap {
namespace {

constexpr std::size_t kFixed = std::numeric_limits<std::size_t>::max();        // φ = 0: the outer boundary
constexpr std::size_t kNotInPart = std::numeric_limits<std::size_t>::max() - 1;  // a vertex of another part

// Union–find over vertex indices, to group boundary vertices into loops.
class Loops {
public:
    explicit Loops(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    std::size_t root(std::size_t i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    void join(std::size_t a, std::size_t b) { parent_[root(a)] = root(b); }

private:
    std::vector<std::size_t> parent_;
};

struct Edge {
    std::size_t from, to;
};

// Boundary edges of one part's triangles (edges used once), with the triangles' orientation:
// counter-clockwise around the material, so the outer loop runs counter-clockwise, holes clockwise.
std::vector<Edge> boundary_edges(const SectionMesh& mesh, std::size_t part) {
    std::vector<std::pair<std::pair<std::size_t, std::size_t>, Edge>> all;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.part_of[t] != part) continue;
        for (int k = 0; k < 3; ++k) {
            const std::size_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
            all.push_back({{std::min(a, b), std::max(a, b)}, Edge{a, b}});
        }
    }
    std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Edge> boundary;
    for (std::size_t i = 0; i < all.size();) {
        std::size_t j = i;
        while (j < all.size() && all[j].first == all[i].first) ++j;
        if (j - i == 1) boundary.push_back(all[i].second);
        i = j;
    }
    return boundary;
}

// The unknown of each vertex: kFixed on the outer loop, one shared unknown per hole loop, one of
// its own inside. Also the area each hole loop encloses.
struct Unknowns {
    std::vector<std::size_t> of_vertex;
    std::vector<double> hole_area;  // by hole unknown
    std::vector<std::size_t> hole_unknown;
    std::size_t count = 0;
};

Unknowns number_unknowns(const SectionMesh& mesh, std::size_t part) {
    const std::vector<Edge> boundary = boundary_edges(mesh, part);
    Loops loops(mesh.vertices.size());
    for (const Edge& e : boundary) loops.join(e.from, e.to);
    // Signed area of each loop (shoelace over its edges): the outer loop's is positive.
    std::vector<double> loop_area(mesh.vertices.size(), 0.0);
    for (const Edge& e : boundary) {
        const Point a = mesh.vertices[e.from], b = mesh.vertices[e.to];
        loop_area[loops.root(e.from)] += 0.5 * (a.x * b.z - b.x * a.z);
    }
    Unknowns u;
    u.of_vertex.assign(mesh.vertices.size(), kNotInPart);
    std::vector<std::size_t> unknown_of_loop(mesh.vertices.size(), kNotInPart);
    for (const Edge& e : boundary) {
        const std::size_t loop = loops.root(e.from);
        if (unknown_of_loop[loop] != kNotInPart) continue;
        if (loop_area[loop] > 0.0) {
            unknown_of_loop[loop] = kFixed;  // the outer boundary
        } else {
            unknown_of_loop[loop] = u.count++;
            u.hole_unknown.push_back(unknown_of_loop[loop]);
            u.hole_area.push_back(-loop_area[loop]);
        }
    }
    for (const Edge& e : boundary) u.of_vertex[e.from] = unknown_of_loop[loops.root(e.from)];
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.part_of[t] != part) continue;
        for (std::size_t v : mesh.triangles[t])
            if (u.of_vertex[v] == kNotInPart) u.of_vertex[v] = u.count++;
    }
    return u;
}

// The unknown of each edge's midpoint (quadratic elements): a boundary edge's takes its loop's
// (0 on the outer boundary, the hole's shared unknown), an inner edge's a new one.
std::map<std::pair<std::size_t, std::size_t>, std::size_t> number_midpoints(const SectionMesh& mesh, std::size_t part,
                                                                             Unknowns& u) {
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.part_of[t] != part) continue;
        for (int k = 0; k < 3; ++k) {
            const std::size_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
    for (const auto& [edge, count] : uses)
        midpoint[edge] = count == 1 ? u.of_vertex[edge.first] : u.count++;  // both ends share the loop's unknown
    return midpoint;
}

// J of one part with quadratic triangles (6 nodes): assemble ∫∇N_a·∇N_b dA (exact with the
// 3-point edge-midpoint rule: the integrand is quadratic) and the load 2∫N_a dA (0 at the
// corners, 2A/3 at the midpoints) plus 2·A_k on each hole's unknown; solve K·φ = f; J = f·φ
// (= 2∫φ dA + 2·Σ c_k·A_k at the discrete solution).
double part_torsion(const SectionMesh& mesh, std::size_t part) {
    Unknowns u = number_unknowns(mesh, part);
    const auto midpoint = number_midpoints(mesh, part, u);
    if (u.count == 0) return 0.0;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd load = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(u.count));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.part_of[t] != part) continue;
        const auto& v = mesh.triangles[t];
        const Point p[3] = {mesh.vertices[v[0]], mesh.vertices[v[1]], mesh.vertices[v[2]]};
        const double area = 0.5 * ((p[1].x - p[0].x) * (p[2].z - p[0].z) - (p[2].x - p[0].x) * (p[1].z - p[0].z));
        // ∇L_i = (z_j − z_k, x_k − x_j)/(2A) for (i, j, k) cyclic.
        double gx[3], gz[3];
        for (int i = 0; i < 3; ++i) {
            const Point pj = p[(i + 1) % 3], pk = p[(i + 2) % 3];
            gx[i] = (pj.z - pk.z) / (2.0 * area);
            gz[i] = (pk.x - pj.x) / (2.0 * area);
        }
        std::size_t node[6];
        for (int i = 0; i < 3; ++i) {
            node[i] = u.of_vertex[v[i]];
            const std::size_t a = v[i], b = v[(i + 1) % 3];
            node[3 + i] = midpoint.at({std::min(a, b), std::max(a, b)});  // midpoint of edge i–(i+1)
        }
        // Gradients of N_i = L_i(2L_i − 1) and N_(i,i+1) = 4·L_i·L_(i+1) at the edge midpoints q.
        double k_local[6][6] = {};
        for (int q = 0; q < 3; ++q) {
            double L[3] = {0.0, 0.0, 0.0};
            L[q] = 0.5, L[(q + 1) % 3] = 0.5;
            double dx[6], dz[6];
            for (int i = 0; i < 3; ++i) {
                dx[i] = (4.0 * L[i] - 1.0) * gx[i], dz[i] = (4.0 * L[i] - 1.0) * gz[i];
                const int j = (i + 1) % 3;
                dx[3 + i] = 4.0 * (L[j] * gx[i] + L[i] * gx[j]), dz[3 + i] = 4.0 * (L[j] * gz[i] + L[i] * gz[j]);
            }
            for (int a = 0; a < 6; ++a)
                for (int b = 0; b < 6; ++b) k_local[a][b] += area / 3.0 * (dx[a] * dx[b] + dz[a] * dz[b]);
        }
        for (int a = 0; a < 6; ++a) {
            if (node[a] == kFixed) continue;
            if (a >= 3) load[static_cast<Eigen::Index>(node[a])] += 2.0 * area / 3.0;  // 2∫4·L_i·L_j dA
            for (int b = 0; b < 6; ++b)
                if (node[b] != kFixed)
                    entries.emplace_back(static_cast<Eigen::Index>(node[a]), static_cast<Eigen::Index>(node[b]), k_local[a][b]);
        }
    }
    for (std::size_t h = 0; h < u.hole_unknown.size(); ++h) load[static_cast<Eigen::Index>(u.hole_unknown[h])] += 2.0 * u.hole_area[h];
    Eigen::SparseMatrix<double> stiffness(static_cast<Eigen::Index>(u.count), static_cast<Eigen::Index>(u.count));
    stiffness.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(stiffness);
    if (solver.info() != Eigen::Success) throw std::runtime_error("torsion: the stiffness matrix could not be factorised");
    const Eigen::VectorXd phi = solver.solve(load);
    return load.dot(phi);
}

}  // namespace

double saint_venant_torsion_on_mesh(const ValidSection& section, double max_area, std::size_t* triangles) {
    MeshOptions options;
    options.max_area = max_area;
    options.refine_shape = true;
    const SectionMesh mesh = mesh_section(section, options);
    if (triangles) *triangles = mesh.triangles.size();
    double J = 0.0;
    for (std::size_t p = 0; p < section.parts().size(); ++p) J += part_torsion(mesh, p);
    return J;
}

TorsionConstant saint_venant_torsion(const ValidSection& section, const TorsionOptions& options) {
    double area = 0.0;
    for (const Part& part : section.parts()) area += part_moments(part).area;
    const detail::Extrapolated e = detail::extrapolate_over_meshes(
        [&](double max_area, std::size_t& triangles) { return saint_venant_torsion_on_mesh(section, max_area, &triangles); },
        area, options.relative_tolerance, options.max_triangles, 4.0);  // quadratic elements: O(h⁴)
    TorsionConstant result{e.value, std::nullopt, e.error, e.triangles, e.converged};
    const std::optional<double> G = section.parts().front().material.shear_modulus();
    bool same_G = G.has_value();
    for (const Part& part : section.parts()) same_G = same_G && part.material.shear_modulus() == G;
    if (same_G) result.GJ = *G * result.J;
    return result;
}

}  // namespace plascap
