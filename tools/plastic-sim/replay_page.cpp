#include "replay_page.hpp"

#include "html_page.hpp"

namespace plascap {

void write_replay_page(const std::string& path, const Scene& scene, const SimulationResult& result, const ReplayRecorder& replay,
                       const ReplayPageInfo& info) {
    nlohmann::json data = replay.data();
    data["format"] = "plascap-replay";
    data["version"] = 1;
    data["title"] = info.title;
    data["engine"] = info.engine;
    data["scene"] = {{"dt", scene.dt}, {"duration", scene.duration}, {"steps", result.steps}, {"iterations", scene.iterations},
                     {"gravity", scene.gravity}};
    data["budget"] = {{"max_frames", info.budget.max_frames}, {"max_frame_bytes", info.budget.max_frame_bytes}};
    // The end state as --json prints it, but for the bodies (the last frame has them).
    nlohmann::json summary = json_summary(scene, result, info.engine);
    summary.erase("bodies");
    data["summary"] = std::move(summary);
    html::write_page(path, html::Page{html::PageKind::Replay, info.title + " — plastic-sim replay", html::json_text(data)}, "--html");
}

}  // namespace plascap
