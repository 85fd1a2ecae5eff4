#pragma once
// A Bullet body's velocities in plascap's engine-neutral form.
#include <btBulletDynamicsCommon.h>

#include "plascap/adapters/impulse_work.hpp"

namespace plascap {

inline BodyVelocity body_velocity(const btRigidBody& body) {
    const btVector3& v = body.getLinearVelocity();
    const btVector3& w = body.getAngularVelocity();
    return {{v.x(), v.y(), v.z()}, {w.x(), w.y(), w.z()}};
}

}  // namespace plascap
