#include "plascap/sections/plastic_torsion.hpp"

#include <algorithm>
#include <array>
#include <queue>
#include <cmath>
#include <limits>
#include <vector>

#include "boundary_distance.hpp"
#include "planar_distance.hpp"
#include "plascap/input_error.hpp"
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/section_mesh.hpp"
#include "triangle_cubature.hpp"

namespace plascap {
namespace {

using detail::distance_to_ring;

constexpr int kHeapRuleOrder = 4;               // points per direction of the fixed rule on each piece
constexpr std::size_t kMaxPieces = 2000000;      // triangles at most: past it, not converged
using detail::distance_to_segment;

// The gap between two rings that do not cross: the nearest pair of points lies at a vertex of one.
double distance_between(const Ring& a, const Ring& b) {
    double d = std::numeric_limits<double>::infinity();
    for (Point p : a) d = std::min(d, distance_to_ring(p, b));
    for (Point p : b) d = std::min(d, distance_to_ring(p, a));
    return d;
}

// Each hole's plateau height: the shortest path from the outer boundary (Dijkstra over the holes,
// the gaps as edge lengths) — the sand heap may not be steeper than 1 anywhere.
std::vector<double> plateaus(const Part& part) {
    const std::size_t n = part.holes.size();
    std::vector<double> height(n), best(n);
    std::vector<bool> done(n, false);
    for (std::size_t k = 0; k < n; ++k) best[k] = distance_between(part.holes[k], part.outer);
    for (std::size_t round = 0; round < n; ++round) {
        std::size_t next = n;
        for (std::size_t k = 0; k < n; ++k)
            if (!done[k] && (next == n || best[k] < best[next])) next = k;
        done[next] = true;
        height[next] = best[next];
        for (std::size_t k = 0; k < n; ++k)
            if (!done[k]) best[k] = std::min(best[k], height[next] + distance_between(part.holes[k], part.holes[next]));
    }
    return height;
}

// φ(p) = min(d(p, outer), min_k (c_k + d(p, hole_k))).
class SandHeap final : public detail::Integrand {
public:
    SandHeap(const Part& part, const std::vector<double>& plateau) : height_(part, plateau) {}
    double operator()(Point p) const override { return height_(p); }
    detail::PolynomialDegree degree_on(const detail::Triangle&) const override { return {}; }

private:
    detail::BoundaryDistance height_;
};

std::array<detail::Triangle, 4> quadrisected(const detail::Triangle& t) {
    const Point ab{(t.a.x + t.b.x) / 2, (t.a.z + t.b.z) / 2}, bc{(t.b.x + t.c.x) / 2, (t.b.z + t.c.z) / 2},
        ca{(t.c.x + t.a.x) / 2, (t.c.z + t.a.z) / 2};
    return {detail::Triangle{t.a, ab, ca}, detail::Triangle{ab, t.b, bc}, detail::Triangle{ca, bc, t.c},
            detail::Triangle{bc, ca, ab}};
}

// ∫φ over the part's triangles, plus the hole plateaus: the heap's volume, to `tolerance` relative.
// Globally adaptive (as QUADPACK's qag is in one dimension): every triangle gets the fixed Gauss
// rule and its own estimate |Q(P) − Q(⌈P/2⌉)|; while the estimates add up to more than the
// tolerance, the triangle with the largest is cut into its four midpoint children. The kinks of φ
// along the medial axis so get small triangles around them only.
detail::Estimate heap_volume(const SectionMesh& mesh, const Part& part, std::size_t p, double tolerance) {
    const std::vector<double> plateau = plateaus(part);
    const SandHeap heap(part, plateau);
    const detail::TriangleRule rule = detail::TriangleRule::fixed(kHeapRuleOrder);
    struct Piece {
        detail::Triangle triangle;
        detail::Estimate estimate;
        bool operator<(const Piece& other) const { return estimate.error < other.estimate.error; }
    };
    std::priority_queue<Piece> pieces;
    detail::Estimate volume;
    for (std::size_t k = 0; k < part.holes.size(); ++k) volume.value += plateau[k] * std::abs(ring_moments(part.holes[k]).area);
    double plateaus_volume = volume.value, value = 0.0, error = 0.0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.part_of[t] != p) continue;
        const auto& v = mesh.triangles[t];
        const detail::Triangle triangle{mesh.vertices[v[0]], mesh.vertices[v[1]], mesh.vertices[v[2]]};
        const detail::Estimate e = rule.integrate(triangle, heap);
        pieces.push({triangle, e});
        value += e.value;
        error += e.error;
    }
    while (error > tolerance * std::abs(value + plateaus_volume) && pieces.size() < kMaxPieces) {
        const Piece worst = pieces.top();
        pieces.pop();
        value -= worst.estimate.value;
        error -= worst.estimate.error;
        for (const detail::Triangle& child : quadrisected(worst.triangle)) {
            const detail::Estimate e = rule.integrate(child, heap);
            pieces.push({child, e});
            value += e.value;
            error += e.error;
        }
    }
    // Sum afresh: the running totals have shed and regained many terms.
    for (; !pieces.empty(); pieces.pop()) {
        volume.value += pieces.top().estimate.value;
        volume.error += pieces.top().estimate.error;
    }
    return volume;
}

detail::Estimate torque_on_mesh(const ValidSection& section, const SectionMesh& mesh, double tolerance) {
    detail::Estimate torque;
    for (std::size_t p = 0; p < section.parts().size(); ++p) {
        const Part& part = section.parts()[p];
        const double factor = 2.0 * shear_yield_stress(part.material.fy, section.shear());  // Nadai: T_p = 2·τy·V
        const detail::Estimate v = heap_volume(mesh, part, p, tolerance);
        torque.value += factor * v.value;
        torque.error += factor * v.error;
    }
    return torque;
}

}  // namespace

PlasticTorsion plastic_torsion(const ValidSection& section, const TorsionOptions& options) {
    if (!(options.relative_tolerance > 0.0 && options.relative_tolerance < 1.0))
        throw InputError("plastic torsion: the relative tolerance must be between 0 and 1");
    // One shape-refined mesh; each triangle adaptively, so that the kinks of φ
    // along the medial axis are resolved where they cross a triangle. (Halving meshes with a fixed
    // rule converged too, but their error changed sign erratically from mesh to mesh, and no
    // estimate drawn from the sequence stayed above it on a regular hexagon.)
    MeshOptions mesh_options;
    mesh_options.refine_shape = true;
    const SectionMesh mesh = mesh_section(section, mesh_options);
    // The estimate adds the outer and the largest inner one, each up to the tolerance: a quarter of it.
    detail::Estimate torque = torque_on_mesh(section, mesh, 0.25 * options.relative_tolerance);
    torque.error += 16.0 * std::numeric_limits<double>::epsilon() * torque.value;  // summation over the triangles
    return {torque.value, torque.error, mesh.triangles.size(), torque.error <= options.relative_tolerance * torque.value};
}

}  // namespace plascap
