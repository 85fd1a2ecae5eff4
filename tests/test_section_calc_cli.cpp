// section-calc end to end: the binary is run as a user would, its output parsed and checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include "cli_run.hpp"

namespace {

using plascap::test::CliRun;

const std::string kSource = PLASCAP_SOURCE_DIR;

CliRun section_calc(const std::string& arguments) { return plascap::test::run_tool(PLASCAP_SECTION_CALC, arguments); }

std::string example(const std::string& name) { return kSource + "/sections/examples/" + name; }

double relative_error(double value, double reference) { return std::fabs(value - reference) / std::fabs(reference); }

}  // namespace

// The paper's square (Fig. 2.6) through --json: every key present and right.
TEST(SectionCalc, JsonOfThePaperSquare) {
    const CliRun run = section_calc("--json \"" + example("paper-square.json") + "\"");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const nlohmann::json j = nlohmann::json::parse(run.out);
    EXPECT_LT(relative_error(j["N"].get<double>(), 0.01 * 0.01 * 200e6), 1e-12);
    EXPECT_LT(relative_error(j["Qx"].get<double>(), 0.01 * 0.01 * 100e6), 1e-12);
    EXPECT_LT(relative_error(j["Qz"].get<double>(), 0.01 * 0.01 * 100e6), 1e-12);
    EXPECT_LT(relative_error(j["Mx"].get<double>(), 200e6 * 0.01 * 0.01 * 0.01 / 4.0), 1e-12);
    EXPECT_LT(relative_error(j["Mz"].get<double>(), 200e6 * 0.01 * 0.01 * 0.01 / 4.0), 1e-12);
    EXPECT_NEAR(j["My"].get<double>(), 38.2597858232, 5e-10);
    EXPECT_EQ(j["method"], "exact");
    EXPECT_EQ(j["shear"], "tresca");
    EXPECT_EQ(j["z_pna"].get<double>(), 0.0);
}

TEST(SectionCalc, TableShowsEveryCapacity) {
    const CliRun run = section_calc("\"" + example("t-section.json") + "\"");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    for (const char* row : {"N ", "Qx ", "Qz ", "Mx ", "Mz ", "My "}) EXPECT_NE(run.out.find(std::string("\n  ") + row), std::string::npos) << row;
    EXPECT_NE(run.out.find("z = 0.15 m (plastic neutral axis"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("42300"), std::string::npos) << run.out;  // Mx = 235e6 · 180,000 mm³
}

// --rect B H --fy FY with --shear von-mises and --only: Qx = b·h·fy/√3, nothing else printed.
TEST(SectionCalc, RectangleShortcutWithShearAndOnly) {
    const CliRun run = section_calc("--rect 0.1 0.2 --fy 300e6 --shear von-mises --only Qx,Mx --json");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out);
    EXPECT_LT(relative_error(j["Qx"].get<double>(), 0.02 * 300e6 / std::sqrt(3.0)), 1e-12);
    EXPECT_LT(relative_error(j["Mx"].get<double>(), 300e6 * 0.1 * 0.04 / 4.0), 1e-12);
    EXPECT_FALSE(j.contains("N") || j.contains("Qz") || j.contains("Mz") || j.contains("My"));
    EXPECT_FALSE(j.contains("x_pna") || j.contains("reference"));
}

// --reference moves the joint point: a corner of the 10 mm square gives a quarter of the 20 mm
// square's ∫d dA about its centre: My = 100e6 · (2/3)(2√2 + 2·asinh 1)·(0.01)³ / 4.
TEST(SectionCalc, ReferenceOption) {
    const CliRun run = section_calc("--rect 0.01 0.01 --fy 200e6 --reference 0.005 0.005 --only My --json");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const double expected = 100e6 * (2.0 / 3.0) * (2.0 * std::sqrt(2.0) + 2.0 * std::asinh(1.0)) * 1e-6 / 4.0;
    EXPECT_LT(relative_error(nlohmann::json::parse(run.out)["My"].get<double>(), expected), 1e-12);
}

TEST(SectionCalc, EveryExampleRuns) {
    for (const char* name : {"paper-square.json", "rectangle.json", "i-section.json", "hollow-rectangle.json",
                             "t-section.json", "two-part.json"}) {
        const CliRun run = section_calc("--json \"" + example(name) + "\"");
        EXPECT_EQ(run.exit_code, 0) << name << ": " << run.err;
        EXPECT_GT(nlohmann::json::parse(run.out)["My"].get<double>(), 0.0) << name;
    }
}

