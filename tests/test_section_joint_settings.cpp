// The one-call bridge from a section to a joint (plascap::section_joints) against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "plascap/adapters/section_joint_settings.hpp"
#include "plascap/input_error.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/shapes.hpp"

namespace plascap {
namespace {

// 40 × 20 mm S355 (E = 210 GPa, von Mises, ε_u = 0.22) as a 0.5 m segment: N = fy·b·h, Mz =
// fy·h·b²/4, My = T_p = τy·h²(3b − h)/6 (h ≤ b), EA/L, EI/L, and the breaking displacement ε_u·L.
TEST(SectionJointSettings, CapacitiesStiffnessLimitsAndTheCoupledCondition) {
    Section s = rectangle_section(0.04, 0.02, 1.0);
    s.parts[0].material = MaterialCatalogue::built_in().get("S355", "test");
    const ValidSection v = validate_section(s);
    SectionJointOptions o;
    o.segment_length = 0.5;
    const PlasticJointSettings j = section_joint_settings(v, o);
    const double fy = 355e6, b = 0.04, h = 0.02, E = 210e9, L = 0.5;
    ASSERT_NE(j.yield_condition, nullptr);
    EXPECT_NEAR(j.laws[index(Dof::N)].capacity_positive, fy * b * h, 1e-9 * fy * b * h);
    EXPECT_NEAR(j.laws[index(Dof::Mz)].capacity_negative, fy * h * b * b / 4, 1e-9 * fy * h * b * b / 4);
    const double tp = fy / std::sqrt(3.0) * h * h * (3 * b - h) / 6;
    EXPECT_NEAR(j.laws[index(Dof::My)].capacity_positive, tp, 1e-4 * tp);
    EXPECT_NEAR(*j.laws[index(Dof::N)].stiffness, E * b * h / L, 1e-9 * E * b * h / L);
    EXPECT_NEAR(*j.laws[index(Dof::Mz)].stiffness, E * h * b * b * b / 12 / L, 1e-6 * E * h * b * b * b / 12 / L);
    EXPECT_NEAR(j.max_plastic_displacement, 0.22 * L, 1e-12);

    o.coupled = false;
    o.torsion = TorsionCapacity::Paper;
    o.modes.fill(DofMode::Rigid);
    o.modes[index(Dof::Mx)] = DofMode::Plastic;
    o.segment_length.reset();
    const PlasticJointSettings box = section_joint_settings(v, o);
    EXPECT_EQ(box.yield_condition, nullptr);
    EXPECT_EQ(box.modes[index(Dof::N)], DofMode::Rigid);
    EXPECT_NEAR(box.laws[index(Dof::Mx)].capacity_positive, fy * b * h * h / 4, 1e-9 * fy * b * h * h / 4);
    EXPECT_FALSE(box.laws[index(Dof::Mx)].stiffness.has_value());
    EXPECT_TRUE(std::isinf(box.max_plastic_displacement));
}

TEST(SectionJointSettings, AStiffnessNeedsE) {
    const ValidSection v = validate_section(rectangle_section(0.04, 0.02, 355e6));  // fy only
    SectionJointOptions o;
    o.segment_length = 0.5;
    try {
        section_joint_settings(v, o);
        FAIL() << "no E, yet a stiffness";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("the stiffness needs E for every material"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace plascap
