// plastic-sim: runs a scene of boxes joined by plastic joints in a physics engine and reports how
// the joints yielded, what they absorbed and when they broke. See docs/plastic-sim.md.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <iostream>

#include "plascap/input_error.hpp"
#include "tool_main.hpp"
#include "scene.hpp"
#include "scene_engine.hpp"
#include "replay_page.hpp"
#include "simulation.hpp"

namespace {

struct Options {
    std::string scene_file;
    std::string engine = "bullet";
    bool json = false;
    std::string csv;
    std::string html;
    std::size_t html_frames = plascap::ReplayBudget{}.max_frames;
    bool quiet = false;
    bool list_engines = false;
};

void add_options(CLI::App& app, Options& o) {
    app.add_option("SCENE", o.scene_file, "Scene file (JSON, docs/plastic-sim.md); - reads standard input");
    app.add_option("--engine", o.engine, "Physics engine: bullet (plascap's own Bullet constraint), bullet-spring2 (Bullet's "
                                     "btGeneric6DofSpring2Constraint driven from outside), bullet-6dof-spring (the older "
                                     "btGeneric6DofSpringConstraint), ode (dWorldQuickStep, its rows warm-started and their position corrections split off) or ode-step (dWorldStep); see --list-engines")->capture_default_str();
    app.add_flag("--json", o.json, "Print the end state as one JSON object instead of the table");
    app.add_option("--csv", o.csv, "Write a per-step trace to this CSV file (time, bodies, joint forces, plastic "
                                   "offsets, accumulated plastic deformation, dissipated energy, broken)");
    app.add_option("--html", o.html, "Write a self-contained page that replays the run in 3-D, with the joints' states and "
                                     "the energy ledger over time (opens from disk; docs/replay.md)");
    app.add_option("--html-frames", o.html_frames, "With --html: the most frames the page holds, the start included, 2 to "
                                                   "100000; fewer when the scene is large (6 MB of frame data at most)")
        ->capture_default_str();
    app.add_flag("--quiet", o.quiet, "No progress lines on standard error");
    app.add_flag("--list-engines", o.list_engines, "List the engines this build has and exit");
    app.set_version_flag("--version", "plastic-sim " PLASCAP_VERSION);
}

plascap::Scene load(const std::string& file) {
    if (file != "-") return plascap::read_scene_file(file);
    std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    try {
        return plascap::parse_scene_json(text);
    } catch (const plascap::InputError& e) {
        throw plascap::InputError(std::string("<stdin>: ") + e.what());
    }
}

int run(const Options& o) {
    if (o.list_engines) {
        for (const std::string& name : plascap::available_engines()) std::cout << name << '\n';
        return 0;
    }
    if (o.scene_file.empty()) throw plascap::InputError("no scene file given (see --help)");
    const plascap::Scene scene = load(o.scene_file);
    const std::unique_ptr<plascap::SceneEngine> engine = plascap::make_engine(o.engine, scene);
    std::ofstream csv;
    plascap::SimulationOptions options;
    if (!o.csv.empty()) {
        csv.open(o.csv);
        if (!csv) throw plascap::InputError("--csv " + o.csv + ": cannot be written");
        csv.precision(10);
        options.trace_csv = &csv;
    }
    if (!o.quiet) options.progress = &std::cerr;
    if (o.html.empty() && o.html_frames != plascap::ReplayBudget{}.max_frames) throw plascap::InputError("--html-frames goes with --html");
    if (o.html_frames < 2 || o.html_frames > 100000)
        throw plascap::InputError("--html-frames " + std::to_string(o.html_frames) + ": expected 2 to 100000");
    plascap::ReplayBudget budget;
    budget.max_frames = o.html_frames;
    std::optional<plascap::ReplayRecorder> replay;
    if (!o.html.empty()) {
        std::ofstream probe(o.html);  // refuse an unwritable path before the run, not after it
        if (!probe) throw plascap::InputError("--html " + o.html + ": cannot be written");
        options.replay = &replay.emplace(scene, budget);
    }
    const plascap::SimulationResult result = plascap::run_simulation(scene, *engine, options);
    if (replay) {
        const std::string title = o.scene_file == "-" ? "standard input" : std::filesystem::path(o.scene_file).filename().string();
        plascap::write_replay_page(o.html, scene, result, *replay, {title, engine->description(), budget});
    }
    if (o.json) {
        plascap::write_json_summary(std::cout, scene, result, engine->description());
    } else {
        plascap::write_text_summary(std::cout, scene, result, engine->description());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"plastic-sim: run a scene of bodies joined by plastic joints (docs/plastic-sim.md)"};
    Options options;
    add_options(app, options);
    return plascap::tool_main("plastic-sim", app, argc, argv, [&] { return run(options); });
}