// "-" reads the section from standard input; its errors name "standard input".
TEST(SectionCalc, ReadsStandardInput) {
    const CliRun good = section_calc("- --json --only N < \"" + example("rectangle.json") + "\"");
    ASSERT_EQ(good.exit_code, 0) << good.err;
    EXPECT_LT(relative_error(nlohmann::json::parse(good.out)["N"].get<double>(), 0.1 * 0.05 * 355e6), 1e-12);
    const CliRun bad = section_calc("- < \"" + kSource + "/tests/bad-input/collinear.json\"");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.err, "section-calc: error: standard input: part 0, outer ring: has zero area: its vertices are collinear\n");
}

// The cubature route end to end: the paper's 38.2 to the requested tolerance, with the estimates,
// mesh size and time the JSON promises; the fixed rule is named as such.
TEST(SectionCalc, CubatureMethodJson) {
    const CliRun run = section_calc("--method cubature --tol 1e-9 --json \"" + example("paper-square.json") + "\"");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["method"], "cubature");
    EXPECT_NEAR(j["My"].get<double>(), 38.2597858232, 38.26 * 1e-9);
    for (const char* key : {"N", "Qx", "Qz", "Mx", "Mz", "My"}) {
        ASSERT_TRUE(j["errors"].contains(key)) << key;
        EXPECT_GE(j["errors"][key].get<double>(), 0.0) << key;
    }
    EXPECT_LE(j["errors"]["My"].get<double>(), 2 * 38.26 * 1e-9);
    EXPECT_GT(j["triangles"].get<int>(), 0);
    EXPECT_GT(j["seconds"].get<double>(), 0.0);
    EXPECT_EQ(j["refinement_stopped"], false);
    EXPECT_EQ(j["cubature"]["rule"], "adaptive");
    EXPECT_EQ(j["cubature"]["tolerance"].get<double>(), 1e-9);

    const CliRun fixed = section_calc("--method cubature --order 6 --max-area 1e-6 --json \"" + example("t-section.json") + "\"");
    ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
    const nlohmann::json f = nlohmann::json::parse(fixed.out);
    EXPECT_EQ(f["cubature"]["rule"], "fixed");
    EXPECT_EQ(f["cubature"]["order"].get<int>(), 6);
    EXPECT_GE(f["triangles"].get<double>(), 0.003 / 1e-6);  // area 3000 mm², triangles ≤ 1 mm²
    EXPECT_LT(relative_error(f["Mx"].get<double>(), 42300.0), 1e-12);
}

