// Where a Bullet step's time goes on the benchmark's hanging boxes (bullet_hanging_boxes.hpp): Bullet's
// own profile zones (BT_PROFILE, which Debian's Bullet keeps), timed through
// btSetCustomEnterProfileZoneFunc, per step, with how often each ran per step — e.g. the solver's
// iterations (solveSingleIteration), which stop early once Bullet's residual test is met. A profile,
// not a benchmark: the goals live in bench_bullet_joints. Run:
//   build/bench/bullet_step_zones --joints 10000 --springs stiff
// (docs/adapters.md, Bullet, "Springs without rows").
#include <CLI/CLI.hpp>
#include <LinearMath/btQuickprof.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bullet_hanging_boxes.hpp"
#include "plascap/adapters/bullet_plastic_joint.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// The open zones, innermost last, and each finished zone's total time and count by its path.
struct ZoneTimes {
    struct Open {
        const char* name;
        Clock::time_point start;
    };
    std::vector<Open> open;
    struct Total {
        double seconds = 0.0;
        long count = 0;
    };
    std::map<std::string, Total> totals;
    bool recording = false;
};
ZoneTimes zones;

void enter_zone(const char* name) { zones.open.push_back({name, Clock::now()}); }

void leave_zone() {
    if (zones.open.empty()) return;  // a zone entered before the hooks were set
    const ZoneTimes::Open zone = zones.open.back();
    zones.open.pop_back();
    if (!zones.recording) return;
    std::string path;
    for (const ZoneTimes::Open& outer : zones.open) path += std::string(outer.name) + "/";
    ZoneTimes::Total& total = zones.totals[path + zone.name];
    total.seconds += std::chrono::duration<double>(Clock::now() - zone.start).count();
    ++total.count;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Bullet's profile zones per step on the benchmark's hanging boxes"};
    int joints = 10000, steps = 40, warm_up = 20;
    std::string springs = "stiff";
    app.add_option("--joints", joints, "boxes, one joint each")->check(CLI::Range(1, 100000))->capture_default_str();
    app.add_option("--springs", springs,
                   "the plastic joints' springs (hanging_box_springs.hpp): none (six rigid-plastic rows), stiff (four rows, "
                   "two springs), sampled (six springs); or fixed: Bullet's btFixedConstraint on its own solver")
        ->check(CLI::IsMember({"none", "stiff", "sampled", "fixed"}))
        ->capture_default_str();
    app.add_option("--steps", steps, "steps timed")->check(CLI::Range(1, 100000))->capture_default_str();
    app.add_option("--warm-up", warm_up, "steps before the timed ones")->check(CLI::Range(0, 100000))->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    const bool fixed = springs == "fixed";
    bench::HangingBoxes scene(joints, /*split_islands=*/false,
                              fixed ? plascap::BulletSolverKind::Bullet : plascap::BulletSolverKind::Plascap);
    std::unique_ptr<bench::FixedJoints> fixed_joints;
    std::vector<std::unique_ptr<plascap::BulletPlasticJoint>> plastic_joints;
    if (fixed) {
        fixed_joints = std::make_unique<bench::FixedJoints>(scene);
    } else {
        const bench::Springs kind = springs == "none" ? bench::Springs::None
                                    : springs == "stiff" ? bench::Springs::Stiff
                                                         : bench::Springs::Sampled;
        for (int i = 0; i < joints; ++i) {
            plastic_joints.push_back(std::make_unique<plascap::BulletPlasticJoint>(nullptr, scene.boxes[i]->body(), scene.anchor(i),
                                                                                   bench::all_six_plastic(kind)));
            plastic_joints.back()->attach(scene.world.world(), bench::kDt);
        }
    }
    btSetCustomEnterProfileZoneFunc(enter_zone);
    btSetCustomLeaveProfileZoneFunc(leave_zone);
    for (int i = 0; i < warm_up; ++i) scene.world.step(bench::kDt);
    zones.recording = true;
    const auto start = Clock::now();
    for (int i = 0; i < steps; ++i) scene.world.step(bench::kDt);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    zones.recording = false;

    std::printf("%d joints (%s), %d steps after %d: %.3f ms a step\n", joints, springs.c_str(), steps, warm_up, 1e3 * seconds / steps);
    std::printf("%10s %8s  zone\n", "ms/step", "n/step");
    for (const auto& [path, total] : zones.totals)
        std::printf("%10.3f %8.2f  %s\n", 1e3 * total.seconds / steps, static_cast<double>(total.count) / steps, path.c_str());
    plastic_joints.clear();  // each joint leaves the world as it is destroyed
    return 0;
}
