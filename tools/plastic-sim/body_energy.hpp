#pragma once
// A scene body's motion for energy ledgers and reports: its kinetic energy ½·m·v² + ½·ωᵀ·I·ω with its
// principal inertia (given, or the box's m(b² + c²)/12, …; any dynamics text, e.g. Meriam & Kraige,
// Table D/4), and where a point of it is.
#include "scene.hpp"
#include "scene_engine.hpp"

namespace plascap {

double kinetic_energy(const SceneBody& body, const BodyState& state);

// The world position of `local` (body frame, from the centre) [m].
Vec3 world_point(const BodyState& state, const Vec3& local);
// The inverse: a world point in the body's frame, from its centre.
Vec3 body_point(const BodyState& state, const Vec3& world);

}  // namespace plascap