TEST(SectionCalc, CubatureTableShowsEstimates) {
    const CliRun run = section_calc("--method cubature \"" + example("t-section.json") + "\"");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("± estimated error"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("cubature, adaptive to 1e-10 relative"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(" triangles, "), std::string::npos) << run.out;
}

// --svg draws the section: the file is SVG with the outline, both axes, centroid, joint and scale.
TEST(SectionCalc, SvgDrawing) {
    const std::string path = ::testing::TempDir() + "section_calc_" + std::to_string(getpid()) + ".svg";
    const CliRun run = section_calc("--svg \"" + path + "\" \"" + example("hollow-rectangle.json") + "\"");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::ifstream file(path);
    std::stringstream svg;
    svg << file.rdbuf();
    const std::string text = svg.str();
    EXPECT_EQ(text.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u) << text.substr(0, 80);
    for (const char* needle : {"fill-rule=\"evenodd\"", "Mx axis z = 0 m", "Mz axis x = 0 m", "centroid", "joint point (My)", "<polygon", " mm</text>", "</svg>"})
        EXPECT_NE(text.find(needle), std::string::npos) << needle;
    std::remove(path.c_str());

    // Bars at their size, a legend of the materials, and the hogging axis on the bars.
    const CliRun beam = section_calc("--svg \"" + path + "\" \"" + example("rc-beam.json") + "\"");
    ASSERT_EQ(beam.exit_code, 0) << beam.err;
    std::stringstream drawing;
    drawing << std::ifstream(path).rdbuf();
    for (const char* needle : {"<circle cx=", ">C25/30</text>", ">B500B</text>", "Mx_neg axis z = -0.2 m"})
        EXPECT_NE(drawing.str().find(needle), std::string::npos) << needle;
    std::remove(path.c_str());
}

// The catalogue: listed for people and for programs (with every value's source), used by name for
// a --rect section or every part of a file, extended by a user's file.
TEST(SectionCalc, MaterialsCatalogue) {
    const CliRun table = section_calc("--list-materials");
    ASSERT_EQ(table.exit_code, 0) << table.err;
    EXPECT_NE(table.out.find("\nS355           355     355     210    0.3"), std::string::npos) << table.out;
    const CliRun listing = section_calc("--list-materials --json");
    ASSERT_EQ(listing.exit_code, 0) << listing.err;
    const nlohmann::json all = nlohmann::json::parse(listing.out);
    ASSERT_GE(all.size(), 12u);
    for (const auto& m : all) EXPECT_TRUE(m["sources"].contains("fy")) << m["name"];

    const CliRun rect = section_calc("--rect 0.1 0.2 --material S355 --only N,Mx --json");
    ASSERT_EQ(rect.exit_code, 0) << rect.err;
    const nlohmann::json r = nlohmann::json::parse(rect.out);
    EXPECT_LT(relative_error(r["N"].get<double>(), 355e6 * 0.02), 1e-12);
    EXPECT_LT(relative_error(r["Mx"].get<double>(), 355e6 * 0.1 * 0.04 / 4.0), 1e-12);

    const CliRun override_file = section_calc("--material s235 --only N --json \"" + example("t-section.json") + "\"");
    ASSERT_EQ(override_file.exit_code, 0) << override_file.err;
    EXPECT_LT(relative_error(nlohmann::json::parse(override_file.out)["N"].get<double>(), 235e6 * 0.003), 1e-12);

    const std::string user = ::testing::TempDir() + "materials_" + std::to_string(getpid()) + ".json";
    std::ofstream(user) << R"({"format": "plascap-materials-1", "materials": [{"name": "Ti-6Al-4V", "fy": 880e6}]})";
    const CliRun titanium = section_calc("--materials \"" + user + "\" --rect 0.01 0.01 --material ti-6al-4v --only N --json");
    ASSERT_EQ(titanium.exit_code, 0) << titanium.err;
    EXPECT_LT(relative_error(nlohmann::json::parse(titanium.out)["N"].get<double>(), 880e6 * 1e-4), 1e-12);
    std::remove(user.c_str());
}

// --elastic: the rectangle's b·h³/12 and b·h²/6, and EA = E·A with a catalogue material.
TEST(SectionCalc, ElasticBlock) {
    const CliRun run = section_calc("--rect 0.1 0.2 --material S355 --elastic --only N --json");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out);
    EXPECT_LT(relative_error(j["Ixx"].get<double>(), 0.1 * 0.008 / 12), 1e-14);
    EXPECT_LT(relative_error(j["Wz"].get<double>(), 0.2 * 0.01 / 6), 1e-14);
    EXPECT_LT(relative_error(j["EA"].get<double>(), 210e9 * 0.02), 1e-14);
    // The square's J = 0.14058·a⁴ (values.md) and T_p = τy·a³/3 (von Mises for S355); a 2 m segment.
    const CliRun square = section_calc("--rect 0.1 0.1 --material S355 --elastic --length 2 --json");
    ASSERT_EQ(square.exit_code, 0) << square.err;
    const nlohmann::json q = nlohmann::json::parse(square.out);
    EXPECT_LT(relative_error(q["J"].get<double>(), 0.14058e-4), 1e-4);
    EXPECT_LT(relative_error(q["GJ"].get<double>(), 81e9 * q["J"].get<double>()), 1e-14);
    EXPECT_LT(relative_error(q["My_plastic_torsion"].get<double>(), 355e6 / std::sqrt(3.0) * 1e-3 / 3), 1e-4);
    EXPECT_LT(relative_error(q["joint"]["axial"].get<double>(), 210e9 * 0.01 / 2), 1e-14);
    EXPECT_LT(relative_error(q["joint"]["shear_z"].get<double>(), 12 * 210e9 * 1e-4 / 12 / 8), 1e-13);
    EXPECT_LT(relative_error(q["joint"]["torsion"].get<double>(), q["GJ"].get<double>() / 2), 1e-14);
    const CliRun table = section_calc("--rect 0.1 0.2 --fy 1e8 --elastic");
    ASSERT_EQ(table.exit_code, 0) << table.err;
    EXPECT_NE(table.out.find("stiffness   not available: a material gives no E"), std::string::npos) << table.out;
}

