#pragma once
// An ODE body's velocities in plascap's engine-neutral form; the static world (0) does not move.
#include <ode/ode.h>

#include "plascap/adapters/impulse_work.hpp"

namespace plascap {

inline BodyVelocity body_velocity(dBodyID body) {
    if (!body) return {};
    const dReal* v = dBodyGetLinearVel(body);
    const dReal* w = dBodyGetAngularVel(body);
    return {{v[0], v[1], v[2]}, {w[0], w[1], w[2]}};
}

}  // namespace plascap
