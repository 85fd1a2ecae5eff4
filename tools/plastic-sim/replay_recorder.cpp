#include "replay_recorder.hpp"

#include <algorithm>
#include <boost/archive/iterators/base64_from_binary.hpp>
#include <boost/archive/iterators/transform_width.hpp>
#include <cmath>
#include <cstdio>
#include <limits>

#include "body_energy.hpp"
#include "plascap/input_error.hpp"

namespace plascap {
namespace {

// The bytes of a frame: 7 int16 per body, and per joint its state, utilisation and three uint16.
std::size_t frame_bytes(const Scene& scene) { return scene.bodies.size() * 14 + scene.joints.size() * 8; }

// RFC 4648 base64 (Boost.Serialization's iterators; the input padded to whole 3-byte groups).
std::string base64(std::vector<std::uint8_t> bytes) {
    using namespace boost::archive::iterators;
    using Encoder = base64_from_binary<transform_width<std::vector<std::uint8_t>::const_iterator, 6, 8>>;
    const std::size_t pad = (3 - bytes.size() % 3) % 3;
    bytes.resize(bytes.size() + pad, 0);
    std::string out(Encoder(bytes.cbegin()), Encoder(bytes.cend()));
    for (std::size_t i = 0; i < pad; ++i) out[out.size() - 1 - i] = '=';
    return out;
}

void put_int16(std::vector<std::uint8_t>& out, long value) {  // little-endian, as the page's DataView reads it
    const long v = std::clamp(value, -32767L, 32767L);
    const auto u = static_cast<std::uint16_t>(static_cast<std::int16_t>(v));
    out.push_back(static_cast<std::uint8_t>(u & 0xff));
    out.push_back(static_cast<std::uint8_t>(u >> 8));
}

// Six significant digits: enough for a plot, a third of the text of a double.
double rounded(double v) {
    if (!std::isfinite(v)) return 0.0;
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return std::strtod(text, nullptr);
}

// Non-negative values per joint and frame as uint16 of their largest: {"scale", "data"}.
nlohmann::json quantised(const std::vector<std::vector<float>>& per_frame) {
    double largest = 0.0;
    for (const auto& f : per_frame)
        for (float v : f) largest = std::max(largest, static_cast<double>(v));
    const double scale = largest > 0.0 ? largest / 65535.0 : 1.0;
    std::vector<std::uint8_t> bytes;
    for (const auto& f : per_frame) {
        for (float v : f) {
            const auto q = static_cast<std::uint16_t>(std::clamp(std::lround(v / scale), 0L, 65535L));
            bytes.push_back(static_cast<std::uint8_t>(q & 0xff));
            bytes.push_back(static_cast<std::uint8_t>(q >> 8));
        }
    }
    return {{"scale", scale}, {"data", base64(std::move(bytes))}};
}

nlohmann::json dofs_json(const SceneJoint& joint) {
    nlohmann::json dofs = nlohmann::json::array();
    for (Dof dof : kAllDofs) {
        const DofMode mode = joint.settings.modes[index(dof)];
        if (mode == DofMode::Free) continue;
        nlohmann::json d = {{"dof", dof_name(dof)}, {"mode", dof_mode_name(mode)}};
        if (mode == DofMode::Plastic) {
            const DofLaw& law = joint.settings.laws[index(dof)];
            d["capacity_positive"] = rounded(law.capacity_positive);
            d["capacity_negative"] = rounded(law.capacity_negative);
            d["stiffness"] = law.stiffness ? nlohmann::json(rounded(*law.stiffness)) : nlohmann::json(nullptr);
        }
        dofs.push_back(d);
    }
    return dofs;
}

nlohmann::json limit(double v) { return std::isfinite(v) ? nlohmann::json(rounded(v)) : nlohmann::json(nullptr); }

nlohmann::json rounded(const Vec3& v) { return {rounded(v[0]), rounded(v[1]), rounded(v[2])}; }

}  // namespace

ReplayRecorder::ReplayRecorder(const Scene& scene, ReplayBudget budget) : scene_(scene), last_plastic_(scene.joints.size(), 0.0) {
    const std::size_t by_bytes = budget.max_frame_bytes / std::max<std::size_t>(1, frame_bytes(scene));
    const std::size_t frames = std::min(budget.max_frames, by_bytes);
    if (frames < 2)
        throw InputError("--html: " + std::to_string(scene.bodies.size()) + " bodies and " + std::to_string(scene.joints.size()) +
                         " joints leave room for fewer than 2 frames in the page's budget");
    const std::size_t steps = scene.steps();
    const std::size_t sampled = std::min(steps, frames - 1);  // frames after the start
    frame_steps_.push_back(0);
    for (std::size_t k = 1; k <= sampled; ++k)  // evenly spaced, the last step last
        frame_steps_.push_back((k * steps + sampled / 2) / sampled);
}

void ReplayRecorder::record_start(const SceneEngine& engine, const EnergyLedger& energy) {
    next_ = 0;
    frames_.clear();
    record(engine, energy);
}

void ReplayRecorder::after_step(std::size_t steps_done, const SceneEngine& engine, const EnergyLedger& energy) {
    if (next_ < frame_steps_.size() && frame_steps_[next_] == steps_done) record(engine, energy);
}

void ReplayRecorder::record(const SceneEngine& engine, const EnergyLedger& energy) {
    Frame f;
    f.time = engine.time();
    f.energy = energy;
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
        const BodyState s = engine.body(i);
        for (double v : s.position) f.poses.push_back(static_cast<float>(v));
        for (double v : s.orientation) f.poses.push_back(static_cast<float>(v));
    }
    for (std::size_t j = 0; j < scene_.joints.size(); ++j) {
        const PlasticJointLaw* law = engine.joint_law(j);
        ReplayJointState state = ReplayJointState::NotEngaged;
        double u = 0.0, plastic = 0.0;
        if (law) {
            plastic = law->plastic_displacement() + law->plastic_rotation();
            u = law->utilisation();
            // Yielding: it flowed in a step since the last frame, or sits at its capacity now.
            const bool flowed = plastic > last_plastic_[j] || law->at_capacity();
            state = law->broken() ? ReplayJointState::Broken : flowed ? ReplayJointState::Yielding : ReplayJointState::Elastic;
        }
        last_plastic_[j] = plastic;
        f.states.push_back(static_cast<std::uint8_t>(state));
        f.utilisation.push_back(static_cast<std::uint8_t>(std::isfinite(u) ? std::clamp(std::lround(100.0 * u), 0L, 255L) : 255));
        f.dissipated.push_back(static_cast<float>(law ? law->dissipated() : 0.0));
        f.plastic_displacement.push_back(static_cast<float>(law ? law->plastic_displacement() : 0.0));
        f.plastic_rotation.push_back(static_cast<float>(law ? law->plastic_rotation() : 0.0));
    }
    frames_.push_back(std::move(f));
    ++next_;
}