// A file of 10⁶ vertices (45 MB) is accepted (measured: 2.0 s on the development machine, all of
// reading, validation and the exact route); N equals fy times the regular polygon's area.
TEST(SectionCalc, MillionVertexFile) {
    const std::string path = ::testing::TempDir() + "million_" + std::to_string(getpid()) + ".json";
    {
        std::ofstream file(path);
        file.precision(17);
        file << R"({"material": {"fy": 355e6}, "parts": [{"outer": [)";
        const int n = 1000000;
        for (int i = 0; i < n; ++i) {
            const double angle = 2.0 * 3.141592653589793 * i / n;
            file << (i ? "," : "") << "[" << 0.1 * std::cos(angle) << "," << 0.1 * std::sin(angle) << "]";
        }
        file << "]}]}";
    }
    const CliRun run = section_calc("--only N --json \"" + path + "\"");
    std::remove(path.c_str());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const double area = 0.5 * 1000000 * 0.01 * std::sin(2.0 * 3.141592653589793 / 1000000);
    EXPECT_LT(relative_error(nlohmann::json::parse(run.out)["N"].get<double>(), 355e6 * area), 1e-9);
}

// Every option is documented in --help.
TEST(SectionCalc, HelpListsEveryOption) {
    const CliRun run = section_calc("--help");
    EXPECT_EQ(run.exit_code, 0);
    for (const char* option : {"FILE", "--rect", "--fy", "--material", "--materials", "--list-materials", "--shear",
                               "--reference", "--only", "--method", "--tol", "--order", "--max-area", "--svg", "--elastic",
                               "--length", "--json",
                               "--version"})
        EXPECT_NE(run.out.find(option), std::string::npos) << option;
}

// Bad command lines: exit 2, one line on stderr, nothing on stdout.
TEST(SectionCalc, BadCommandLines) {
    const struct {
        std::string arguments;
        std::string message;
    } cases[] = {
        {"", "section-calc: error: no section: give FILE, --rect B H --fy FY or --shape NAME --material M (see --help)\n"},
        {"--rect 0.1 0.1", "section-calc: error: --rect needs --fy FY, the yield stress in Pa, or --material NAME\n"},
        {"--rect -0.1 0.1 --fy 1e8", "section-calc: error: --rect: width B [m] must be a positive finite number (got -0.1)\n"},
        {"--rect 0.1 0.1 --fy -1e8", "section-calc: error: part 0, material: yield stress fy must be a finite number >= 0 in Pa (got -100000000)\n"},
        {"--rect 0.1 0.1 --fy 1e8 --only N,Mq", "section-calc: error: unknown capacity 'Mq' (choose from N, Qx, Qz, Mx, Mz, My, N_neg, Mx_neg, Mz_neg)\n"},
        {"--rect 0.1 0.1 --fy 1e8 --shear rankine", "section-calc: error: unknown shear criterion 'rankine' (choose \"tresca\" or \"von-mises\")\n"},
        {"--rect 0.1 0.1 --fy 1e8 --method magic", "section-calc: error: --method magic: unknown method (available: exact, cubature)\n"},
        {"--rect 0.1 0.1 --material S335", "section-calc: error: --material: unknown material \"S335\" (did you mean S235, S355, S275?)\n"},
        {"--rect 0.1 0.1 --fy 1e8 --material S355", "section-calc: error: give --fy or --material, not both\n"},
        {"--materials /nonexistent/m.json --list-materials", "section-calc: error: /nonexistent/m.json: cannot open the materials file\n"},
        {"--materials " + kSource + "/tests/bad-input/materials-malformed.json --list-materials",
         "section-calc: error: " + kSource + "/tests/bad-input/materials-malformed.json: malformed JSON: parse error at line 1, column 73: syntax error while parsing object key - unexpected '}'; expected string literal\n"},
        {"--rect 0.1 0.1 --fy 1e8 --length 2", "section-calc: error: --length goes with --elastic\n"},
        {"--rect 0.1 0.1 --fy 1e8 --elastic --length 2", "section-calc: error: --length: the joint stiffness needs E for every material\n"},
        {"--rect 0.1 0.1 --material S355 --elastic --length -2", "section-calc: error: joint stiffness: the segment length must be a positive finite number in m\n"},
        {"--rect 0.1 0.1 --fy 1e8 --tol 1e-6", "section-calc: error: --tol, --order and --max-area go with --method cubature\n"},
        {"--rect 0.1 0.1 --fy 1e8 --method cubature --tol 1e-6 --order 3", "section-calc: error: give --tol (adaptive rule) or --order (fixed rule), not both\n"},
        {"--rect 0.1 0.1 --fy 1e8 --method cubature --tol 1e-20", "section-calc: error: cubature: the tolerance must be between 1e-13 and 0.1 (got 1e-20)\n"},
        {"--rect 0.1 0.1 --fy 1e8 --method cubature --order 0", "section-calc: error: cubature: the order must be a whole number from 1 to 100 (got 0)\n"},
        {"--rect 0.1 0.1 --fy 1e8 --method cubature --max-area -1", "section-calc: error: cubature: the largest triangle area must be a finite number ≥ 0 m² (got -1)\n"},
        {"--rect 0.1 0.1 --fy 1e8 --svg /nonexistent/dir/x.svg", "section-calc: error: --svg /nonexistent/dir/x.svg: cannot write the file (No such file or directory)\n"},
        {"/nonexistent.json", "section-calc: error: /nonexistent.json: cannot open the file\n"},
    };
    for (const auto& c : cases) {
        const CliRun run = section_calc(c.arguments);
        EXPECT_EQ(run.exit_code, 2) << c.arguments;
        EXPECT_EQ(run.err, c.message) << c.arguments;
        EXPECT_EQ(run.out, "") << c.arguments;
    }
    const CliRun unknown_option = section_calc("--frobnicate");
    EXPECT_EQ(unknown_option.exit_code, 2);
    EXPECT_EQ(unknown_option.out, "");
}

