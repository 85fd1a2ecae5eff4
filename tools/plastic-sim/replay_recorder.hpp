#pragma once
// What plastic-sim --html replays: the run sampled at evenly spaced steps (frames), within a frame
// budget, and encoded compactly for the page (docs/replay.md, "The data"). Every frame stands for
// the steps since the one before: a joint that flowed in any of them shows as yielding.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "energy_ledger.hpp"
#include "scene_engine.hpp"

namespace plascap {

struct ReplayBudget {
    std::size_t max_frames = 600;               // the most frames, the start included
    std::size_t max_frame_bytes = 6'000'000;    // the frames' encoded data before base64 [bytes]
};

// A joint's state in a frame.
enum class ReplayJointState : std::uint8_t { Elastic = 0, Yielding = 1, Broken = 2, NotEngaged = 3 };

class ReplayRecorder {
public:
    // Throws InputError when the budget allows fewer than 2 frames (--html-frames).
    ReplayRecorder(const Scene& scene, ReplayBudget budget);

    void record_start(const SceneEngine& engine, const EnergyLedger& energy);
    // After step number `steps_done` (1, 2, …): records a frame when one falls on it.
    void after_step(std::size_t steps_done, const SceneEngine& engine, const EnergyLedger& energy);

    // The frames and the scene's bodies and joints, as the page reads them.
    nlohmann::json data() const;

private:
    struct Frame {
        double time = 0.0;
        std::vector<float> poses;  // per body: x, y, z, qw, qx, qy, qz
        std::vector<std::uint8_t> states, utilisation;  // per joint; utilisation in hundredths, 255 = 2.55 or more
        std::vector<float> dissipated, plastic_displacement, plastic_rotation;  // per joint [J, m, rad]
        EnergyLedger energy;
    };
    void record(const SceneEngine& engine, const EnergyLedger& energy);

    const Scene& scene_;
    std::vector<std::size_t> frame_steps_;  // after how many steps each frame is taken
    std::size_t next_ = 0;                  // the next frame to take
    std::vector<Frame> frames_;
    std::vector<double> last_plastic_;      // per joint: accumulated plastic deformation at the last frame
};

}  // namespace plascap
