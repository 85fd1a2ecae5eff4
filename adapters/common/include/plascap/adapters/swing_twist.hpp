#pragma once
// A joint's relative rotation as swing and twist about its beam axis y, with no singularity short
// of folding the beam back on itself (swing π), where Euler angles have one at a 90° twist.
//   swing: the shortest-arc rotation taking a's y to b's y, as a rotation vector (φx, 0, φz);
//   twist: the angle τ about y that remains, R = S(φ)·Ry(τ) (the swing–twist decomposition, e.g.
//   Dobrowolski, "Swing-twist decomposition in Clifford algebra", 2015).
// The gradients are exact: with Ω the angular velocity of b relative to a in a's frame,
// (φ̇x, τ̇, φ̇z) = (g_x·Ω, g_y·Ω, g_z·Ω), where, with σ = |φ|, h = (1 − σ·cot σ)/σ² and
// t = tan(σ/2)/σ (derived from ḃ_y = Ω × b_y and the angular velocity of an axis–angle rotation,
// ω = σ̇n + sin σ·ṅ + (1 − cos σ)·n × ṅ; checked by finite differences in test_swing_twist):
//   g_x = (1 − h·φz², φz, h·φx·φz),  g_y = (−t·φz, 1, t·φx),  g_z = (h·φx·φz, −φx, 1 − h·φx²).
// A row along g_i therefore applies the generalised force of its own angle: its work is force × Δangle.
#include "plascap/adapters/joint_frame.hpp"

namespace plascap {

struct SwingTwist {
    Vec3 angles{};     // (φx, τ, φz) [rad]; τ in (−π, π]
    Mat3 gradients{};  // rows g_x, g_y, g_z, in a's frame
};

// `b_in_a`: b's frame seen from a's (columns: b's axes in a's coordinates).
SwingTwist swing_twist(const Mat3& b_in_a);

// The joint from the world poses of its frame as carried by a and by b, with swing–twist rotations:
// translations as measure_joint (joint_frame.hpp: components along a's axes of b's anchor minus a's),
// rotations (φx, τ, φz), and each rotation row along its angle's gradient in the world (not of unit
// length): a row along it measures the angle's rate, and a moment decomposed along the three is the
// angles' generalised forces. Every engine adapter whose rows are swing and twist measures with it.
JointFrameState measure_joint_swing_twist(const Pose& frame_on_a, const Pose& frame_on_b);

}  // namespace plascap
