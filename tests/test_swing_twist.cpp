// The swing–twist measure of a joint's rotation (swing_twist.hpp): its angles for rotations whose
// decomposition is known by construction, its gradients against finite differences of the angles
// themselves, and no jump where Euler angles have one (a 90° twist); and the joint measured from two
// bodies' world poses (measure_joint_swing_twist, what the Bullet and ODE rows act along).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "plascap/adapters/swing_twist.hpp"

namespace plascap {
namespace {

// Rodrigues: the rotation by `angle` about the unit `axis`.
Mat3 rotation(Vec3 axis, double angle) {
    axis = normalised(axis);
    const double c = std::cos(angle), s = std::sin(angle), C = 1.0 - c;
    const double x = axis[0], y = axis[1], z = axis[2];
    return {{{c + x * x * C, x * y * C - z * s, x * z * C + y * s},
             {y * x * C + z * s, c + y * y * C, y * z * C - x * s},
             {z * x * C - y * s, z * y * C + x * s, c + z * z * C}}};
}

Mat3 times(const Mat3& a, const Mat3& b) {
    Mat3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return m;
}

TEST(SwingTwist, RecoversTheSwingVectorAndTheTwistItWasBuiltFrom) {
    // R = S(φ)·Ry(τ) with φ in the x–z plane: the measure returns (φx, τ, φz), twists past 90° too.
    for (const double tau : {0.0, 0.7, 1.5707963267948966, 2.4, -3.0}) {
        for (const Vec3 phi : {Vec3{0.3, 0, 0}, Vec3{0, 0, -0.8}, Vec3{1.1, 0, 0.9}, Vec3{1e-7, 0, 2e-7}}) {
            const Mat3 r = times(rotation(phi, norm(phi)), rotation({0, 1, 0}, tau));
            const SwingTwist st = swing_twist(r);
            EXPECT_NEAR(st.angles[0], phi[0], 1e-12) << "tau " << tau;
            EXPECT_NEAR(st.angles[1], tau, 1e-12) << "phi " << phi[0] << ", " << phi[2];
            EXPECT_NEAR(st.angles[2], phi[2], 1e-12) << "tau " << tau;
        }
    }
}

TEST(SwingTwist, GradientsAreTheAnglesRatesUnderARelativeAngularVelocity) {
    // A small turn δ about a's axis k moves the angles by δ·(g_x[k], g_y[k], g_z[k]) (central
    // differences, error O(δ²)); random rotations up to a 2.5 rad swing and any twist.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), swing(0.0, 2.5), twist(-3.1, 3.1);
    const double delta = 1e-6;
    double worst = 0.0;
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 axis = {unit(random), 0.0, unit(random)};
        const Mat3 r = times(rotation(axis, swing(random)), rotation({0, 1, 0}, twist(random)));
        const SwingTwist st = swing_twist(r);
        for (int k = 0; k < 3; ++k) {
            Vec3 e{};
            e[k] = 1.0;
            const SwingTwist ahead = swing_twist(times(rotation(e, delta), r));
            const SwingTwist behind = swing_twist(times(rotation(e, -delta), r));
            for (int i = 0; i < 3; ++i) {
                const double step = std::remainder(ahead.angles[i] - behind.angles[i], 2.0 * std::acos(-1.0));
                worst = std::max(worst, std::abs(step / (2.0 * delta) - st.gradients[i][k]));
            }
        }
    }
    EXPECT_LT(worst, 1e-6);
}

TEST(SwingTwist, TwistingThroughNinetyDegreesUnderABendIsSmooth) {
    // A 0.3 rad bend about x, twisted from 0 to 3 rad in steps of 0.01: the swing stays put and the
    // twist follows, with no branch jump at 90° (where R = Rz·Ry·Rx's θy is singular).
    double last_twist = 0.0;
    for (int n = 0; n <= 300; ++n) {
        const double tau = 0.01 * n;
        const SwingTwist st = swing_twist(times(rotation({1, 0, 0}, 0.3), rotation({0, 1, 0}, tau)));
        EXPECT_NEAR(st.angles[0], 0.3, 1e-12);
        EXPECT_NEAR(st.angles[2], 0.0, 1e-12);
        if (n > 0) {
            EXPECT_NEAR(st.angles[1] - last_twist, 0.01, 1e-12) << "at twist " << tau;
        }
        last_twist = st.angles[1];
    }
}

TEST(SwingTwist, JointMeasuredFromWorldPosesHasRowsAlongTheAnglesWorldGradients) {
    // Frames a and b anywhere in the world (the joint's frame as each body carries it): the positions
    // are b's anchor seen from a and the swing and twist of b seen from a; turning b by a small δ
    // about a world axis k moves each angle by δ·(its row's axis)[k] (central differences), which is
    // what a row along that axis measures, whatever a's own orientation.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), angle(0.0, 2.5), twist(-3.1, 3.1);
    const double delta = 1e-6;
    double worst_rate = 0.0, worst_position = 0.0;
    for (int trial = 0; trial < 100; ++trial) {
        Pose a, b;
        a.rotation = rotation({unit(random), unit(random), unit(random)}, angle(random));
        a.origin = {unit(random), unit(random), unit(random)};
        const Mat3 b_in_a = times(rotation({unit(random), 0.0, unit(random)}, angle(random)), rotation({0, 1, 0}, twist(random)));
        b.rotation = times(a.rotation, b_in_a);
        b.origin = {unit(random), unit(random), unit(random)};
        const JointFrameState s = measure_joint_swing_twist(a, b);
        const SwingTwist direct = swing_twist(b_in_a);
        for (int i = 0; i < 3; ++i) {
            const Vec3 offset = difference(b.origin, a.origin);
            const double along = offset[0] * a.rotation[0][i] + offset[1] * a.rotation[1][i] + offset[2] * a.rotation[2][i];
            worst_position = std::max({worst_position, std::abs(s.positions[i] - along),
                                       std::abs(s.positions[i + 3] - direct.angles[i])});
        }
        for (int k = 0; k < 3; ++k) {
            Vec3 e{};
            e[k] = 1.0;
            Pose ahead = b, behind = b;
            ahead.rotation = times(rotation(e, delta), b.rotation);
            behind.rotation = times(rotation(e, -delta), b.rotation);
            const JointFrameState sa = measure_joint_swing_twist(a, ahead), sb = measure_joint_swing_twist(a, behind);
            for (int i = 0; i < 3; ++i) {
                const double step = std::remainder(sa.positions[i + 3] - sb.positions[i + 3], 2.0 * std::acos(-1.0));
                worst_rate = std::max(worst_rate, std::abs(step / (2.0 * delta) - s.axes.rotation[i][k]));
            }
        }
    }
    EXPECT_LT(worst_position, 1e-12);
    EXPECT_LT(worst_rate, 1e-6);
}

}  // namespace
}  // namespace plascap
