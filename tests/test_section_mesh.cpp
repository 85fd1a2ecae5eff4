// The CGAL mesh of a section: it covers exactly the material (holes left out), respects the size
// bound, and conforms to the kinks — no triangle straddles a cut line, the joint point is a vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "plascap/input_error.hpp"
#include "plascap/sections/section_mesh.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::box;
using plascap::test::part;
using plascap::test::section_of;

namespace {

constexpr double mm = 1e-3;

double signed_area(const SectionMesh& m, std::size_t i) {
    const Point a = m.vertices[m.triangles[i][0]], b = m.vertices[m.triangles[i][1]], c = m.vertices[m.triangles[i][2]];
    return 0.5 * ((b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z));
}

double mesh_area(const SectionMesh& m) {
    double area = 0.0;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) area += signed_area(m, i);
    return area;
}

// Hollow rectangle 200 x 100 with a 180 x 80 hole, beside a 50 x 50 square: area 0.0056 + 0.0025.
ValidSection hollow_and_square() {
    return validate_section(section_of({part(box(-0.1, -0.05, 0.1, 0.05), 355e6, {box(-0.09, -0.04, 0.09, 0.04)}),
                                        part(box(0.1, -0.025, 0.15, 0.025), 235e6)}));
}

TEST(SectionMesh, CoversTheMaterialAndNotTheHoles) {
    const ValidSection s = hollow_and_square();
    const SectionMesh m = mesh_section(s);
    EXPECT_NEAR(mesh_area(m), 0.2 * 0.1 - 0.18 * 0.08 + 0.05 * 0.05, 1e-15);
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        EXPECT_GT(signed_area(m, i), 0.0);  // counter-clockwise
        const auto& t = m.triangles[i];
        const Point c{(m.vertices[t[0]].x + m.vertices[t[1]].x + m.vertices[t[2]].x) / 3.0,
                      (m.vertices[t[0]].z + m.vertices[t[1]].z + m.vertices[t[2]].z) / 3.0};
        const Point global = s.to_section(c);
        const bool in_hole = std::abs(global.x) < 0.09 && std::abs(global.z) < 0.04;
        EXPECT_FALSE(in_hole) << "triangle " << i << " lies in the hole";
        EXPECT_EQ(m.part_of[i], global.x > 0.1 ? 1u : 0u) << "triangle " << i;
    }
}

TEST(SectionMesh, RespectsTheLargestArea) {
    const ValidSection s = hollow_and_square();
    MeshOptions options;
    options.max_area = 1e-5;
    const SectionMesh m = mesh_section(s, options);
    EXPECT_NEAR(mesh_area(m), 0.2 * 0.1 - 0.18 * 0.08 + 0.05 * 0.05, 1e-15);
    double largest = 0.0;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) largest = std::max(largest, signed_area(m, i));
    EXPECT_LE(largest, 1e-5);
    EXPECT_GE(m.triangles.size(), static_cast<std::size_t>(mesh_area(m) / 1e-5));
}

// T with the axis on the flange-web junction, a vertical cut off-centre and the joint point on the
// vertical cut: no triangle has corners on both sides of a cut, and the joint point is a vertex.
TEST(SectionMesh, ConformsToCutsAndJointPoint) {
    const Ring tee = {{-10 * mm, 0}, {10 * mm, 0}, {10 * mm, 100 * mm}, {50 * mm, 100 * mm},
                      {50 * mm, 120 * mm}, {-50 * mm, 120 * mm}, {-50 * mm, 100 * mm}, {-10 * mm, 100 * mm}};
    const ValidSection s = validate_section(section_of({part(tee, 355e6)}));
    for (double max_area : {0.0, 2e-5}) {
        MeshOptions options;
        options.max_area = max_area;
        options.z_cuts = {s.to_local({0, 100 * mm}).z};
        options.x_cuts = {s.to_local({3 * mm, 0}).x};
        options.vertex = s.to_local({3 * mm, 50 * mm});
        const SectionMesh m = mesh_section(s, options);
        bool has_vertex = false;
        for (Point v : m.vertices) has_vertex = has_vertex || (v.x == options.vertex->x && v.z == options.vertex->z);
        EXPECT_TRUE(has_vertex);
        for (const auto& t : m.triangles) {
            int below_z = 0, above_z = 0, left = 0, right = 0;
            for (std::size_t k : t) {
                below_z += m.vertices[k].z < options.z_cuts[0];
                above_z += m.vertices[k].z > options.z_cuts[0];
                left += m.vertices[k].x < options.x_cuts[0];
                right += m.vertices[k].x > options.x_cuts[0];
            }
            EXPECT_FALSE(below_z > 0 && above_z > 0) << "a triangle straddles the horizontal cut";
            EXPECT_FALSE(left > 0 && right > 0) << "a triangle straddles the vertical cut";
        }
        EXPECT_NEAR(mesh_area(m), 0.02 * 0.1 + 0.1 * 0.02, 1e-16);
    }
}

TEST(SectionMesh, RefusesBadSizes) {
    const ValidSection s = hollow_and_square();
    MeshOptions options;
    options.max_area = -1.0;
    EXPECT_THROW(mesh_section(s, options), InputError);
    options.max_area = std::nan("");
    EXPECT_THROW(mesh_section(s, options), InputError);
    options.max_area = 1e-15;
    EXPECT_THROW(mesh_section(s, options), InputError);
}

}  // namespace