nlohmann::json ReplayRecorder::data() const {
    nlohmann::json d;
    d["outlines"] = nlohmann::json::array();
    for (const SectionOutline& outline : scene_.outlines) {
        nlohmann::json parts = nlohmann::json::array();
        for (const OutlinePart& p : outline) parts.push_back({{"outer", p.outer}, {"holes", p.holes}});
        d["outlines"].push_back(parts);
    }
    d["bodies"] = nlohmann::json::array();
    for (const SceneBody& b : scene_.bodies) {
        d["bodies"].push_back({{"name", b.name}, {"size", rounded(b.size)}, {"mass", rounded(b.mass)}, {"static", b.is_static},
                               {"outline", b.outline ? nlohmann::json(*b.outline) : nlohmann::json(nullptr)}});
    }
    d["joints"] = nlohmann::json::array();
    for (const SceneJoint& j : scene_.joints) {
        // Drawn at the anchor as carried by body b (its initial pose places it in b's frame).
        BodyState start;
        start.position = scene_.bodies[j.b].position;
        start.orientation = scene_.bodies[j.b].orientation;
        d["joints"].push_back({{"name", j.name},
                               {"a", j.a ? nlohmann::json(*j.a) : nlohmann::json(nullptr)},
                               {"b", j.b},
                               {"anchor_in_b", rounded(body_point(start, j.anchor))},
                               {"coupled", j.settings.yield_condition != nullptr},
                               {"max_plastic_displacement", limit(j.settings.max_plastic_displacement)},
                               {"max_plastic_rotation", limit(j.settings.max_plastic_rotation)},
                               {"dofs", dofs_json(j)}});
    }

    // Positions as int16 about the middle of everything the bodies swept, quaternions as int16/32767.
    std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const Frame& f : frames_)
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i)
            for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], double(f.poses[7 * i + c])), hi[c] = std::max(hi[c], double(f.poses[7 * i + c]));
    std::array<double, 3> centre{}, scale{1, 1, 1};
    for (int c = 0; c < 3 && !scene_.bodies.empty(); ++c) {
        centre[c] = 0.5 * (lo[c] + hi[c]);
        if (hi[c] > lo[c]) scale[c] = 0.5 * (hi[c] - lo[c]) / 32767.0;
    }
    std::vector<std::uint8_t> poses, states, utilisation;
    std::vector<std::vector<float>> dissipated, displacement, rotation;
    nlohmann::json time = nlohmann::json::array();
    nlohmann::json energy = {{"kinetic", nlohmann::json::array()}, {"gravitational", nlohmann::json::array()},
                             {"elastic", nlohmann::json::array()}, {"dissipated", nlohmann::json::array()},
                             {"external_work", nlohmann::json::array()}, {"remainder", nlohmann::json::array()},
                             {"corrections", nlohmann::json::array()}, {"contacts", nlohmann::json::array()},
                             {"joints_unbooked", nlohmann::json::array()}};
    for (const Frame& f : frames_) {
        time.push_back(rounded(f.time));
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
            for (int c = 0; c < 3; ++c) put_int16(poses, std::lround((f.poses[7 * i + c] - centre[c]) / scale[c]));
            for (int c = 3; c < 7; ++c) put_int16(poses, std::lround(f.poses[7 * i + c] * 32767.0));
        }
        states.insert(states.end(), f.states.begin(), f.states.end());
        utilisation.insert(utilisation.end(), f.utilisation.begin(), f.utilisation.end());
        dissipated.push_back(f.dissipated);
        displacement.push_back(f.plastic_displacement);
        rotation.push_back(f.plastic_rotation);
        const EnergyLedger& e = f.energy;
        energy["kinetic"].push_back(rounded(e.kinetic));
        energy["gravitational"].push_back(rounded(e.gravitational));
        energy["elastic"].push_back(rounded(e.elastic));
        energy["dissipated"].push_back(rounded(e.dissipated));
        energy["external_work"].push_back(rounded(e.external_work));
        energy["remainder"].push_back(rounded(e.remainder()));
        energy["corrections"].push_back(rounded(e.corrections));
        energy["contacts"].push_back(rounded(e.contacts));
        energy["joints_unbooked"].push_back(rounded(e.joints_unbooked));
    }
    d["frames"] = {{"count", frames_.size()},
                   {"steps", frame_steps_},
                   {"time", time},
                   {"poses", {{"centre", centre}, {"scale", scale}, {"quaternion_scale", 1.0 / 32767.0}, {"data", base64(std::move(poses))}}},
                   {"joint_states", base64(std::move(states))},
                   {"joint_utilisation", base64(std::move(utilisation))},
                   {"joint_dissipated", quantised(dissipated)},
                   {"joint_plastic_displacement", quantised(displacement)},
                   {"joint_plastic_rotation", quantised(rotation)}};
    d["energy"] = energy;
    return d;
}

}  // namespace plascap