// One file per class of bad input: exit 2, one line on stderr naming the file and the problem,
// nothing on stdout.
TEST(SectionCalc, BadInputFiles) {
    const struct {
        const char* file;
        const char* message;
    } cases[] = {
        {"malformed.json", "malformed JSON: parse error at line 1, column 63"},
        {"empty.json", "malformed JSON: parse error at line 1, column 1"},
        {"random-bytes.json", "malformed JSON: parse error at line 1, column 1: syntax error while parsing value - invalid literal; last read: '\\x89'"},
        {"not-an-object.json", "section: expected a JSON object with \"parts\", got array"},
        {"overflowing-number.json", "unreadable JSON: number overflow parsing '1e400'"},
        {"wrong-type.json", "parts[0].outer[1][1]: expected a number, got string"},
        {"unknown-key.json", "parts[0]: unknown key \"hole\""},
        {"missing-material.json", "parts[0]: no material"},
        {"unknown-material-name.json", "material: unknown material \"Unobtainium\" (section-calc --list-materials shows them all)"},
        {"no-parts.json", "section: has no parts"},
        {"too-few-vertices.json", "part 0, outer ring: has 2 distinct vertices; a ring needs at least 3"},
        {"repeated-vertex.json", "part 0, outer ring, vertex 2: repeats vertex 1"},
        {"coordinate-out-of-range.json", "part 0, outer ring, vertex 1: coordinate x = 10000000 m is outside the supported range"},
        {"collinear.json", "part 0, outer ring: has zero area: its vertices are collinear"},
        {"vanishing-area.json", "part 0, outer ring: is only 1e-300 m across"},
        {"self-intersecting.json", "part 0, outer ring, vertex 0: is self-intersecting: edge 0-1 meets edge 2-3"},
        {"hole-outside.json", "part 0, hole 0, vertex 0: lies outside its outer ring"},
        {"hole-crossing.json", "part 0, hole 0, vertex 0: touches or crosses its outer ring (its edge 0-1 meets edge 1-2"},
        {"holes-overlapping.json", "part 0, hole 1, vertex 0: overlaps or touches hole 0 of the same part"},
        {"parts-overlapping.json", "part 1: overlaps part 0"},
        {"negative-yield-stress.json", "material: yield stress fy must be a finite number >= 0 in Pa (got -200000000)"},
        {"zero-yield-stress.json", "parts[0].material: the material has no strength: fy and fc are both 0"},
        {"bar-outside-part.json", "part 0, bar 0: its centre (0.4, 0.05) m lies outside its part"},
        {"bar-across-edge.json", "part 0, bar 0: the bar (radius 0.009997464892 m for its area) crosses its part's edge"},
        {"bars-overlap.json", "part 0, bar 1: overlaps bar 0 (centres 0.01 m apart"},
        {"bar-negative-area.json", "part 0, bar 0: its area must be a positive finite number up to its part's area"},
        {"reinforcement-ratio-out-of-range.json", "parts[0].reinforcement.ratio: must be between 0 and 1"},
        {"unknown-bar-material.json", "parts[0].bars[0].material: unknown material \"B550\" (did you mean B500B?)"},
        {"unknown-shear.json", "shear: unknown shear criterion 'rankine'"},
    };
    for (const auto& c : cases) {
        const std::string path = kSource + "/tests/bad-input/" + c.file;
        const CliRun run = section_calc("\"" + path + "\"");
        EXPECT_EQ(run.exit_code, 2) << c.file;
        EXPECT_EQ(run.out, "") << c.file;
        EXPECT_EQ(run.err.rfind("section-calc: error: " + path + ": ", 0), 0u) << c.file << ": " << run.err;
        EXPECT_NE(run.err.find(c.message), std::string::npos) << c.file << ": " << run.err;
        EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << c.file << ": more than one line: " << run.err;
    }
}

