#pragma once
// The kinetic energy of a scene's box body, for energy ledgers: ½·m·v² + ½·ωᵀ·I·ω with the box's
// principal inertia m(b² + c²)/12, … (any dynamics text, e.g. Meriam & Kraige, Table D/4).
#include "scene.hpp"
#include "scene_engine.hpp"

namespace plascap {

double kinetic_energy(const SceneBody& body, const BodyState& state);

}  // namespace plascap
