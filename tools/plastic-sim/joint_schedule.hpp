#pragma once
// When each joint of a scene joins its world: at the step starting nearest its engage_at.
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

private:
    const Scene& scene_;
    std::vector<bool> engaged_;
};

}  // namespace plascap
