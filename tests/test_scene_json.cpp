// The scene reader (tools/plastic-sim/scene.hpp): every bad scene is refused with a message that
// names the problem and where it is; good scenes give the frame, capacities and stiffness that the
// closed forms predict.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plascap/input_error.hpp"
#include "scene.hpp"
#include "scene_errors.hpp"

namespace plascap {
namespace {

// A valid one-body, one-joint scene with `joint_extra` spliced into the joint object.
std::string scene_with(const std::string& joint_extra, const std::string& body_extra = "\"mass\": 2") {
    return R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "block", "box": [1, 2, 3], )" + body_extra +
           R"(}], "joints": [{"name": "j", "a": "world", "b": "block", "anchor": [0, 0, 0], "axis": [0, 1, 0], )" +
           joint_extra + "}]}";
}

std::string error_of(const std::string& text) { return test::scene_error(text); }

TEST(SceneJson, ReadsBodiesJointsAndDefaults) {
    const Scene s = parse_scene_json(scene_with(R"("capacities": {"N": 100, "Mz": 5, "Mz_neg": 3})", R"("density": 10)"));
    EXPECT_EQ(s.steps(), 100u);
    EXPECT_EQ(s.iterations, 10);
    EXPECT_DOUBLE_EQ(s.gravity[1], -9.81);
    EXPECT_DOUBLE_EQ(s.bodies[0].mass, 60.0);  // 10 kg/m³ × 6 m³
    const SceneJoint& j = s.joints[0];
    EXPECT_FALSE(j.a.has_value());
    // Dofs with a capacity are plastic, the others rigid; _neg defaults to the positive value.
    EXPECT_EQ(j.settings.modes[index(Dof::N)], DofMode::Plastic);
    EXPECT_EQ(j.settings.modes[index(Dof::Mz)], DofMode::Plastic);
    EXPECT_EQ(j.settings.modes[index(Dof::Qx)], DofMode::Rigid);
    EXPECT_DOUBLE_EQ(j.settings.laws[index(Dof::N)].capacity_negative, 100.0);
    EXPECT_DOUBLE_EQ(j.settings.laws[index(Dof::Mz)].capacity_negative, 3.0);
    EXPECT_FALSE(j.settings.laws[index(Dof::N)].stiffness.has_value());
    EXPECT_TRUE(std::isinf(j.settings.max_plastic_displacement));
}

TEST(SceneJson, JointFrameIsOrthonormalAndRightHanded) {
    const Scene s = parse_scene_json(
        R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1, 1, 1], "mass": 1}],
            "joints": [{"name": "j", "a": "world", "b": "b", "anchor": [0, 0, 0], "axis": [0, 0, 2],
                        "x_axis": [1, 0, 1], "capacities": {"N": 1}}]})");
    const auto& [x, y, z] = s.joints[0].axes;
    EXPECT_NEAR(y[2], 1.0, 1e-15);
    EXPECT_NEAR(x[0], 1.0, 1e-15);  // the part of x_axis across y
    EXPECT_NEAR(x[2], 0.0, 1e-15);
    EXPECT_NEAR(z[1], -1.0, 1e-15);  // z = x × y
}

