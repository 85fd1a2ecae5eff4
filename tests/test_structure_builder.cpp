// The library's structure builder (plascap::structures, structure_model.hpp), driven from C++ with no
// scene file: an L of an IPE 200 column and beam in S355 becomes segments with the member's mass and
// inertia, hinges with the section's capacity and the segment's stiffness, a node joint in the
// beam's frame, a fixed and a pinned support, and bad input gets one message naming the member,
// node or support. Published IPE 200 values (ArcelorMittal sales programme; EN 10365): A = 28.48 cm²,
// I_y = 1943 cm⁴, W_pl,y = 220.6 cm³; S355 from the catalogue (E = 210 GPa, EN 1993-1-1 3.2.6;
// ρ = 7850 kg/m³). The outline route rounds the root radii, so 0.5 % is allowed on section values.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "plascap/adapters/structure_model.hpp"
#include "plascap/input_error.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/shape_designation.hpp"

namespace plascap {
namespace {

constexpr double kArea = 28.48e-4, kIy = 1943e-8, kWply = 220.6e-6;  // [m², m⁴, m³]
constexpr double kE = 210e9, kFy = 355e6, kRho = 7850;

std::shared_ptr<const ValidSection> ipe200() {
    return std::make_shared<const ValidSection>(
        validate_section(shape_section("IPE 200", MaterialCatalogue::built_in().get("S355", "test"))));
}

StructureMember member(const std::string& name, const std::string& from, const std::string& to, const Vec3& z, int segments,
                       std::shared_ptr<const ValidSection> section) {
    StructureMember m;
    m.name = name;
    m.from = from;
    m.to = to;
    m.z_axis = z;
    m.segments = segments;
    m.section = std::move(section);
    return m;
}

// A 3 m column A–B (4 segments, depth along x) and a 2 m beam B–C (2 segments, depth along y);
// A fixed, C pinned.
Structure l_frame() {
    const auto section = ipe200();
    Structure s;
    s.nodes = {{"A", {0, 0, 0}}, {"B", {0, 3, 0}}, {"C", {2, 3, 0}}};
    s.members = {member("col", "A", "B", {1, 0, 0}, 4, section), member("beam", "B", "C", {0, 1, 0}, 2, section)};
    s.supports = {{"A", StructureSupport::fixed()}, {"C", StructureSupport::pinned()}};
    return s;
}

// v rotated by the unit quaternion q = (w, x, y, z): v + 2w(u × v) + 2u × (u × v), u = (x, y, z).
Vec3 rotated(const Quaternion& q, const Vec3& v) {
    const Vec3 u{q[1], q[2], q[3]}, t = scaled(cross(u, v), 2.0);
    Vec3 r = v;
    add_scaled(r, t, q[0]);
    add_scaled(r, cross(u, t), 1.0);
    return r;
}

void expect_near(const Vec3& a, const Vec3& b, double tol) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

std::string error_of(const Structure& s) {
    try {
        build_structure(s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(StructureBuilder, MembersBecomeSegmentsWithTheRealMembersMassAndInertiaAlongTheirAxes) {
    const StructureModel model = build_structure(l_frame());
    ASSERT_EQ(model.segments.size(), 6u);
    const StructureSegment& col = model.segments[0];
    const double l = 0.75, m = kRho * kArea * l;
    EXPECT_EQ(col.name, "col#1");
    EXPECT_NEAR(col.mass, m, 0.005 * m);
    // About the section's x (its strong axis, I_y in the tables): ρ·ℓ·I + m·ℓ²/12.
    EXPECT_NEAR(col.inertia[0], kRho * l * kIy + m * l * l / 12, 0.005 * (kRho * l * kIy + m * l * l / 12));
    expect_near(col.position, {0, 0.375, 0}, 1e-12);
    expect_near(rotated(col.orientation, {0, 1, 0}), {0, 1, 0}, 1e-12);  // y along the member
    expect_near(rotated(col.orientation, {0, 0, 1}), {1, 0, 0}, 1e-12);  // z the depth given
    const StructureSegment& beam = model.segments[5];
    expect_near(beam.position, {1.5, 3, 0}, 1e-12);
    expect_near(rotated(beam.orientation, {0, 1, 0}), {1, 0, 0}, 1e-12);
    expect_near(rotated(beam.orientation, {0, 0, 1}), {0, 1, 0}, 1e-12);
    EXPECT_EQ(model.outlines.size(), 1u);  // one section, drawn once
    EXPECT_EQ(beam.outline, 0u);
}

TEST(StructureBuilder, HingesCarryTheSectionsCapacityAndTheSegmentsStiffness) {
    const StructureModel model = build_structure(l_frame());
    // 3 + 1 inside the members, one at B, two supports.
    ASSERT_EQ(model.joints.size(), 7u);
    const StructureJoint& inside = model.joints[0];
    EXPECT_EQ(inside.name, "col#1-2");
    EXPECT_EQ(*inside.a, 0u);
    EXPECT_EQ(inside.b, 1u);
    expect_near(inside.anchor, {0, 0.75, 0}, 1e-12);
    EXPECT_EQ(inside.settings.modes[index(Dof::Mx)], DofMode::Plastic);
    EXPECT_EQ(inside.settings.modes[index(Dof::N)], DofMode::Rigid);
    const DofLaw& mx = inside.settings.laws[index(Dof::Mx)];
    EXPECT_NEAR(mx.capacity_positive, kWply * kFy, 0.005 * kWply * kFy);  // M_p = W_pl·fy
    EXPECT_NEAR(*mx.stiffness, kE * kIy / 0.75, 0.005 * kE * kIy / 0.75);  // EI/ℓ

    // B: the beam's first segment joined to the column's last, in the beam's frame, for the
    // length between the two segments' centres.
    const StructureJoint& node = model.joints[4];
    EXPECT_EQ(node.name, "node B: col-beam");
    EXPECT_EQ(*node.a, 3u);
    EXPECT_EQ(node.b, 4u);
    expect_near(node.axes[1], {1, 0, 0}, 1e-12);
    EXPECT_NEAR(*node.settings.laws[index(Dof::Mx)].stiffness, kE * kIy / 0.875, 0.005 * kE * kIy / 0.875);

    // A fixed: to the world, a hinge for half a segment (2EI/ℓ); C pinned: rigid translations along
    // the world's axes, free rotations.
    const StructureJoint& a = model.joints[5];
    EXPECT_EQ(a.name, "support A");
    EXPECT_FALSE(a.a.has_value());
    EXPECT_NEAR(*a.settings.laws[index(Dof::Mx)].stiffness, 2 * kE * kIy / 0.75, 0.01 * kE * kIy / 0.75);
    const StructureJoint& c = model.joints[6];
    EXPECT_EQ(c.b, 5u);
    expect_near(c.axes[0], {1, 0, 0}, 0.0);
    for (Dof dof : kAllDofs) EXPECT_EQ(c.settings.modes[index(dof)], is_rotation(dof) ? DofMode::Free : DofMode::Rigid);
}

TEST(StructureBuilder, NodesAreMaterialPointsOfTheFirstMemberThatMeetsThem) {
    const StructureModel model = build_structure(l_frame());
    ASSERT_EQ(model.nodes.size(), 3u);
    EXPECT_EQ(model.nodes[1].name, "B");
    EXPECT_EQ(model.nodes[1].at.body, 3u);                    // the column's top segment
    expect_near(model.nodes[1].at.local, {0, 0.375, 0}, 1e-12);  // half a segment up its axis
}

TEST(StructureBuilder, ARemovedMemberIsSeveredFromTheRestOnly) {
    Structure s = l_frame();
    s.members[1].removed_at = 0.5;
    const StructureModel model = build_structure(s);
    for (const StructureJoint& j : model.joints) {
        const bool lets_go = j.name == "node B: col-beam" || j.name == "support C";
        EXPECT_EQ(j.severed_at.has_value(), lets_go) << j.name;
        if (lets_go) {
            EXPECT_EQ(*j.severed_at, 0.5) << j.name;
        }
    }
}

TEST(StructureBuilder, BadInputNamesTheMemberNodeOrSupport) {
    Structure s = l_frame();
    s.members[1].to = "X";
    EXPECT_EQ(error_of(s), "member \"beam\".to: no node named \"X\"");
    s = l_frame();
    s.members[1].where = "members[1]";
    s.members[1].to = "B";
    EXPECT_EQ(error_of(s), "members[1]: has zero length (\"B\" and \"B\" coincide)");
    s = l_frame();
    s.members[0].z_axis = Vec3{0, -2, 0};
    EXPECT_EQ(error_of(s), "member \"col\".z_axis: is zero or along the member");
    s = l_frame();
    s.members[1].name = "col";
    EXPECT_EQ(error_of(s), "member \"col\": a second member named \"col\"");
    s = l_frame();
    s.members[0].section.reset();
    EXPECT_EQ(error_of(s), "member \"col\": a member needs a section");
    s = l_frame();
    s.members[0].segments = 0;
    EXPECT_EQ(error_of(s), "member \"col\".segments: expected a whole number from 1 to 1000");
    s = l_frame();
    Material no_density("steel", 355e6);
    no_density.E = 210e9;
    s.members[0].section = std::make_shared<const ValidSection>(validate_section(shape_section("IPE 200", no_density)));
    EXPECT_EQ(error_of(s), "member \"col\": the material \"steel\" needs a density (the member's mass)");
    s = l_frame();
    s.nodes["B"][1] = std::nan("");
    EXPECT_EQ(error_of(s), "node \"B\": its position is not finite");
    s = l_frame();
    s.members[0].z_axis = Vec3{INFINITY, 0, 0};
    EXPECT_EQ(error_of(s), "member \"col\".z_axis: is not finite");
    s = l_frame();
    s.members[0].removed_at = std::nan("");
    EXPECT_EQ(error_of(s), "member \"col\".removed_at: is not a finite time");
    s = l_frame();
    s.members[0].removed_at = -1.0;
    EXPECT_EQ(error_of(s), "member \"col\".removed_at: must not be negative");
    s = l_frame();
    s.supports["Q"] = StructureSupport::fixed();
    EXPECT_EQ(error_of(s), "supports.Q: no node named \"Q\"");
    s = l_frame();
    s.nodes["D"] = {5, 5, 5};
    s.supports["D"] = StructureSupport::pinned();
    EXPECT_EQ(error_of(s), "supports.D: no member meets this node");
    s = l_frame();
    s.supports["C"] = StructureSupport{{false, false, false}, {false, false, false}};
    EXPECT_EQ(error_of(s), "supports.C: restrains nothing");
}

}  // namespace
}  // namespace plascap
