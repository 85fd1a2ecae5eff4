// The section file reader: the documented format, and one message naming the JSON location for
// each way a file can be wrong.
#include <gtest/gtest.h>

#include "plascap/input_error.hpp"
#include "plascap/sections/section_json.hpp"

using namespace plascap;

namespace {

std::string refusal(const std::string& text) {
    try {
        parse_section_json(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(SectionJson, ReadsTheDocumentedFormat) {
    const Section s = parse_section_json(R"({
      "name": "demo", "shear": "von-mises", "reference": [0.01, -0.02],
      "material": {"fy": 355e6},
      "parts": [
        {"outer": [[0, 0], [0.2, 0], [0.2, 0.1], [0, 0.1]], "holes": [[[0.05, 0.02], [0.15, 0.02], [0.1, 0.08]]]},
        {"outer": [[0.2, 0], [0.3, 0], [0.3, 0.1]], "material": {"name": "S235", "fy": 235e6}}
      ]})");
    ASSERT_EQ(s.parts.size(), 2u);
    EXPECT_EQ(s.shear, ShearCriterion::VonMises);
    ASSERT_TRUE(s.reference);
    EXPECT_EQ(s.reference->x, 0.01);
    EXPECT_EQ(s.reference->z, -0.02);
    EXPECT_EQ(s.parts[0].outer.size(), 4u);
    EXPECT_EQ(s.parts[0].outer[2].x, 0.2);
    EXPECT_EQ(s.parts[0].outer[2].z, 0.1);
    ASSERT_EQ(s.parts[0].holes.size(), 1u);
    EXPECT_EQ(s.parts[0].holes[0][2].z, 0.08);
    EXPECT_EQ(s.parts[0].material.fy, 355e6);  // the section's default
    EXPECT_EQ(s.parts[1].material.fy, 235e6);
    EXPECT_EQ(s.parts[1].material.name, "S235");
}

TEST(SectionJson, MalformedJsonNamesLineAndColumn) {
    const std::string message = refusal("{\n  \"parts\": [\n    {\"outer\": [[0, 0], [1, 0] [1, 1]]}\n  ]\n}");
    EXPECT_EQ(message.rfind("malformed JSON: ", 0), 0u) << message;
    EXPECT_NE(message.find("line 3"), std::string::npos) << message;
}

TEST(SectionJson, EmptyText) { EXPECT_EQ(refusal("").rfind("malformed JSON: ", 0), 0u); }

TEST(SectionJson, NaNIsNotJson) { EXPECT_EQ(refusal(R"({"parts": [{"outer": [[NaN, 0]]}]})").rfind("malformed JSON: ", 0), 0u); }

TEST(SectionJson, OverflowingNumberIsRefused) {
    const std::string message = refusal(R"({"material": {"fy": 1e8}, "parts": [{"outer": [[0, 0], [1e400, 0], [1, 1]]}]})");
    EXPECT_NE(message, "");
    EXPECT_TRUE(message.find("1e400") != std::string::npos || message.find("parts[0].outer[1][0]") != std::string::npos)
        << message;
}

TEST(SectionJson, WrongTypesNameTheirLocation) {
    EXPECT_EQ(refusal(R"([1, 2])"), R"(section: expected a JSON object with "parts", got array)");
    EXPECT_EQ(refusal(R"({"material": {"fy": 1e8}, "parts": {}})"), "parts: expected an array of parts, got object");
    EXPECT_EQ(refusal(R"({"material": {"fy": 1e8}, "parts": [{"outer": [[0, 0], [1, "a"], [1, 1]]}]})"),
              "parts[0].outer[1][1]: expected a number, got string");
    EXPECT_EQ(refusal(R"({"material": {"fy": 1e8}, "parts": [{"outer": [[0, 0], [1, 0, 2], [1, 1]]}]})"),
              "parts[0].outer[1]: expected a point [x, z] (two numbers in metres), got an array of 3");
    EXPECT_EQ(refusal(R"({"material": {"fy": 1e8}, "parts": [{"outer": [[0, 0], [1, 0], [1, 1]], "holes": [[[0, 0]], 5]}]})"),
              "parts[0].holes[1]: expected a ring: an array of [x, z] points, got number");
    EXPECT_EQ(refusal(R"({"material": {"fy": "strong"}, "parts": []})"), "material.fy: expected a number, got string");
}

TEST(SectionJson, MissingPiecesAreNamed) {
    EXPECT_EQ(refusal(R"({})"), R"(section: has no "parts" (or "shape"))");
    EXPECT_EQ(refusal(R"({"parts": [{"holes": []}]})"), R"(parts[0]: the part has no "outer" ring)");
    EXPECT_EQ(refusal(R"({"parts": [{"outer": [[0, 0], [1, 0], [1, 1]]}]})"),
              R"(parts[0]: no material: give the part a "material" or the section a default "material")");
    EXPECT_EQ(refusal(R"({"material": {}, "parts": []})"), R"(material: the material has no yield stress "fy" [Pa])");
}

TEST(SectionJson, UnknownKeysAreRefused) {
    EXPECT_EQ(refusal(R"({"material": {"fy": 1e8}, "parts": [{"outer": [[0, 0], [1, 0], [1, 1]], "hole": []}]})"),
              R"(parts[0]: unknown key "hole" (known keys: outer, holes, material, bars, reinforcement, name))");
    EXPECT_EQ(refusal(R"({"sheer": "tresca", "parts": []})"),
              R"(section: unknown key "sheer" (known keys: shear, reference, material, parts, shape, name, description))");
}

TEST(SectionJson, UnknownShearCriterion) {
    EXPECT_EQ(refusal(R"({"shear": "rankine", "parts": []})"),
              R"(shear: unknown shear criterion 'rankine' (choose "tresca" or "von-mises"))");
}

TEST(SectionJson, NamedMaterialsComeFromTheCatalogue) {
    const Section s = parse_section_json(
        R"({"material": "S355", "parts": [{"outer": [[0, 0], [1, 0], [1, 1]]}, {"outer": [[2, 0], [3, 0], [3, 1]], "material": "s235"}]})");
    EXPECT_EQ(s.parts[0].material.name, "S355");
    EXPECT_EQ(s.parts[0].material.fy, 355e6);
    EXPECT_EQ(s.parts[0].material.E, 210e9);
    EXPECT_EQ(s.parts[1].material.fy, 235e6);  // names ignore case
    EXPECT_EQ(refusal(R"({"material": "S335", "parts": []})"), R"(material: unknown material "S335" (did you mean S235, S355, S275?))");
}

TEST(SectionJson, MaterialObjectsCarryEveryProperty) {
    const Section s = parse_section_json(
        R"({"parts": [{"outer": [[0, 0], [1, 0], [1, 1]], "material": {"name": "mine", "fy": 3e8, "E": 2e11, "nu": 0.25, "density": 7000, "ultimate_strain": 0.2, "max_plastic_rotation": 0.3, "shear": "von-mises"}}]})");
    const Material& m = s.parts[0].material;
    EXPECT_EQ(m.name, "mine");
    EXPECT_EQ(*m.shear_modulus(), 2e11 / 2.5);
    EXPECT_EQ(*m.density, 7000.0);
    EXPECT_EQ(*m.max_plastic_rotation, 0.3);
    EXPECT_EQ(m.shear, ShearCriterion::VonMises);
    EXPECT_EQ(refusal(R"({"parts": [{"outer": [[0, 0], [1, 0], [1, 1]], "material": {"fy": 3e8, "nu": 0.7}}]})"),
              "parts[0].material: Poisson's ratio nu must be within (-1, 0.5] (got 0.69999999999999996)");
    EXPECT_EQ(refusal(R"({"parts": [{"outer": [[0, 0], [1, 0], [1, 1]], "material": {"fy": 3e8, "colour": "red"}}]})").rfind(
                  R"(parts[0].material: unknown key "colour" in a material)", 0),
              0u);
}

TEST(SectionJson, UnreadableFileIsNamed) {
    try {
        read_section_file("/nonexistent/section.json");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/section.json: cannot open the file");
    }
}