TEST(SceneJson, CapacitiesAndStiffnessFromASectionMatchTheClosedForms) {
    // 40 × 20 mm S355 rectangle (b along x, h along z), 0.5 m long: Mz = fy·h·b²/4, Mx = fy·b·h²/4,
    // N = fy·b·h, Q = fy/√3·b·h (the catalogue gives steel von Mises); EA/L, EI/L, 12EI/L³.
    const Scene s = parse_scene_json(scene_with(
        R"("section": {"parts": [{"outer": [[-0.02, -0.01], [0.02, -0.01], [0.02, 0.01], [-0.02, 0.01]]}]},
           "material": "S355", "length": 0.5)"));
    const PlasticJointSettings& j = s.joints[0].settings;
    const double fy = 355e6, b = 0.04, h = 0.02, E = 210e9, L = 0.5;
    EXPECT_NEAR(j.laws[index(Dof::N)].capacity_positive, fy * b * h, 1e-6 * fy * b * h);
    EXPECT_NEAR(j.laws[index(Dof::Qx)].capacity_positive, fy / std::sqrt(3.0) * b * h, 1e-6 * fy * b * h);
    EXPECT_NEAR(j.laws[index(Dof::Mz)].capacity_positive, fy * h * b * b / 4, 1e-6 * fy * h * b * b);
    EXPECT_NEAR(j.laws[index(Dof::Mx)].capacity_negative, fy * b * h * h / 4, 1e-6 * fy * b * h * h);
    EXPECT_NEAR(*j.laws[index(Dof::N)].stiffness, E * b * h / L, 1e-9 * E * b * h / L);
    const double Izz = h * b * b * b / 12;  // about z: stress varies with x
    EXPECT_NEAR(*j.laws[index(Dof::Mz)].stiffness, E * Izz / L, 1e-6 * E * Izz / L);
    EXPECT_NEAR(*j.laws[index(Dof::Qx)].stiffness, 12 * E * Izz / (L * L * L), 1e-6 * 12 * E * Izz / (L * L * L));
    // S355's ultimate strain 0.22 × 0.5 m is the breaking displacement.
    EXPECT_NEAR(j.max_plastic_displacement, 0.22 * 0.5, 1e-12);
}

struct BadScene {
    const char* what;
    std::string text;
    const char* message;  // a part of the expected message
};

class BadScenes : public ::testing::TestWithParam<BadScene> {};

// A joint named by its standard shape: the capacities of the EN 10365 HEB 200 in S355
// (Wpl,y 642.5 cm³ and Wpl,z 305.8 cm³ as tabulated; N = fy·A, A = 78.08 cm²).
TEST(SceneJson, JointFromAShapeName) {
    const Scene s = parse_scene_json(scene_with(R"("shape": "HE 200 B", "material": "S355")"));
    const SceneJoint& j = s.joints[0];
    EXPECT_NEAR(j.settings.laws[index(Dof::N)].capacity_positive / 355e6, 78.08e-4, 0.005 * 78.08e-4);
    EXPECT_NEAR(j.settings.laws[index(Dof::Mx)].capacity_positive / 355e6, 642.5e-6, 0.005 * 642.5e-6);
    EXPECT_NEAR(j.settings.laws[index(Dof::Mz)].capacity_positive / 355e6, 305.8e-6, 0.005 * 305.8e-6);
    EXPECT_NE(error_of(scene_with(R"("shape": "HEB 210", "material": "S355")")).find("did you mean HEB 200"), std::string::npos);
    EXPECT_NE(error_of(scene_with(R"("shape": "HEB 200")")).find("a shape needs a \"material\""), std::string::npos);
}

// Section joints yield on the coupled surface unless told "box"; their torsion capacity is the
// sand heap's T_p = τy·b²(3h − b)/6 (b ≤ h; S355 is von Mises, τy = fy/√3), eq. 2.14 with "paper".
TEST(SceneJson, SectionJointsYieldOnTheCoupledSurfaceWithTorsionTp) {
    const std::string rect = R"("section": {"parts": [{"outer": [[-0.02, -0.01], [0.02, -0.01], [0.02, 0.01], [-0.02, 0.01]]}]}, "material": "S355")";
    const Scene coupled = parse_scene_json(scene_with(rect));
    EXPECT_NE(coupled.joints[0].settings.yield_condition, nullptr);
    const double tp = 355e6 / std::sqrt(3.0) * 0.02 * 0.02 * (3 * 0.04 - 0.02) / 6;
    EXPECT_NEAR(coupled.joints[0].settings.laws[index(Dof::My)].capacity_positive, tp, 1e-4 * tp);
    const Scene box = parse_scene_json(scene_with(rect + R"(, "yield_surface": "box")"));
    EXPECT_EQ(box.joints[0].settings.yield_condition, nullptr);
    EXPECT_NEAR(box.joints[0].settings.laws[index(Dof::My)].capacity_positive, tp, 1e-4 * tp);
    const Scene paper = parse_scene_json(scene_with(rect + R"(, "yield_surface": "box", "torsion": "paper")"));
    // Eq. 2.14: τy·∫∫d dA, over [−a, a] × [−c, c]: (2/3)·[2acr + a³·ln((c + r)/a) + c³·ln((a + r)/c)].
    const double a = 0.02, c = 0.01, r = std::hypot(a, c);
    const double paper_my = 355e6 / std::sqrt(3.0) * 2.0 / 3.0 * (2 * a * c * r + a * a * a * std::log((c + r) / a) + c * c * c * std::log((a + r) / c));
    EXPECT_NEAR(paper.joints[0].settings.laws[index(Dof::My)].capacity_positive, paper_my, 1e-9 * paper_my);
    EXPECT_EQ(parse_scene_json(scene_with(R"("capacities": {"N": 1})")).joints[0].settings.yield_condition, nullptr);
}

TEST_P(BadScenes, AreRefusedWithAMessageNamingTheProblem) {
    EXPECT_NE(error_of(GetParam().text).find(GetParam().message), std::string::npos)
        << GetParam().what << ": " << error_of(GetParam().text);
}

INSTANTIATE_TEST_SUITE_P(
    SceneJson, BadScenes,
    ::testing::Values(
        BadScene{"malformed", "{\"dt\": 0.01,", "not valid JSON"},
        BadScene{"unknown body", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1}],
            "joints": [{"name": "j", "a": "world", "b": "c", "anchor": [0,0,0], "axis": [0,1,0], "capacities": {"N": 1}}]})",
                 "joints[0] (\"j\").b: no body named \"c\""},
        BadScene{"zero axis", scene_with(R"("capacities": {"N": 1}, "axis": [0, 0, 0])"), "zero length"},
        BadScene{"coupled without a section", scene_with(R"("capacities": {"N": 1}, "yield_surface": "coupled")"),
                 "joints[0] (\"j\").yield_surface: \"coupled\" needs the section"},
        BadScene{"unknown yield surface", scene_with(R"("shape": "IPE 200", "material": "S355", "yield_surface": "ellipse")"),
                 "yield_surface: unknown \"ellipse\" (available: coupled, box)"},
        BadScene{"torsion with capacities", scene_with(R"("capacities": {"N": 1}, "torsion": "paper")"),
                 "torsion: chooses a section's torsion capacity"},
        BadScene{"unknown torsion", scene_with(R"("shape": "IPE 200", "material": "S355", "torsion": "elastic")"),
                 "unknown torsion capacity \"elastic\" (available: fully-plastic, paper)"},
        BadScene{"parallel x_axis", scene_with(R"("capacities": {"N": 1}, "x_axis": [0, 3, 0])"), "parallel to axis"},
        BadScene{"negative mass", scene_with(R"("capacities": {"N": 1})", R"("mass": -1)"), "bodies[0] (\"block\").mass: must be positive"},
        BadScene{"mass and density", scene_with(R"("capacities": {"N": 1})", R"("mass": 1, "density": 2)"), "exactly one of \"mass\" and \"density\""},
        BadScene{"overflowing number", scene_with(R"("capacities": {"N": 1e999})"), "number overflow parsing '1e999'"},
        BadScene{"negative capacity", scene_with(R"("capacities": {"N": -5})"), "capacities.N: must be positive"},
        BadScene{"no strength", scene_with(R"("dofs": {"N": "plastic"})"), "exactly one of \"capacities\", \"section\" and \"shape\""},
        BadScene{"plastic without capacity", scene_with(R"("capacities": {"N": 1}, "dofs": {"Mx": "plastic"})"), "dofs.Mx: a plastic dof needs its capacity"},
        BadScene{"unknown dof", scene_with(R"("capacities": {"N": 1}, "dofs": {"Mq": "plastic"})"), "unknown dof \"Mq\""},
        BadScene{"unknown mode", scene_with(R"("capacities": {"N": 1}, "dofs": {"N": "elastic"})"), "unknown dof mode \"elastic\""},
        BadScene{"unknown key", scene_with(R"("capacities": {"N": 1}, "stifness": {"N": 1})"), "unknown key \"stifness\""},
        BadScene{"length without section", scene_with(R"("capacities": {"N": 1}, "length": 1)"), "needs a \"section\""},
        BadScene{"bad section", scene_with(R"("section": {"parts": [{"outer": [[0,0],[1,0],[2,0]]}]}, "material": "S355")"), "section"},
        BadScene{"unknown material", scene_with(R"("section": {"parts": [{"outer": [[0,0],[1,0],[1,1]]}]}, "material": "S999")"), "S999"},
        BadScene{"zero stiffness", scene_with(R"("capacities": {"N": 1}, "stiffness": {"N": 0})"), "stiffness.N: must be positive"},
        BadScene{"same body twice", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1}],
            "joints": [{"name": "j", "a": "b", "b": "b", "anchor": [0,0,0], "axis": [0,1,0], "capacities": {"N": 1}}]})",
                 "a and b are the same body"},
        BadScene{"world as b", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1}],
            "joints": [{"name": "j", "a": "b", "b": "world", "anchor": [0,0,0], "axis": [0,1,0], "capacities": {"N": 1}}]})",
                 "must be a body"},
        BadScene{"static to world", scene_with(R"("capacities": {"N": 1})", R"("mass": 1, "static": true)"), "two static"},
        BadScene{"duplicate body", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1},
            {"name": "b", "box": [1,1,1], "mass": 1}]})", "a second body named \"b\""},
        BadScene{"body named world", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "world", "box": [1,1,1], "mass": 1}]})", "reserved"},
        BadScene{"huge box", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1e300,1], "mass": 1}]})", "box[1]: beyond the supported 1e4 m"},
        BadScene{"far away", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1, "position": [0,0,1e9]}]})", "position[2]: beyond the supported 1e6 m"},
        BadScene{"huge mass", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1e20}]})", "mass is beyond the supported 1e12 kg"},
        BadScene{"zero box", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,0,1], "mass": 1}]})", "box[1]: must be positive"},
        BadScene{"zero quaternion", R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1, "orientation": [0,0,0,0]}]})", "zero length"},
        BadScene{"no bodies", R"({"dt": 0.01, "duration": 1, "bodies": []})", "bodies: expected a non-empty array"},
        BadScene{"negative dt", R"({"dt": -0.01, "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1}]})", "dt: must be positive"},
        BadScene{"endless run", R"({"dt": 1e-9, "duration": 100, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1}]})", "more than the 1e7 allowed"},
        BadScene{"fractional iterations", R"({"dt": 0.01, "duration": 1, "iterations": 2.5, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1}]})", "iterations"},
        BadScene{"string for number", R"({"dt": "0.01", "duration": 1, "bodies": [{"name": "b", "box": [1,1,1], "mass": 1}]})", "dt: expected a number, got string"},
        BadScene{"negative engage_at", scene_with(R"("capacities": {"N": 1}, "engage_at": -1)"), "engage_at: must not be negative"},
        BadScene{"zero breaking limit", scene_with(R"("capacities": {"N": 1}, "max_plastic_rotation": 0)"), "max_plastic_rotation: must be positive"}),
    [](const ::testing::TestParamInfo<BadScene>& info) {
        std::string name = info.param.what;
        for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        return name;
    });

}  // namespace
}  // namespace plascap
