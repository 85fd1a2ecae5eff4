#pragma once
// Every scene's energy ledger: kinetic, gravitational, elastic (in the joints' springs), dissipated
// in plastic flow, the work of the external loads, and the remainder — what the contacts and the
// solver added or took. A joint that creates energy shows as a positive remainder.
#include <vector>

#include "scene_engine.hpp"

namespace plascap {

struct EnergyLedger {
    double kinetic = 0.0;        // Σ ½mv² + ½ωᵀIω [J]
    double gravitational = 0.0;  // Σ −m·g·(x − x₀) [J]
    double elastic = 0.0;        // Σ ½k(x − x_p)² over the springs [J]
    double dissipated = 0.0;     // Σ over the joints [J]
    double external_work = 0.0;  // Σ over the loads of F·Δx + M·Δθ [J]
    double initial = 0.0;        // the kinetic energy at the start [J]
    double corrections = 0.0;    // of the remainder, what the engine's split-impulse position corrections did: their
                                 // work against loads and gravity, and the dissipation booked on flow they drove [J]
    double contacts = 0.0;       // of the remainder, the work the contacts did (impacts, friction: negative) [J]
    // Of the remainder, the joints' rows' work on their bodies less what the laws booked (elastic energy,
    // dissipation not driven by corrections): negative where rows gave way or stopped a motion at once
    // (solver slack), positive where a joint created energy [J].
    double joints_unbooked = 0.0;
    double handled = 0.0;        // the largest of the terms' magnitudes so far [J]: the scale of the remainder
    // kinetic + gravitational + elastic + dissipated − external work − initial [J].
    double remainder() const { return kinetic + gravitational + elastic + dissipated - external_work - initial; }
};

// A load as applied for one step: where and how much, so that its work can be booked after it.
struct AppliedLoad {
    std::size_t body = 0;
    Vec3 local{};   // the point, in the body's frame
    Vec3 point{};   // the point in the world before the step
    Vec3 force{}, moment{};
};

// One joint's share of joints_unbooked [J] (0 before it takes hold); `elastic` is its elastic energy now.
double unbooked_work(const PlasticJointLaw& law, double elastic, double rows_work);
double unbooked_work(SceneEngine& engine, std::size_t joint);

// Applies every scene load at the engine's time (its history factor then), for the next step.
std::vector<AppliedLoad> apply_scene_loads(const Scene& scene, SceneEngine& engine);

class EnergyAccount {
public:
    EnergyAccount(const Scene& scene, const SceneEngine& engine);
    // After a step: the terms now, and the work the loads applied for it did (F·Δx of their
    // material points, M·ω·dt).
    void after_step(SceneEngine& engine, const std::vector<AppliedLoad>& loads);
    const EnergyLedger& ledger() const { return ledger_; }

private:
    const Scene& scene_;
    std::vector<Vec3> start_;  // the bodies' centres at the start
    EnergyLedger ledger_;
};

}  // namespace plascap
