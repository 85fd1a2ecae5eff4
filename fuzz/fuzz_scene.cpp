// libFuzzer target: any bytes through the plastic-sim scene reader. Contract under test: either an
// InputError, or a scene whose every number an engine may use is finite and in range (unit joint
// axes, orthonormal; positive finite masses; valid laws); never a crash, a hang or another
// exception. Build and run: see docs/fuzzing.md.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "plascap/input_error.hpp"
#include "scene.hpp"

namespace {

void require(bool ok) {
    if (!ok) std::abort();
}


void check(const plascap::Scene& s) {
    require(s.dt > 0.0 && std::isfinite(s.duration) && s.steps() >= 1 && s.steps() <= 10000000);
    for (const plascap::SceneBody& b : s.bodies) {
        require(b.mass > 0.0 && std::isfinite(b.mass));
        for (double e : b.size) require(e > 0.0 && std::isfinite(e));
        double q = 0.0;
        for (double c : b.orientation) q += c * c;
        require(std::abs(q - 1.0) < 1e-9);
    }
    for (const plascap::SceneJoint& j : s.joints) {
        require(j.b < s.bodies.size() && (!j.a || (*j.a < s.bodies.size() && *j.a != j.b)));
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t k = 0; k < 3; ++k) require(std::abs(plascap::dot(j.axes[i], j.axes[k]) - (i == k ? 1.0 : 0.0)) < 1e-9);
        }
        plascap::validate_joint_settings(j.settings, j.name);  // throws InputError: not expected here
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    plascap::Scene scene;
    try {
        scene = plascap::parse_scene_json(text);
    } catch (const plascap::InputError&) {
        return 0;  // refused with a message: fine
    }
    try {
        check(scene);
    } catch (const plascap::InputError&) {
        std::abort();  // accepted, then found invalid
    }
    return 0;
}
