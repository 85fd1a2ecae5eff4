// Scenes: a plastic-sim scene (docs/plastic-sim.md) run on any engine, returning the JSON summary
// and the CSV trace that plastic-sim writes (plascap/scenes.py turns them into Python objects and
// NumPy arrays). The run releases the GIL, so threads and dask workers run scenes in parallel.
#include <pybind11/stl.h>

#include <memory>
#include <sstream>

#include "bindings.hpp"
#include "plascap/input_error.hpp"
#include "scene.hpp"
#include "scene_engine.hpp"
#include "simulation.hpp"

namespace plascap::python {
namespace {

Scene load(const std::string& scene, bool is_path) {
    if (is_path) return read_scene_file(scene);
    try {
        return parse_scene_json(scene);
    } catch (const InputError& e) {
        throw InputError(std::string("<scene>: ") + e.what());
    }
}

std::pair<std::string, std::string> run_scene(const std::string& scene_text_or_path, bool is_path, const std::string& engine,
                                              bool trace) {
    const Scene scene = load(scene_text_or_path, is_path);
    const std::unique_ptr<SceneEngine> e = make_engine(engine, scene);
    std::ostringstream csv;
    csv.precision(10);  // as plastic-sim --csv
    SimulationOptions options;
    if (trace) options.trace_csv = &csv;
    // What the engine foresees (ode-step on a large island: hours of dense solves) is a
    // RuntimeWarning before the run, as plastic-sim prints it on stderr: under
    // warnings.simplefilter("error") it stops the run before it starts.
    const py::object warn = py::module_::import("warnings").attr("warn");
    for (const std::string& w : e->warnings()) warn(w, py::handle(PyExc_RuntimeWarning));
    SimulationResult result;
    {
        py::gil_scoped_release release;
        result = run_simulation(scene, *e, options);
    }
    std::ostringstream summary;
    write_json_summary(summary, scene, result, e->description());
    return {summary.str(), csv.str()};
}

}  // namespace

void bind_scenes(py::module_& m) {
    m.def("_run_scene", &run_scene, py::arg("scene"), py::arg("is_path"), py::arg("engine"), py::arg("trace"));
    m.def("engines", &available_engines, "The engines scenes run on: bullet, bullet-spring2, bullet-6dof-spring, ode, ode-step.");
}

}  // namespace plascap::python
