#include "plascap/adapters/swing_twist.hpp"

#include <cmath>

namespace plascap {
namespace {

// Below this swing the closed forms of h and t lose digits to cancellation; their series are
// exact there to ~σ⁴ (σ·cot σ = 1 − σ²/3 − σ⁴/45 − …, tan(σ/2)/σ = 1/2 + σ²/24 + …).
constexpr double kSmallSwing = 1e-2;

}  // namespace

SwingTwist swing_twist(const Mat3& r) {
    const Vec3 b_y = {r[0][1], r[1][1], r[2][1]}, b_x = {r[0][0], r[1][0], r[2][0]};
    // b_y is a unit vector: its x–z part cannot overflow, and needs no std::hypot.
    const double sin_swing = std::sqrt(b_y[0] * b_y[0] + b_y[2] * b_y[2]), cos_swing = b_y[1];
    const double swing = std::atan2(sin_swing, cos_swing);
    // n = y × b_y / |y × b_y|, the swing axis (any axis in x–z when there is no swing).
    const Vec3 n = sin_swing > 0.0 ? Vec3{b_y[2] / sin_swing, 0.0, -b_y[0] / sin_swing} : Vec3{1.0, 0.0, 0.0};
    SwingTwist st;
    const double phi_x = swing * n[0], phi_z = swing * n[2];
    // Sᵀ·b_x = Ry(τ)·x = (cos τ, 0, −sin τ): b_x turned back about n by the swing (Rodrigues).
    const Vec3 n_cross = cross(n, b_x);
    const double along = dot(n, b_x);
    const double back_x = b_x[0] * cos_swing - sin_swing * n_cross[0] + (1.0 - cos_swing) * along * n[0];
    const double back_z = b_x[2] * cos_swing - sin_swing * n_cross[2] + (1.0 - cos_swing) * along * n[2];
    st.angles = {phi_x, std::atan2(-back_z, back_x), phi_z};

    const double s2 = swing * swing;
    const double h = swing < kSmallSwing ? 1.0 / 3.0 + s2 / 45.0 : (1.0 - swing * cos_swing / sin_swing) / s2;
    // tan(σ/2) = (1 − cos σ) / sin σ (the half-angle identity), from the sine and cosine at hand; this
    // form keeps its digits as σ → π (where 1 + cos σ would cancel), and below kSmallSwing the series serves.
    const double t = swing < kSmallSwing ? 0.5 + s2 / 24.0 : (1.0 - cos_swing) / (sin_swing * swing);
    st.gradients = {{{1.0 - h * phi_z * phi_z, phi_z, h * phi_x * phi_z},
                     {-t * phi_z, 1.0, t * phi_x},
                     {h * phi_x * phi_z, -phi_x, 1.0 - h * phi_x * phi_x}}};
    return st;
}

JointFrameState measure_joint_swing_twist(const Pose& frame_on_a, const Pose& frame_on_b) {
    const Pose b_in_a = relative(frame_on_a, frame_on_b);
    const SwingTwist st = swing_twist(b_in_a.rotation);
    const Mat3& a = frame_on_a.rotation;  // rows; its columns are a's axes in the world
    JointFrameState s;
    for (std::size_t i = 0; i < 3; ++i) {
        s.positions[i] = b_in_a.origin[i];
        s.positions[i + 3] = st.angles[i];
        s.axes.translation[i] = {a[0][i], a[1][i], a[2][i]};
        const Vec3& g = st.gradients[i];  // in a's frame: to the world
        s.axes.rotation[i] = {dot(a[0], g), dot(a[1], g), dot(a[2], g)};
    }
    s.axes.anchor = frame_on_b.origin;
    return s;
}

}  // namespace plascap
