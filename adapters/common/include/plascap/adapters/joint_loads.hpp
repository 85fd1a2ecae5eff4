#pragma once
// Engines report a joint's action on a body in the world frame, with the torque about the body's
// centre of mass (Bullet's btJointFeedback, ODE's dJointFeedback). The plastic law needs it per dof
// of the joint frame, with moments about the joint's anchor.
#include <array>

#include "plascap/adapters/dof.hpp"
#include "plascap/adapters/impulse_work.hpp"
#include "plascap/adapters/vec3.hpp"

namespace plascap {

struct WorldLoad {
    Vec3 force{};             // on body b, world frame [N]
    Vec3 torque_about_com{};  // on body b about its centre of mass, world frame [N·m]
};

// The work of a load held over dt on a body moving at `velocity` [J]: (F·v + T·ω)·dt.
inline double held_load_work(const WorldLoad& load, const BodyVelocity& velocity, double dt) {
    return (dot(load.force, velocity.linear) + dot(load.torque_about_com, velocity.angular)) * dt;
}

struct JointAxesInWorld {
    Vec3 anchor{};                      // where the joint acts on b [m]
    std::array<Vec3, 3> translation{};  // unit axes of the Qx, N, Qz rows
    std::array<Vec3, 3> rotation{};     // axes of the Mx, My, Mz rows (unit, or an angle's gradient)
};

// Generalised forces on b per dof: the components of F along the translation axes, and of the
// moment about the anchor, T − r × F with r = anchor − centre of mass (moment transfer; any statics
// text, e.g. Meriam & Kraige §2/6), along the rotation axes. Euler-angle rows (Bullet's Spring2) and
// swing-twist gradient rows have rotation axes that are not orthogonal once the joint has turned, so the moment
// is decomposed in their basis (a 3×3 solve), which gives each row's own moment exactly; a
// degenerate basis (gimbal lock) falls back to projections.
PerDof<double> joint_frame_loads(const WorldLoad& load, const Vec3& centre_of_mass, const JointAxesInWorld& axes);

}  // namespace plascap