namespace {

// Exit 2, nothing on stdout, one line on stderr that contains `text`.
void expect_refused(const std::string& arguments, const std::string& text) {
    const CliRun run = section_calc(arguments);
    EXPECT_EQ(run.exit_code, 2) << arguments;
    EXPECT_EQ(run.out, "") << arguments;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_NE(run.err.find(text), std::string::npos) << run.err;
}

}  // namespace

// --shape: an IPE 300 in S355 by name; Wpl,y = Mx/fy against the EN 10365 table's 628.4 cm³.
TEST(SectionCalc, ShapeByName) {
    const CliRun run = section_calc("--shape \"IPE300\" --material S355 --json");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out);
    EXPECT_LT(relative_error(j["Mx"].get<double>() / 355e6, 628.4e-6), 5e-4);
    EXPECT_LT(relative_error(j["Mz"].get<double>() / 355e6, 125.2e-6), 5e-4);
    EXPECT_LT(relative_error(j["area"].get<double>(), 53.81e-4), 5e-4);
    const CliRun same = section_calc("--shape \"I 300x150x7.1x10.7 r15\" --fy 355e6 --json");
    ASSERT_EQ(same.exit_code, 0) << same.err;
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(same.out)["Mx"].get<double>(), j["Mx"].get<double>());
    const CliRun table = section_calc("--shape \"HE 200 B\" --fy 235e6 --only N");
    ASSERT_EQ(table.exit_code, 0) << table.err;
    EXPECT_NE(table.out.find("--shape HE 200 B"), std::string::npos) << table.out;
}

TEST(SectionCalc, ShapeErrorsAreOneLine) {
    expect_refused("--shape \"IPE 310\" --material S355", "did you mean IPE 300, IPE 330 or IPE 360?");
    expect_refused("--shape \"IPE 300\"", "--shape needs --material NAME");
    expect_refused("--shape \"I 300x150x7.1x160\" --fy 355e6", "tf = 160 mm must be less than h/2 = 150 mm");
    expect_refused("--shape \"I 300x150x7.1x10.7 r80\" --fy 355e6", "root radius r 80 mm does not fit");
    expect_refused("--shape \"TUBE 100x60\" --fy 355e6", "t = 60 mm must be less than D/2 = 50 mm");
    expect_refused("--shape \"IPE 300\" --fy 355e6 --arc-tolerance 0.5", "between 1e-12 and 1e-2");
    expect_refused("--shape \"IPE 300\" --fy 355e6 --rect 0.1 0.1", "not several");
    expect_refused("--list-shapes XYZ", "unknown shape family \"XYZ\" (known: IPE, HEA");
    expect_refused("--table IPE --shape \"IPE 300\"", "give no FILE, --rect or --shape");
    expect_refused("--csv --shape \"IPE 300\" --fy 1e8", "--csv goes with --table");
}

