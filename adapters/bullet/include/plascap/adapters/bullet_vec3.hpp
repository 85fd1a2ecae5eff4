#pragma once
// Bullet's vectors, transforms and a body's velocities in plascap's engine-neutral form (vec3.hpp,
// joint_frame.hpp), both ways.
#include <btBulletDynamicsCommon.h>

#include "plascap/adapters/impulse_work.hpp"
#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/vec3.hpp"

namespace plascap {

inline Vec3 to_vec3(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

inline btVector3 to_bt(const Vec3& v) { return {btScalar(v[0]), btScalar(v[1]), btScalar(v[2])}; }

inline Pose to_pose(const btTransform& t) {
    const btMatrix3x3& r = t.getBasis();
    return {to_vec3(t.getOrigin()), {to_vec3(r[0]), to_vec3(r[1]), to_vec3(r[2])}};  // rows
}

// A joint frame (origin the anchor, rotation's columns the joint's x, y, z) as BulletPlasticJoint takes it.
inline btTransform to_transform(const Pose& p) {
    const Mat3& r = p.rotation;  // rows
    return btTransform(btMatrix3x3(r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2]), to_bt(p.origin));
}

inline BodyVelocity body_velocity(const btRigidBody& body) {
    return {to_vec3(body.getLinearVelocity()), to_vec3(body.getAngularVelocity())};
}

}  // namespace plascap
