// plascap's own Bullet constraint (bullet_plastic_constraint.hpp), where it does what Bullet's 6-dof
// springs cannot: a row bounded by both capacities, so a load reversal meets the capacity of its own
// side from its first step; and a twist measure without the Euler singularity at 90°, so a joint
// twisting through several turns dissipates exactly the work of its torsional capacity. (The
// analytic cases every engine passes are in test_plastic_joint_engines.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_world.hpp"

namespace plascap {
namespace {

constexpr double kDt = 1.0 / 240;
constexpr double kMass = 10.0;

// One dof plastic (rigid-plastic, the given capacities), every other rigid.
PlasticJointSettings one_plastic(Dof dof, double positive, double negative) {
    PlasticJointSettings s;
    s.modes.fill(DofMode::Rigid);
    s.modes[index(dof)] = DofMode::Plastic;
    s.laws[index(dof)] = {positive, negative, std::nullopt};
    return s;
}

// A 10 kg block (0.2 × 1 × 0.2 m) without gravity, joined to the world at its top.
struct Block {
    BulletWorld world{btVector3(0, 0, 0), 50};
    BulletBox box{btVector3(0.1, 0.5, 0.1), kMass, btTransform(btQuaternion::getIdentity(), btVector3(0, -0.5, 0))};
    Block() { world.world().addRigidBody(&box.body()); }
    ~Block() { world.world().removeRigidBody(&box.body()); }
    btTransform anchor() const { return btTransform::getIdentity(); }
};

// The axial force along the joint's y, in phases of (force on the block [N], steps): tension
// pulls the block away from its anchor (−y), so it loads the dof's negative side.
template <class Joint>
double axial_plastic_after(const std::vector<std::pair<double, int>>& phases, double tension_capacity,
                           double compression_capacity) {
    Block block;
    // The dof's position is b's anchor minus a's along y: pulling the block down is negative motion,
    // resisted by capacity_negative (here the tension capacity).
    Joint joint(nullptr, block.box.body(), block.anchor(), one_plastic(Dof::N, compression_capacity, tension_capacity));
    joint.attach(block.world.world(), kDt);
    for (const auto& [force, steps] : phases) {
        for (int i = 0; i < steps; ++i) {
            block.box.body().applyCentralForce(btVector3(0, -force, 0));
            block.world.step(kDt);
        }
    }
    return joint.law().plastic_displacement();
}

TEST(BulletPlasticConstraint, LoadReversalMeetsTheCapacityOfItsOwnSideFromItsFirstStep) {
    // N = 1,000 N in tension, N_neg = 3,000 N in compression: 800 N of tension, then 2,500 N of
    // compression. Both are below their side's capacity, so nothing may flow.
    const std::vector<std::pair<double, int>> reversal = {{800.0, 120}, {-2500.0, 120}};
    EXPECT_LT(axial_plastic_after<BulletPlasticJoint>(reversal, 1000.0, 3000.0), 1e-9);
    // Spring2's motor has one bound, that of the side last loaded: it lets the first steps of the
    // reversal through at 1,000 N (which is why the default constraint is plascap's own).
    EXPECT_GT(axial_plastic_after<BulletPlasticJointSpring2>(reversal, 1000.0, 3000.0), 1e-4);
}

TEST(BulletPlasticConstraint, CompressionPastItsCapacityFlowsAtThatCapacity) {
    // 3,300 N against N_neg = 3,000 N: the block accelerates at (3,300 − 3,000)/m, so after n steps
    // of h (semi-implicit Euler) it has moved a·h²·n(n+1)/2 — after first holding 800 N of tension.
    const int n = 120;
    const double a = (3300.0 - 3000.0) / kMass;
    const double expected = a * kDt * kDt * n * (n + 1) / 2;
    const double plastic = axial_plastic_after<BulletPlasticJoint>({{800.0, 60}, {-3300.0, n}}, 1000.0, 3000.0);
    EXPECT_NEAR(plastic, expected, 0.01 * expected);
}

TEST(BulletPlasticConstraint, TwistThroughSeveralTurnsDissipatesTheKineticEnergyAtTheTorsionalCapacity) {
    // A block spinning about its own axis (the joint's y) at ω0 on a rigid-plastic My of capacity T,
    // every other dof rigid: it decelerates at T/I and stops after θ = I·ω0²/(2T) − ω0·h/2
    // (semi-implicit Euler's sum), here ≈ 4 rad — through 90°, 180° and 270° of twist. Its kinetic
    // energy is dissipated in the joint; the bending dofs stay put.
    Block block;
    const double T = 5.0;
    const double I = kMass / 3.0 * (0.1 * 0.1 + 0.1 * 0.1);  // box about its long axis
    const double omega = std::sqrt(2.0 * T * 4.0 / I);
    BulletPlasticJoint joint(nullptr, block.box.body(), block.anchor(), one_plastic(Dof::My, T, T));
    joint.attach(block.world.world(), kDt);
    block.box.body().setAngularVelocity(btVector3(0, omega, 0));
    for (int i = 0; i < 240; ++i) block.world.step(kDt);
    const double expected = I * omega * omega / (2.0 * T) - omega * kDt / 2.0;
    EXPECT_NEAR(joint.law().plastic_rotation(), expected, 0.01 * expected);
    // The joint's work is T times that rotation, which is the kinetic energy but for the one-step
    // lag of semi-implicit Euler (T·ω0·h/2, 1.3 % here).
    EXPECT_NEAR(joint.law().dissipated(), T * expected, 1e-3 * T * expected);
    EXPECT_NEAR(joint.law().dissipated(), 0.5 * I * omega * omega, 0.02 * 0.5 * I * omega * omega);
    const btVector3 axis = block.box.body().getCenterOfMassTransform().getBasis().getColumn(1);
    EXPECT_NEAR(axis.y(), 1.0, 1e-6);  // still hanging straight: no bending through the turns
    EXPECT_LT(block.box.body().getAngularVelocity().length(), 1e-6);
}

TEST(BulletPlasticConstraint, TheSolverHandsEachRowTheEffectiveMassOfItsClosedForm) {
    // The block hangs at rest from its top (lever r = anchor − centre = 0.5 m along y). Per row,
    // 1/(J·M⁻¹·Jᵀ): along y (r ∥ y) the block's mass; along x and z m⁻¹ + (r × e)·I⁻¹·(r × e) =
    // 1/m + r²/I_zz (resp. I_xx); about an axis its moment of inertia (box: I = m(a² + b²)/12).
    Block block;
    PlasticJointSettings s;
    for (Dof dof : kAllDofs) {
        s.modes[index(dof)] = DofMode::Plastic;
        s.laws[index(dof)] = {1e6, 1e6, 1.0};  // soft springs: every dof elastic-plastic (ω·dt ≪ 0.25)
    }
    BulletPlasticJoint joint(nullptr, block.box.body(), block.anchor(), s);
    joint.attach(block.world.world(), kDt);
    const PerDof<double> before = joint.constraint().solved_masses();
    for (double m : before) EXPECT_TRUE(std::isnan(m));  // no solve yet: the joint computes them
    block.world.step(kDt);
    const double bending = kMass * (0.2 * 0.2 + 1.0 * 1.0) / 12, twisting = kMass * (0.2 * 0.2 + 0.2 * 0.2) / 12;
    const double shear = 1.0 / (1.0 / kMass + 0.5 * 0.5 / bending);
    const PerDof<double> expected = {shear, kMass, shear, bending, twisting, bending};
    const PerDof<double> solved = joint.constraint().solved_masses();
    for (std::size_t i = 0; i < kDofCount; ++i) EXPECT_NEAR(solved[i], expected[i], 1e-12 * expected[i]) << i;
    // The law plans the next step with them: its ω·dt is √(k/m)·dt (eq. 3.2) with k = 1.
    for (std::size_t i = 0; i < kDofCount; ++i)
        EXPECT_NEAR(joint.law().law(kAllDofs[i])->omega_dt(), std::sqrt(1.0 / expected[i]) * kDt, 1e-12) << i;
}

}  // namespace
}  // namespace plascap
