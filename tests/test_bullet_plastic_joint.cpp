// The Bullet adapter's build: the linked library computes in the precision its headers were
// compiled for (the analytic tests of the joints, on every engine: test_plastic_joint_engines.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_world.hpp"

namespace plascap {
namespace {

TEST(BulletPrecision, LinkedLibraryComputesInTheHeadersPrecision) {
    // Free fall under symplectic Euler: y_n = −g·h²·n(n+1)/2 exactly. A library built for the
    // other btScalar would read the bodies' fields at the wrong offsets or round at 1e-7.
    const double g = 9.81, h = 0.01;
    const int n = 200;
    BulletWorld world(btVector3(0, -g, 0), 10);
    BulletBox box(btVector3(0.1, 0.1, 0.1), 1.0, btTransform(btQuaternion::getIdentity(), btVector3(0, -0.5, 0)));
    world.world().addRigidBody(&box.body());
    for (int i = 0; i < n; ++i) world.step(h);
    const double exact = -0.5 - g * h * h * n * (n + 1) / 2;
    const double tolerance = sizeof(btScalar) == 8 ? 1e-12 : 1e-5;
    EXPECT_NEAR(box.body().getCenterOfMassPosition().y(), exact, tolerance * std::abs(exact));
    world.world().removeRigidBody(&box.body());
#ifdef BT_USE_DOUBLE_PRECISION
    static_assert(sizeof(btScalar) == 8, "BT_USE_DOUBLE_PRECISION must mean a double btScalar");
#endif
}

}  // namespace
}  // namespace plascap