TEST(SectionCalc, ListShapes) {
    const CliRun text = section_calc("--list-shapes");
    ASSERT_EQ(text.exit_code, 0) << text.err;
    for (const char* name : {"IPE 300", "HEB 1000", "UPE 400", "CHS 168.3x8", "RHS 300x200x10", "L 60x40x5"})
        EXPECT_NE(text.out.find(name), std::string::npos) << name;
    const CliRun json = section_calc("--list-shapes HEB --json");
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const nlohmann::json j = nlohmann::json::parse(json.out);
    ASSERT_EQ(j["families"].size(), 1u);
    EXPECT_EQ(j["families"][0]["shapes"].size(), 24u);
    EXPECT_EQ(j["families"][0]["shapes"][5]["designation"], "HEB 200");
    EXPECT_DOUBLE_EQ(j["families"][0]["shapes"][5]["geometry"]["r"].get<double>(), 0.018);
    EXPECT_DOUBLE_EQ(j["families"][0]["shapes"][5]["published"]["Wpl_y"].get<double>(), 642.5e-6);
}

// --table: one row per shape, as CSV and as JSON; the angles' areas against EN 10056-1.
TEST(SectionCalc, CatalogueTable) {
    const CliRun csv = section_calc("--table L --skip-torsion --csv");
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    EXPECT_EQ(std::count(csv.out.begin(), csv.out.end(), '\n'), 11);
    EXPECT_EQ(csv.out.rfind("designation,A,Ixx,Izz,Wel_x,Wel_z,Wpl_x,Wpl_z,N,Qx,Qz,Mx,Mz,My\n", 0), 0u) << csv.out;
    const CliRun json = section_calc("--table L --json --fy 235e6");
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const nlohmann::json j = nlohmann::json::parse(json.out);
    ASSERT_EQ(j["rows"].size(), 10u);
    EXPECT_EQ(j["rows"][0]["designation"], "L 30x20x3");
    EXPECT_NEAR(j["rows"][0]["A"].get<double>(), 1.43e-4, 0.01e-4);  // EN 10056-1: 1.43 cm²
    EXPECT_GT(j["rows"][0]["J"].get<double>(), 0.0);
    EXPECT_GT(j["rows"][0]["T_p"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j["rows"][0]["N"].get<double>(), 235e6 * j["rows"][0]["A"].get<double>());
}

// "shape" in a section file instead of parts.
TEST(SectionCalc, ShapeInASectionFile) {
    const std::string file = ::testing::TempDir() + "shape_section_" + std::to_string(getpid()) + ".json";
    std::ofstream(file) << R"({"shape": "SHS 200x200x10", "material": "S355", "shear": "tresca"})";
    const CliRun run = section_calc("--json \"" + file + "\"");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out);
    EXPECT_LT(relative_error(j["Mx"].get<double>() / 355e6, 531e-6), 5e-3);  // EN 10210-2: Wpl 531 cm³
    EXPECT_EQ(j["shear"], "tresca");
    std::ofstream(file) << R"({"shape": "SHS 200x200x10", "material": "S355", "parts": []})";
    expect_refused("\"" + file + "\"", "shape: give \"shape\" or \"parts\", not both");
    std::ofstream(file) << R"({"shape": "SHS 210x200x10", "material": "S355"})";
    expect_refused("\"" + file + "\"", "shape: shape \"SHS 210x200x10\": not a known designation");
    std::remove(file.c_str());
}

// --version names the project's version (CMake's project(VERSION)), not a copy of it.
TEST(SectionCalc, VersionIsTheProjects) {
    const CliRun run = section_calc("--version");
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.out, std::string("section-calc (plascap) ") + PLASCAP_VERSION + "\n");
}

