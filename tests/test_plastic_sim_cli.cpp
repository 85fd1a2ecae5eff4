// plastic-sim end to end: every example scene runs, and the numbers the examples stand for hold.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace {

using plascap::test::CliRun;
using Json = nlohmann::json;

const std::string kSource = PLASCAP_SOURCE_DIR;

CliRun plastic_sim(const std::string& arguments) { return plascap::test::run_tool(PLASCAP_PLASTIC_SIM, arguments); }

std::string scene(const std::string& name) { return "\"" + kSource + "/examples/scenes/" + name + "\""; }

Json run_json(const std::string& name, const std::string& engine = "bullet") {
    const CliRun run = plastic_sim("--json --quiet --engine " + engine + " " + scene(name));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    return Json::parse(run.out);
}

TEST(PlasticSim, PaperTensionBlockRestsWithTable35sPlasticElongation) {
    const Json j = run_json("paper-tension-block.json");
    const Json& top = j["joints"]["top"];
    EXPECT_FALSE(top["broken"].get<bool>());
    // Free fall in step 1, then three steps flowing at 80 kN against 60 kN until the block stops:
    // 0.0028 m of plastic flow (Table 3.5: location −0.0028 → −0.0056 m).
    EXPECT_NEAR(top["plastic_displacement"].get<double>(), 0.0027778, 1e-6);
    EXPECT_NEAR(top["dissipated"].get<double>(), 80e3 * top["plastic_displacement"].get<double>(), 1e-6);
    EXPECT_NEAR(j["bodies"]["block"]["velocity"][1].get<double>(), 0.0, 1e-5);
    EXPECT_EQ(top["dofs"]["N"]["regime"], "rigid-plastic");
}

TEST(PlasticSim, CharpyAbsorbsWhatTheAuthorMeasured) {
    // values.md: expected ≈ 122 J (64 N·m × 1.9 rad); the author measured 90–170 J.
    const Json j = run_json("charpy-impact.json");
    const double absorbed = j["joints"]["notch"]["dissipated"].get<double>();
    EXPECT_GT(absorbed, 90.0);
    EXPECT_LT(absorbed, 170.0);
}

TEST(PlasticSim, CantileverYieldsElasticPlasticallyAndReportsItsRegimes) {
    const Json j = run_json("cantilever-bending.json");
    const Json& root = j["joints"]["root"];
    EXPECT_GT(root["plastic_rotation"].get<double>(), 0.05);
    EXPECT_FALSE(root["broken"].get<bool>());
    EXPECT_EQ(root["dofs"]["Mz"]["regime"], "elastic-plastic");
    EXPECT_LT(root["dofs"]["Mz"]["omega_dt"].get<double>(), 0.25);
    EXPECT_EQ(root["dofs"]["My"]["regime"], "stiff: rigid-plastic");  // GJ/L on the arm: ω·dt > 0.25
}

TEST(PlasticSim, StackCollapsesStoreyByStorey) {
    const Json j = run_json("collapsing-stack.json");
    std::vector<double> breaks;
    for (const auto& joint : j["joints"]) {
        if (joint["broken"].get<bool>()) breaks.push_back(joint["broken_at"].get<double>());
    }
    ASSERT_GE(breaks.size(), 2u);
    std::sort(breaks.begin(), breaks.end());
    EXPECT_GT(breaks[1] - breaks[0], 0.1);  // one after another, not at once
}

