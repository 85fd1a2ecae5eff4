#include "plascap/sections/section_mesh.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <deque>
#include <limits>
#include <set>

#include "mesh_cuts.hpp"
#include "plascap/input_error.hpp"

namespace plascap {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Kernel>>;
// The int is the face's nesting level while marking the domain (-1: not reached yet).
using FaceBase = CGAL::Delaunay_mesh_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel, CGAL::Constrained_Delaunay_triangulation_face_base_2<Kernel>>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// The "plus" hierarchy tells which input constraint (ring or chord) each mesh edge comes from;
// Exact_predicates_tag lets constraints touch and overlap (a chord along a ring edge).
using Cdt = CGAL::Constrained_triangulation_plus_2<CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>>;
using ConstraintId = Cdt::Constraint_id;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

class PartTriangulation {
public:
    // The rings, the joint vertex and the chords of the cut lines (mesh_cuts.hpp): every chord
    // ends on a vertex of the same coordinates, so no intersection is ever constructed.
    explicit PartTriangulation(const detail::MeshCuts& cuts) {
        for (const Ring& ring : cuts.rings) insert_ring(ring);
        if (cuts.vertex) cdt_.insert(Kernel::Point_2(cuts.vertex->x, cuts.vertex->z));
        for (const auto& [from, to] : cuts.chords)
            cdt_.insert_constraint(Kernel::Point_2(from.x, from.z), Kernel::Point_2(to.x, to.z));
    }

    // Marks the faces inside the part (odd nesting level across ring edges; cut edges do not
    // count), then refines them when asked.
    // Marks the faces inside the part (odd nesting level across ring edges; chords do not count),
    // then refines them when asked, within a budget of vertices. Returns false when the budget
    // stopped the refinement.
    bool mark_and_refine(const MeshOptions& options, double part_area) {
        mark_domain();
        if (options.max_area <= 0.0 && !options.refine_shape) return true;
        // A triangle whose longest edge is ≤ S has area ≤ (√3/4)·S² (the equilateral one).
        const double max_edge = options.max_area > 0.0 ? std::sqrt(4.0 * options.max_area / std::sqrt(3.0)) : 0.0;
        CGAL::Delaunay_mesher_2<Cdt, Criteria> mesher(cdt_, Criteria(0.125, max_edge));
        mesher.init(true);
        // Delaunay refinement can keep splitting near a feature or angle too small for doubles; a
        // well-posed mesh needs far fewer vertices than this.
        const double size_share = options.max_area > 0.0 ? 4.0 * part_area / options.max_area : 0.0;
        const double budget = 50.0 * static_cast<double>(cdt_.number_of_vertices()) + size_share + 10000.0;
        while (!mesher.is_refinement_done()) {
            if (static_cast<double>(cdt_.number_of_vertices()) > budget) return false;
            mesher.try_one_step_refine_mesh();
        }
        return true;
    }

    void append_to(SectionMesh& mesh, std::size_t part_index) {
        for (auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
            v->info() = std::numeric_limits<std::size_t>::max();
        for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
            if (!f->is_in_domain()) continue;
            std::array<std::size_t, 3> triangle{};
            for (int i = 0; i < 3; ++i) triangle[static_cast<std::size_t>(i)] = index_of(f->vertex(i), mesh);
            mesh.triangles.push_back(triangle);
            mesh.part_of.push_back(part_index);
        }
    }

private:
    void insert_ring(const Ring& ring) {
        std::vector<Kernel::Point_2> points;
        points.reserve(ring.size());
        for (Point p : ring) points.emplace_back(p.x, p.z);
        ring_constraints_.insert(cdt_.insert_constraint(points.begin(), points.end(), true));
    }

    bool is_ring_edge(Cdt::Face_handle face, int i) const {
        if (!face->is_constrained(i)) return false;
        const Cdt::Vertex_handle a = face->vertex(Cdt::cw(i)), b = face->vertex(Cdt::ccw(i));
        for (auto context = cdt_.contexts_begin(a, b); context != cdt_.contexts_end(a, b); ++context)
            if (ring_constraints_.count(context->id()) != 0) return true;
        return false;
    }

    // Flood fill by nesting level: the infinite face is level 0, crossing a ring edge adds one.
    void mark_domain() {
        for (auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f) f->info() = -1;
        std::deque<Cdt::Edge> borders;
        flood(cdt_.infinite_face(), 0, borders);
        while (!borders.empty()) {
            const Cdt::Edge edge = borders.front();
            borders.pop_front();
            const Cdt::Face_handle next = edge.first->neighbor(edge.second);
            if (next->info() == -1) flood(next, edge.first->info() + 1, borders);
        }
        for (auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f)
            f->set_in_domain(!cdt_.is_infinite(f) && f->info() % 2 == 1);
    }

    void flood(Cdt::Face_handle start, int level, std::deque<Cdt::Edge>& borders) {
        std::deque<Cdt::Face_handle> queue{start};
        start->info() = level;
        while (!queue.empty()) {
            const Cdt::Face_handle face = queue.front();
            queue.pop_front();
            for (int i = 0; i < 3; ++i) {
                const Cdt::Face_handle next = face->neighbor(i);
                if (next->info() != -1) continue;
                if (is_ring_edge(face, i)) {
                    borders.emplace_back(face, i);
                } else {
                    next->info() = level;
                    queue.push_back(next);
                }
            }
        }
    }

    static std::size_t index_of(Cdt::Vertex_handle v, SectionMesh& mesh) {
        if (v->info() == std::numeric_limits<std::size_t>::max()) {
            v->info() = mesh.vertices.size();
            mesh.vertices.push_back({v->point().x(), v->point().y()});
        }
        return v->info();
    }

    Cdt cdt_;
    std::set<ConstraintId> ring_constraints_;
};

double ring_area(const Ring& ring) {  // shoelace
    double area = 0.0;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
        area += 0.5 * (ring[j].x * ring[i].z - ring[i].x * ring[j].z);
    return std::abs(area);
}

// The outer rings' area: an upper bound of the section's.
double outer_area(const ValidSection& section) {
    double area = 0.0;
    for (const Part& part : section.parts()) area += ring_area(part.outer);
    return area;
}

constexpr double kMaxTriangles = 5e6;  // about 1 GB of CGAL triangulation; beyond it, refuse

}  // namespace

SectionMesh mesh_section(const ValidSection& section, const MeshOptions& options) {
    if (!std::isfinite(options.max_area) || options.max_area < 0.0)
        throw InputError("mesh: the largest triangle area must be a finite number ≥ 0 m² (0: no size bound)");
    if (options.max_area > 0.0 && outer_area(section) / options.max_area > kMaxTriangles) {
        char message[160];
        std::snprintf(message, sizeof message,
                      "mesh: a largest triangle area of %.3g m² would make about %.2g triangles (limit %.0e); give a larger one",
                      options.max_area, outer_area(section) / options.max_area, kMaxTriangles);
        throw InputError(message);
    }
    SectionMesh mesh;
    for (std::size_t p = 0; p < section.parts().size(); ++p) {
        PartTriangulation triangulation(
            detail::plan_mesh_cuts(section.parts()[p], options.z_cuts, options.x_cuts, options.vertex));
        if (!triangulation.mark_and_refine(options, ring_area(section.parts()[p].outer))) mesh.refinement_stopped = true;
        triangulation.append_to(mesh, p);
    }
    return mesh;
}

}  // namespace plascap
