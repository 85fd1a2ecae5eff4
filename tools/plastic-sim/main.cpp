// plastic-sim: runs a scene of boxes joined by plastic joints in a physics engine and reports how
// the joints yielded, what they absorbed and when they broke. See docs/plastic-sim.md.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>

#include "plascap/input_error.hpp"
#include "tool_main.hpp"
#include "scene.hpp"
#include "scene_engine.hpp"
#include "simulation.hpp"

namespace {

struct Options {
    std::string scene_file;
    std::string engine = "bullet";
    bool json = false;
    std::string csv;
    bool quiet = false;
    bool list_engines = false;
};

void add_options(CLI::App& app, Options& o) {
    app.add_option("SCENE", o.scene_file, "Scene file (JSON, docs/plastic-sim.md); - reads standard input");
    app.add_option("--engine", o.engine, "Physics engine: bullet (plascap's own Bullet constraint), bullet-spring2 (Bullet's "
                                     "btGeneric6DofSpring2Constraint driven from outside), bullet-6dof-spring (the older "
                                     "btGeneric6DofSpringConstraint), ode (dWorldQuickStep) or ode-step (dWorldStep); see --list-engines")->capture_default_str();
    app.add_flag("--json", o.json, "Print the end state as one JSON object instead of the table");
    app.add_option("--csv", o.csv, "Write a per-step trace to this CSV file (time, bodies, joint forces, plastic "
                                   "offsets, accumulated plastic deformation, dissipated energy, broken)");
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
    const plascap::SimulationResult result = plascap::run_simulation(scene, *engine, options);
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
