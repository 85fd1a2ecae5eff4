#pragma once
// When each joint of a scene joins its world: at the step starting nearest its engage_at; and when
// a joint is severed: in the step starting nearest its severed_at.
#include <vector>

#include "scene.hpp"

namespace plascap {

class JointSchedule {
public:
    explicit JointSchedule(const Scene& scene) : scene_(scene), engaged_(scene.joints.size(), false) {}
    // The joints to engage before the step that starts at `time`; marks them engaged.
    std::vector<std::size_t> due(double time) {
        std::vector<std::size_t> now;
        for (std::size_t i = 0; i < engaged_.size(); ++i) {
            if (!engaged_[i] && scene_.joints[i].engage_at < time + 0.5 * scene_.dt) {
                engaged_[i] = true;
                now.push_back(i);
            }
        }
        return now;
    }
    bool engaged(std::size_t joint) const { return engaged_[joint]; }

    // The joints to sever in the step that starts at `time` (each once).
    std::vector<std::size_t> severed(double time) {
        std::vector<std::size_t> now;
        for (std::size_t i = 0; i < severed_.size(); ++i) {
            const std::optional<double>& at = scene_.joints[i].severed_at;
            if (!severed_[i] && at && *at < time + 0.5 * scene_.dt) {
                severed_[i] = true;
                now.push_back(i);
            }
        }
        return now;
    }

private:
    const Scene& scene_;
    std::vector<bool> engaged_;
    std::vector<bool> severed_ = std::vector<bool>(scene_.joints.size(), false);
};

}  // namespace plascap