namespace plascap {
namespace {

// --load on a 0.2 × 0.3 m rectangle, fy = 355 MPa: n² + m = 1 (closed form) gives U = 1; half of
// that load gives 0.5; the JSON key "utilisation" is a number.
TEST(SectionCalc, LoadUtilisationOfARectangle) {
    const double fy = 355e6, Np = fy * 0.2 * 0.3, Mp = fy * 0.2 * 0.09 / 4;
    char load[200];
    std::snprintf(load, sizeof load, "N=%.17g,Mx=%.17g", 0.5 * Np, 0.75 * Mp);
    CliRun run = section_calc(std::string("--rect 0.2 0.3 --fy 355e6 --json --load ") + load);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    nlohmann::json j = nlohmann::json::parse(run.out);
    EXPECT_NEAR(j["utilisation"].get<double>(), 1.0, 1e-9);
    EXPECT_NEAR(j["load_check"]["surface_point"]["N"].get<double>(), 0.5 * Np, 1e-9 * Np);
    std::snprintf(load, sizeof load, "N=%.17g,Mx=%.17g", 0.25 * Np, 0.375 * Mp);
    run = section_calc(std::string("--rect 0.2 0.3 --fy 355e6 --load ") + load);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("utilisation  0.5"), std::string::npos) << run.out;
    // Torsion: the sand heap's T_p by default, eq. 2.14 with --torsion paper.
    run = section_calc("--rect 0.2 0.3 --fy 355e6 --json --load My=1e4");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    j = nlohmann::json::parse(run.out);
    const double Tp = j["load_check"]["torsion"]["value"].get<double>();
    EXPECT_NEAR(j["utilisation"].get<double>(), 1e4 / Tp, 1e-12);
    // T_p of a b × h rectangle (b ≤ h), τy = fy/2: τy·b²(3h − b)/6 (Nadai's sand heap).
    EXPECT_NEAR(Tp, fy / 2 * 0.04 * (0.9 - 0.2) / 6, 1e-4 * Tp);
    run = section_calc("--rect 0.2 0.3 --fy 355e6 --json --load My=1e4 --torsion paper");
    j = nlohmann::json::parse(run.out);
    EXPECT_EQ(j["load_check"]["torsion"]["capacity"], "paper");
    EXPECT_DOUBLE_EQ(j["load_check"]["torsion"]["value"].get<double>(), j["My"].get<double>());
}

TEST(SectionCalc, InteractionCurvesInJsonAndSvg) {
    const std::string svg = ::testing::TempDir() + "plascap_interaction.svg";
    const CliRun run = section_calc("--shape \"HEB 200\" --material S355 --json --interaction --samples 40 --load N=1e6,Mz=2e4 --svg \"" + svg + "\"");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out);
    ASSERT_EQ(j["interaction"]["N_Mx"].size(), 40u);
    ASSERT_EQ(j["interaction"]["Mx_Mz"]["points"].size(), 40u);
    EXPECT_DOUBLE_EQ(j["interaction"]["Mx_Mz"]["N"].get<double>(), 1e6);
    // The N–Mx curve's point on the N axis is the squash load, and its Mx at N = 0 is Mx.
    EXPECT_NEAR(j["interaction"]["N_Mx"][0][0].get<double>(), j["N"].get<double>(), 1e-9 * j["N"].get<double>());
    EXPECT_NEAR(j["interaction"]["N_Mx"][10][1].get<double>(), j["Mx"].get<double>(), 1e-9 * j["Mx"].get<double>());
    std::stringstream text;
    text << std::ifstream(svg).rdbuf();
    EXPECT_NE(text.str().find("N-Mx (Mz = 0)"), std::string::npos);
    EXPECT_NE(text.str().find("Mx-Mz at N = 1e+06 N"), std::string::npos);
    std::remove(svg.c_str());
}

TEST(SectionCalc, BadLoadsSayWhatIsWrong) {
    const auto message = [](const std::string& args) {
        const CliRun run = section_calc("--rect 0.2 0.3 --fy 355e6 " + args);
        EXPECT_EQ(run.exit_code, 2) << args;
        return run.err;
    };
    EXPECT_NE(message("--load Mq=3").find("unknown component \"Mq\""), std::string::npos);
    EXPECT_NE(message("--load N=abc").find("N = \"abc\" is not a finite number"), std::string::npos);
    EXPECT_NE(message("--load N=1,N=2").find("N is given twice"), std::string::npos);
    EXPECT_NE(message("--load N").find("is not NAME=VALUE"), std::string::npos);
    EXPECT_NE(message("--load N=1 --torsion sand").find("unknown torsion capacity \"sand\""), std::string::npos);
    EXPECT_NE(message("--interaction --load N=2.2e7").find("must lie strictly between"), std::string::npos);
    EXPECT_NE(message("--interaction --samples 3").find("samples must be between 8 and 100000"), std::string::npos);
}

}  // namespace
}  // namespace plascap
