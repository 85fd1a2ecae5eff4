#pragma once
// Bullet's vectors and a body's velocities in plascap's engine-neutral form (vec3.hpp).
#include <btBulletDynamicsCommon.h>

#include "plascap/adapters/impulse_work.hpp"
#include "plascap/adapters/vec3.hpp"

namespace plascap {

inline Vec3 to_vec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

inline BodyVelocity body_velocity(const btRigidBody& body) {
    return {to_vec3(body.getLinearVelocity()), to_vec3(body.getAngularVelocity())};
}

}  // namespace plascap
