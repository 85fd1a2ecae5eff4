#pragma once
// The per-step CSV trace: time; each body's position, velocity and orientation (a unit quaternion
// w, x, y, z); each joint's force and plastic
// offset per plastic dof, accumulated plastic displacement and rotation, dissipated energy, broken;
// each node's displacement; the energy ledger (energy_ledger.hpp).
#include <iosfwd>

#include "energy_ledger.hpp"
#include "scene_engine.hpp"

namespace plascap {

void write_trace_header(std::ostream& out, const Scene& scene);
void write_trace_row(std::ostream& out, const Scene& scene, const SceneEngine& engine, const EnergyLedger& energy);

}  // namespace plascap