#ifdef PLASCAP_HAVE_ODE
// Issue 7: every example gives the same plastic deformation, dissipated energy and break times on
// Bullet and ODE (dWorldQuickStep), within a tolerance stated per scene. Built only with ODE.
TEST(PlasticSim, EveryExampleAgreesAcrossBulletAndOde) {
    struct Agreement {
        const char* scene;
        double tolerance;  // on plastic displacement, rotation and dissipated energy, relative to the largest joint's
        const char* why;
    };
    const Agreement agreements[] = {
        {"paper-tension-block.json", 1e-3, "one rigid-plastic row: both engines solve it exactly"},
        {"cantilever-bending.json", 1e-3, "explicit elastic-plastic rows: no solver in the loop"},
        {"collapsing-stack.json", 0.15, "rigid-plastic rows under contact; the first break must match to one step"},
        {"charpy-impact.json", 0.4, "decided by contacts, which the engines model differently (docs/cross-engine.md)"},
    };
    for (const Agreement& a : agreements) {
        const Json bullet = run_json(a.scene, "bullet"), ode = run_json(a.scene, "ode");
        const char* keys[] = {"plastic_displacement", "plastic_rotation", "dissipated"};
        std::map<std::string, double> largest;
        for (const auto& joint : bullet["joints"]) {
            for (const char* key : keys) largest[key] = std::max(largest[key], std::abs(joint[key].get<double>()));
        }
        double first_break = INFINITY;
        for (const auto& joint : bullet["joints"])
            if (joint["broken"].get<bool>()) first_break = std::min(first_break, joint["broken_at"].get<double>());
        for (const auto& [name, joint] : bullet["joints"].items()) {
            const Json& other = ode["joints"][name];
            for (const char* key : keys) {
                const double x = joint[key].get<double>(), y = other[key].get<double>();
                EXPECT_LE(std::abs(x - y), a.tolerance * largest[key])
                    << a.scene << ", " << name << ", " << key << ": bullet " << x << ", ode " << y << " (" << a.why << ")";
            }
            ASSERT_EQ(joint["broken"], other["broken"]) << a.scene << ", " << name;
            if (joint["broken"].get<bool>()) {
                // A broken joint's pieces collide again, and the engines' contacts differ
                // (docs/cross-engine.md): breaks after the first, which follow those contacts, match
                // to 0.3 s (72 steps) only — joint-2 breaks at 1.30 s on bullet, 1.38 s on
                // bullet-spring2 and 1.47 s on ode (docs/cross-engine.md).
                const bool first = joint["broken_at"].get<double>() == first_break;
                const double dt = a.scene == std::string("collapsing-stack.json") ? (first ? 1.0 / 240 : 0.3) : 0.0;
                EXPECT_LE(std::abs(joint["broken_at"].get<double>() - other["broken_at"].get<double>()), dt + 1e-9)
                    << a.scene << ", " << name;
            }
        }
    }
}

#endif

TEST(PlasticSim, CsvTraceHasAHeaderAndOneRowPerStep) {
    const std::string csv = ::testing::TempDir() + "plastic_sim_trace_" + std::to_string(getpid()) + ".csv";
    const CliRun run = plastic_sim("--quiet --csv \"" + csv + "\" " + scene("paper-tension-block.json"));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::ifstream in(csv);
    std::string header, line;
    std::getline(in, header);
    EXPECT_EQ(header.rfind("time,block.x,block.y,block.z,block.vx,block.vy,block.vz,block.qw,block.qx,block.qy,block.qz,"
                           "top.N.force,top.N.offset,", 0), 0u)
        << header;
    int rows = 0;
    std::string last;
    while (std::getline(in, line)) {
        ++rows;
        last = line;
    }
    EXPECT_EQ(rows, 60);
    EXPECT_EQ(last.rfind("1,", 0), 0u) << last;
    std::remove(csv.c_str());
}

TEST(PlasticSim, BadInputExitsTwoWithOneMessageAndNoResult) {
    const std::string bad = ::testing::TempDir() + "plastic_sim_bad_" + std::to_string(getpid()) + ".json";
    std::ofstream(bad) << R"({"dt": 0.01, "duration": 1, "bodies": [{"name": "b", "box": [1, 1, 1], "mass": -3}]})";
    for (const std::string& args : {"\"" + bad + "\"", std::string("/nonexistent/scene.json"), "--engine havok " + scene("paper-tension-block.json"),
                                    std::string("--bogus")}) {
        const CliRun run = plastic_sim(args);
        EXPECT_EQ(run.exit_code, 2) << args;
        EXPECT_EQ(run.out, "") << args;
        EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
        EXPECT_EQ(run.err.rfind("plastic-sim: error: ", 0), 0u) << run.err;
    }
    std::remove(bad.c_str());
}

}  // namespace
