// The material catalogue: the built-in grades with their sourced values, user catalogues, lookup
// with suggestions, and clear refusals of bad material files.
#include <gtest/gtest.h>

#include <string>

#include "plascap/input_error.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/materials/material_json.hpp"

using namespace plascap;

namespace {

std::string refusal(const std::string& text) {
    try {
        MaterialCatalogue::parse(text, "mine.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace

// Every grade the materials issue names is there, and every number in it has a source.
TEST(MaterialCatalogue, BuiltInGradesAreSourced) {
    const MaterialCatalogue& c = MaterialCatalogue::built_in();
    for (const char* name : {"S235", "S275", "S355", "S460", "paper-steel", "B500B", "EN-AW-6061-T6", "C25/30", "C30/37", "C24"})
        EXPECT_NE(c.find(name), nullptr) << name;
    for (const Material& m : c.materials()) {
        EXPECT_FALSE(m.description.empty()) << m.name;
        const auto sourced = [&](const char* key) { return m.sources.count(key) == 1 && !m.sources.at(key).empty(); };
        EXPECT_TRUE(sourced("fy")) << m.name;
        EXPECT_TRUE(!m.fc || sourced("fc")) << m.name;
        EXPECT_TRUE(!m.E || sourced("E")) << m.name;
        EXPECT_TRUE(!m.nu || sourced("nu")) << m.name;
        EXPECT_TRUE(!m.G || sourced("G")) << m.name;
        EXPECT_TRUE(!m.density || sourced("density")) << m.name;
        EXPECT_TRUE(!m.ultimate_strain || sourced("ultimate_strain")) << m.name;
        EXPECT_TRUE(!m.max_plastic_rotation || sourced("max_plastic_rotation")) << m.name;
        EXPECT_TRUE(!m.shear || sourced("shear")) << m.name;
        for (const auto& [key, text] : m.sources) EXPECT_FALSE(text.empty()) << m.name << "." << key;
    }
}

// Spot checks against the standards quoted in the file (EN 1993-1-1 Table 3.1 and 3.2.6, EN 1992-1-1
// Table 3.1, EN 338 Table 1) and the paper (Section 3).
TEST(MaterialCatalogue, ValuesOfTheStandards) {
    const MaterialCatalogue& c = MaterialCatalogue::built_in();
    const Material& s355 = *c.find("S355");
    EXPECT_EQ(s355.fy, 355e6);
    EXPECT_EQ(s355.compression_strength(), 355e6);
    EXPECT_EQ(*s355.E, 210e9);
    EXPECT_EQ(*s355.shear_modulus(), 81e9);  // given: EN 1993-1-1 rounds E/(2(1 + ν)) = 80.8 GPa to 81
    EXPECT_EQ(s355.shear, ShearCriterion::VonMises);
    const Material& b500 = *c.find("B500B");
    EXPECT_DOUBLE_EQ(*b500.shear_modulus(), 200e9 / 2.6);  // E/(2(1 + ν)), ν = 0.3
    const Material& concrete = *c.find("C25/30");
    EXPECT_EQ(concrete.fy, 0.0);
    EXPECT_EQ(concrete.compression_strength(), 25e6);
    EXPECT_EQ(*concrete.ultimate_strain, 0.0035);
    const Material& timber = *c.find("C24");
    EXPECT_EQ(timber.fy, 14.5e6);
    EXPECT_EQ(timber.compression_strength(), 21e6);
    const Material& paper = *c.find("paper-steel");
    EXPECT_EQ(paper.fy, 200e6);
    EXPECT_EQ(*paper.E, 200e9);
    EXPECT_EQ(*paper.density, 7800.0);
}

TEST(MaterialCatalogue, LookupIgnoresCaseAndSuggestsCloseNames) {
    const MaterialCatalogue& c = MaterialCatalogue::built_in();
    EXPECT_EQ(&c.get("s355", "x"), c.find("S355"));
    try {
        c.get("S335", "--material");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "--material: unknown material \"S335\" (did you mean S235, S355, S275?)");
    }
    EXPECT_EQ(c.similar_names("c25").front(), "C25/30");  // contains it: closest
    EXPECT_TRUE(c.similar_names("Unobtainium").empty());
}

TEST(MaterialCatalogue, UserFilesAddAndReplace) {
    MaterialCatalogue c = MaterialCatalogue::built_in();
    const std::size_t before = c.materials().size();
    c.add(MaterialCatalogue::parse(R"({"format": "plascap-materials-1", "materials": [
        {"name": "S355", "fy": 360e6, "description": "mill certificate"},
        {"name": "Ti-6Al-4V", "fy": 880e6, "E": 114e9, "nu": 0.34, "density": 4430}]})",
                                   "mine.json"));
    EXPECT_EQ(c.materials().size(), before + 1);
    EXPECT_EQ(c.get("S355", "x").fy, 360e6);
    EXPECT_EQ(c.get("ti-6al-4v", "x").density, 4430.0);
}

TEST(MaterialCatalogue, BadFilesAreRefusedByPlace) {
    EXPECT_EQ(refusal("{\"materials\": [").rfind("mine.json: malformed JSON", 0), 0u);
    EXPECT_EQ(refusal(R"({"materials": {}})"), R"(mine.json: expected {"format": "plascap-materials-1", "materials": [...]})");
    EXPECT_EQ(refusal(R"({"format": "other", "materials": []})"), R"(mine.json: unknown format "other" (expected "plascap-materials-1"))");
    EXPECT_EQ(refusal(R"({"materials": [{"fy": 1e8}]})"), R"(mine.json: materials[0]: a catalogue material needs a "name")");
    EXPECT_EQ(refusal(R"({"materials": [{"name": "a", "fy": 1e8}, {"name": "A", "fy": 2e8}]})"),
              R"(mine.json: materials[1]: the name "A" is given twice in this file)");
    EXPECT_EQ(refusal(R"({"materials": [{"name": "a", "fy": 1e8, "E": -1}]})"),
              "mine.json: materials[0]: Young's modulus E must be within [1000, 10000000000000] Pa (got -1)");
    EXPECT_EQ(refusal(R"({"materials": [{"name": "a", "fy": "strong"}]})"), "mine.json: materials[0].fy: expected a number, got string");
    EXPECT_EQ(refusal(R"({"materials": [{"name": "a", "fy": 1e8, "fc": -5}]})"),
              "mine.json: materials[0]: compressive strength fc must be a finite number >= 0 in Pa (got -5)");
    EXPECT_EQ(refusal(R"({"materials": [{"name": "a", "fy": 1e8, "shear": "rankine"}]})"),
              R"(mine.json: materials[0].shear: unknown shear criterion 'rankine' (choose "tresca" or "von-mises"))");
    try {
        MaterialCatalogue::read_file("/nonexistent/materials.json");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/materials.json: cannot open the materials file");
    }
}

TEST(MaterialJson, OneObject) {
    const Material m = parse_material_json(R"({"fy": 1e8, "fc": 2e8, "max_plastic_rotation": 0.2})", "m");
    EXPECT_EQ(m.compression_strength(), 2e8);
    EXPECT_EQ(*m.max_plastic_rotation, 0.2);
    EXPECT_FALSE(m.shear_modulus());
    EXPECT_THROW(parse_material_json(R"({"fy": 1e8, "max_plastic_rotation": 7})", "m"), InputError);
    EXPECT_THROW(parse_material_json("[1]", "m"), InputError);
}
