// A plastic joint's lifecycle, as a library user meets it (docs/adapters.md, "Lifecycle"): the
// engine-neutral driver reports each step's event once; a Bullet joint leaves its world when
// destroyed; ODE's joints step in one call; joined bodies do not collide until their joint breaks;
// the break callback fires once; and a joint that yields keeps its bodies awake, so that a slow
// plastic flow is not frozen by the engines' sleeping.
//
// The reference motion is the rigid-plastic oscillator of docs/references.md: a block of mass m
// hanging on a joint whose axial dof flows at capacity F < m·g falls at a = g − F/m, so after n steps
// of h (semi-implicit Euler, as both engines integrate) it has dropped a·h²·n(n+1)/2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "plascap/adapters/plastic_joint_driver.hpp"

#ifdef PLASCAP_HAVE_BULLET
#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_world.hpp"
#endif
#ifdef PLASCAP_HAVE_ODE
#include "plascap/adapters/ode_plastic_joints.hpp"
#include "plascap/adapters/prefetch.hpp"
#endif

namespace plascap {
namespace {

constexpr double kG = 10.0, kMass = 3.0, kDt = 0.01;

// The axial dof plastic at capacity F (no stiffness), every other dof rigid.
PlasticJointSettings axial(double F, double max_plastic_displacement = INFINITY) {
    PlasticJointSettings s;
    s.modes.fill(DofMode::Rigid);
    s.modes[index(Dof::N)] = DofMode::Plastic;
    s.laws[index(Dof::N)] = {F, F, std::nullopt};
    s.max_plastic_displacement = max_plastic_displacement;
    return s;
}

double drop_after(int steps, double F) {
    return 0.5 * (kG - F / kMass) * kDt * kDt * steps * (steps + 1);
}

// The axial dof an elastic spring k with capacities far above the load, every other dof rigid.
PlasticJointSettings axial_spring(double k) {
    PlasticJointSettings s = axial(1e6);
    s.laws[index(Dof::N)].stiffness = k;
    return s;
}

// The block's drop u after each step under its weight suddenly applied, on an explicit spring
// (force k·u from the step's start) and semi-implicit Euler, as both engines integrate: w ← w + h·(g − k·u/m),
// u ← u + h·w (the elastic–perfectly-plastic oscillator of docs/references.md, W ≤ F/2, peak 2W/k).
std::vector<double> spring_drops(double k, const std::vector<double>& steps) {
    std::vector<double> drops;
    double u = 0.0, w = 0.0;
    for (double h : steps) {
        w += h * (kG - k * u / kMass);
        u += h * w;
        drops.push_back(u);
    }
    return drops;
}

// The driver without an engine: a row at its bound with motion far beyond solver noise is flow
// (Yielded), a row below it is not (None); past the limit it breaks once (Broke, the callback once),
// and then reports None.
TEST(JointDriver, ReportsEachStepsEventOnceAndBreaksOnce) {
    PlasticJointDriver driver(axial(10.0, 0.02));
    int breaks = 0;
    JointBreak seen;
    driver.on_break([&](const JointBreak& b) {
        ++breaks;
        seen = b;
    });
    PerDof<double> x{};
    driver.engage(x, 0.0);
    JointFrameState state;
    state.axes.translation = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    state.axes.rotation = state.axes.translation;
    BodyInertia block;  // b, a point mass kMass at the anchor
    block.inverse_mass = 1.0 / kMass;
    const auto plan = [&] { driver.plan(state, kDt, [&] { return std::pair{block, std::optional<BodyInertia>{}}; }); };
    // The row's force on b along N, and where the step left the dof.
    const auto step = [&](double force, double to) {
        plan();
        x[index(Dof::N)] = to;
        state.positions = x;
        PerDof<double> forces{};
        forces[index(Dof::N)] = force;
        return driver.settle(forces, x, kDt);
    };
    EXPECT_EQ(step(5.0, 0.0), JointEvent::None);       // half the capacity: holds
    EXPECT_EQ(step(10.0, -0.01), JointEvent::Yielded);  // at capacity and moving: flows 0.01 m
    EXPECT_EQ(step(10.0, -0.025), JointEvent::Broke);   // 0.025 m > 0.02 m
    EXPECT_EQ(step(10.0, -0.04), JointEvent::None);     // broken stays broken, reported once
    EXPECT_EQ(breaks, 1);
    EXPECT_NEAR(seen.time, 3 * kDt, 1e-12);
    EXPECT_NEAR(seen.plastic_displacement, 0.025, 1e-12);
    EXPECT_NEAR(seen.dissipated, 10.0 * 0.025, 1e-12);  // F·Δx_p
    EXPECT_NEAR(driver.time(), 4 * kDt, 1e-12);
}

#ifdef PLASCAP_HAVE_BULLET
btTransform at(double y) { return btTransform(btQuaternion::getIdentity(), btVector3(0, y, 0)); }

TEST(BulletLifecycle, DestroyingAnAttachedJointTakesItOutOfTheWorld) {
    BulletWorld world(btVector3(0, -kG, 0), 10);
    BulletBox block(btVector3(0.1, 0.1, 0.1), kMass, at(-0.5));
    world.world().addRigidBody(&block.body());
    {
        BulletPlasticJoint joint(nullptr, block.body(), btTransform::getIdentity(), axial(18.0));
        joint.attach(world.world(), kDt);
        EXPECT_EQ(world.world().getNumConstraints(), 1);
        for (int i = 0; i < 10; ++i) world.step(kDt);
    }
    EXPECT_EQ(world.world().getNumConstraints(), 0);
    // Its action is gone too: stepping on must not call into the destroyed joint (ASan would say),
    // and the block falls freely: its speed grows by g·h a step.
    const double v = block.body().getLinearVelocity().y();
    for (int i = 0; i < 10; ++i) world.step(kDt);
    EXPECT_NEAR(block.body().getLinearVelocity().y(), v - kG * 10 * kDt, 1e-9);
    world.world().removeRigidBody(&block.body());
}

// The block hangs from a static body on a joint that breaks after 0.05 m of flow.
TEST(BulletLifecycle, ABrokenJointCallsBackOnceAndItsBodiesCollideAgain) {
    BulletWorld world(btVector3(0, -kG, 0), 10);
    BulletBox ceiling(btVector3(1, 0.1, 1), 0.0, at(0.1));
    BulletBox block(btVector3(0.1, 0.1, 0.1), kMass, at(-0.5));
    world.world().addRigidBody(&ceiling.body());
    world.world().addRigidBody(&block.body());
    BulletPlasticJoint joint(&ceiling.body(), block.body(), btTransform::getIdentity(), axial(18.0, 0.05));
    std::vector<double> breaks;
    joint.on_break([&](const JointBreak& b) { breaks.push_back(b.time); });
    joint.attach(world.world(), kDt);
    EXPECT_FALSE(block.body().checkCollideWith(&ceiling.body()));  // joined: no contacts
    for (int i = 0; i < 40; ++i) world.step(kDt);
    ASSERT_EQ(breaks.size(), 1u);
    EXPECT_DOUBLE_EQ(breaks[0], *joint.law().broken_at());
    // 0.05 m of flow at 4 m/s² takes 16 steps (a·h²·n(n+1)/2 first exceeds 0.05 m at n = 16).
    EXPECT_NEAR(breaks[0], 16 * kDt, 1e-9);
    EXPECT_EQ(world.world().getNumConstraints(), 0);
    EXPECT_TRUE(block.body().checkCollideWith(&ceiling.body()));  // broken: they collide again
    world.world().removeRigidBody(&block.body());
    world.world().removeRigidBody(&ceiling.body());
}

// F just below m·g: the block creeps down at a = g/600, far below Bullet's sleeping speed
// (0.8 m/s), so its island would fall asleep after 2 s and freeze the flow; the yielding joint keeps
// it awake, and the drop follows the oscillator's.
// A block hanging from the world on axial(F), allowed to sleep (a BulletBox may not, by default).
struct SleepableBlock {
    BulletWorld world{btVector3(0, -kG, 0), 10};
    BulletBox box{btVector3(0.1, 0.1, 0.1), kMass, at(-0.5)};
    BulletPlasticJoint joint;
    explicit SleepableBlock(double F) : joint(nullptr, box.body(), btTransform::getIdentity(), axial(F)) {
        box.body().forceActivationState(ACTIVE_TAG);
        world.world().addRigidBody(&box.body());
        joint.attach(world.world(), kDt);
    }
    ~SleepableBlock() { world.world().removeRigidBody(&box.body()); }
    btRigidBody& body() { return box.body(); }
};

TEST(BulletLifecycle, AYieldingJointKeepsItsBodiesAwake) {
    const double F = kMass * kG * (1 - 1.0 / 600);
    SleepableBlock block(F);
    const int steps = 500;  // 5 s
    for (int i = 0; i < steps; ++i) block.world.step(kDt);
    EXPECT_TRUE(block.body().isActive());
    EXPECT_NEAR(-0.5 - block.body().getCenterOfMassPosition().y(), drop_after(steps, F), 1e-6 * drop_after(steps, F));
}

// A joint whose island sleeps costs a glance: Bullet solves none of its constraints, and the joint is
// neither settled nor planned (solved() false) — its law stays as it was, its clock runs on — and
// when the block is woken and pushed past the capacity, the rows planned before it slept flow at
// once, as the oscillator says for the load m·g + P against F: a = (m·g + P − F)/m.
TEST(BulletLifecycle, ASleepingJointIsSkippedAndFlowsWhenWoken) {
    const double F = 2.0 * kMass * kG, push = 1.5 * kMass * kG;
    SleepableBlock block(F);
    BulletPlasticJoint& joint = block.joint;
    int steps = 0;
    for (; steps < 400 && block.body().isActive(); ++steps) block.world.step(kDt);
    ASSERT_FALSE(block.body().isActive()) << "Bullet did not put the hanging block to sleep";
    const double y = block.body().getCenterOfMassPosition().y();
    const PerDof<double> forces = joint.forces();
    for (int i = 0; i < 40; ++i) {
        block.world.step(kDt);
        ASSERT_FALSE(joint.solved()) << "asleep, step " << i;
    }
    EXPECT_EQ(block.body().getCenterOfMassPosition().y(), y);
    EXPECT_EQ(joint.forces(), forces);                     // no settle: what the rows last applied
    EXPECT_NEAR(forces[index(Dof::N)], kMass * kG, 1e-6);  // holding the weight
    EXPECT_EQ(joint.law().plastic_displacement(), 0.0);
    EXPECT_NEAR(joint.time(), (steps + 40) * kDt, 1e-12);

    block.body().activate();
    const int flowing = 30;
    for (int i = 0; i < flowing; ++i) {
        block.body().applyCentralForce(btVector3(0, -push, 0));
        block.world.step(kDt);
        ASSERT_TRUE(joint.solved()) << "awake, step " << i;
    }
    const double a = (kMass * kG + push - F) / kMass;
    const double expected = 0.5 * a * kDt * kDt * flowing * (flowing + 1);
    EXPECT_NEAR(y - block.body().getCenterOfMassPosition().y(), expected, 1e-6 * expected);
    EXPECT_NEAR(joint.law().plastic_displacement(), expected, 1e-6 * expected);
}

// A spring's force is fixed before the solve, so BulletPlasticSolver applies it once, in its set-up,
// without a row; the iterations solve the other joints' rows (issue 16). In one world: a block on an
// axial spring, added first, drops as the oscillator's recurrence says, the joint reports the
// spring's force as applied and the law sees the row's effective mass (the block's, for a row
// through its centre: ω·dt = √(k/m)·dt, eq. 3.2); a second block, on a rigid-plastic axial joint
// after it, flows at its capacity as the rigid-plastic oscillator says.
TEST(BulletLifecycle, ASpringIsAppliedOnceAStepAsTheOscillatorSaysAndTheRowsAfterItStillHold) {
    const double k = 1200.0, F = 18.0;  // ω·dt = √(k/m)·dt = 0.2 ≤ 0.25: an elastic row (eq. 3.2)
    BulletWorld world(btVector3(0, -kG, 0), 10);
    BulletBox sprung(btVector3(0.1, 0.1, 0.1), kMass, at(-0.5));
    BulletBox flowing(btVector3(0.1, 0.1, 0.1), kMass, btTransform(btQuaternion::getIdentity(), btVector3(3, -0.5, 0)));
    world.world().addRigidBody(&sprung.body());
    world.world().addRigidBody(&flowing.body());
    {
        BulletPlasticJoint spring(nullptr, sprung.body(), btTransform::getIdentity(), axial_spring(k));
        BulletPlasticJoint capacity(nullptr, flowing.body(), btTransform(btQuaternion::getIdentity(), btVector3(3, 0, 0)), axial(F));
        spring.attach(world.world(), kDt);
        capacity.attach(world.world(), kDt);
        const int steps = 40;
        const std::vector<double> drops = spring_drops(k, std::vector<double>(steps, kDt));
        for (int i = 0; i < steps; ++i) {
            const double before = -0.5 - sprung.body().getCenterOfMassPosition().y();
            world.step(kDt);
            ASSERT_NEAR(-0.5 - sprung.body().getCenterOfMassPosition().y(), drops[static_cast<std::size_t>(i)], 1e-9) << "step " << i;
            ASSERT_NEAR(spring.forces()[index(Dof::N)], k * before, 1e-9) << "step " << i;  // tension k·u of the step's start
            ASSERT_NEAR(spring.law().law(Dof::N)->omega_dt(), std::sqrt(k / kMass) * kDt, 1e-12) << "step " << i;
            ASSERT_NEAR(-0.5 - flowing.body().getCenterOfMassPosition().y(), drop_after(i + 1, F), 1e-9) << "step " << i;
        }
        EXPECT_NEAR(capacity.law().plastic_displacement(), drop_after(steps, F), 1e-9);
    }
    world.world().removeRigidBody(&flowing.body());
    world.world().removeRigidBody(&sprung.body());
}

// A disabled constraint has no rows in the solve (Bullet asks it for none), and BulletPlasticSolver
// applies none of its springs either: a block on an axial spring, stretched so the spring pulls
// about 40 N against its 30 N weight, falls freely once its constraint is disabled.
TEST(BulletLifecycle, ADisabledJointsSpringPushesNothing) {
    const double k = 1200.0;  // ω·dt = 0.2: an elastic row (eq. 3.2)
    BulletWorld world(btVector3(0, -kG, 0), 10);
    BulletBox block(btVector3(0.1, 0.1, 0.1), kMass, at(-0.5));
    world.world().addRigidBody(&block.body());
    {
        BulletPlasticJoint spring(nullptr, block.body(), btTransform::getIdentity(), axial_spring(k));
        spring.attach(world.world(), kDt);
        for (int i = 0; i < 10; ++i) world.step(kDt);
        ASSERT_GT(k * (-0.5 - block.body().getCenterOfMassPosition().y()), kMass * kG);
        spring.constraint().setEnabled(false);
        const double v0 = block.body().getLinearVelocity().y();
        for (int i = 1; i <= 10; ++i) {
            world.step(kDt);
            ASSERT_NEAR(block.body().getLinearVelocity().y(), v0 - kG * kDt * i, 1e-9) << "step " << i;
        }
    }
    world.world().removeRigidBody(&block.body());
}
#endif

#ifdef PLASCAP_HAVE_ODE
struct OdeWorld {
    OdeWorld() {
        dInitODE2(0);
        world = dWorldCreate();
        dWorldSetGravity(world, 0, -kG, 0);
    }
    ~OdeWorld() { dWorldDestroy(world); }
    dBodyID box(double y) {
        dBodyID b = dBodyCreate(world);
        dMass m;
        dMassSetBoxTotal(&m, kMass, 0.2, 0.2, 0.2);
        dBodySetMass(b, &m);
        dBodySetPosition(b, 0, y, 0);
        return b;
    }
    dWorldID world;
};

// One call per step: the joint takes hold at its time, then the block flows as the oscillator says.
TEST(OdeLifecycle, OneCallPerStepRunsTheWholeCycle) {
    OdeWorld ode;
    const dBodyID block = ode.box(-0.5);
    {
        OdePlasticJoints joints(ode.world);
        joints.add(nullptr, block, Pose{}, axial(18.0), /*takes_hold_at=*/0.05);
        for (int i = 0; i < 5; ++i) joints.step(kDt);  // free fall until t = 0.05 s
        EXPECT_FALSE(joints[0].engaged());
        const double y0 = dBodyGetPosition(block)[1], v0 = dBodyGetLinearVel(block)[1];
        for (int i = 0; i < 30; ++i) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
        EXPECT_TRUE(joints[0].engaged());
        // From the speed it had when the joint took hold: y0 + v0·t − drop.
        const double expected = y0 + v0 * 30 * kDt - drop_after(30, 18.0);
        EXPECT_NEAR(dBodyGetPosition(block)[1], expected, 1e-9);
        EXPECT_NEAR(joints.time(), 35 * kDt, 1e-12);
    }
}

// A group plans each joint's next step as it settles it (OdePlasticJoint::after_step_and_plan), from
// what before_step would read at the next step's start: the same rows, so the same motion to the
// last bit as a joint stepped by hand — here a block swinging and spinning on a joint with all six
// dofs flowing, through a change of dt (which the group plans again for) and back.
TEST(OdeLifecycle, AGroupThatPlansAsItSettlesMovesAsAJointSteppedByHand) {
    PlasticJointSettings six;
    for (Dof dof : kAllDofs) {
        six.modes[index(dof)] = DofMode::Plastic;
        six.laws[index(dof)] = is_rotation(dof) ? DofLaw{2.0, 3.0, std::nullopt} : DofLaw{20.0, 25.0, 4000.0};
    }
    OdeWorld grouped, by_hand;
    const dBodyID a = grouped.box(-0.5), b = by_hand.box(-0.5);
    for (dBodyID block : {a, b}) {
        dBodySetLinearVel(block, 0.8, 0, -0.3);
        dBodySetAngularVel(block, 1.5, -2.0, 0.7);
    }
    OdePlasticJoints joints(grouped.world);
    OdePlasticJoint& in_group = joints.add(nullptr, a, Pose{}, six);
    OdePlasticJoint alone(by_hand.world, nullptr, b, Pose{}, six);
    alone.engage(0.0);
    double dissipated = 0.0;
    for (int i = 0; i < 60; ++i) {
        const double dt = i >= 20 && i < 30 ? 0.5 * kDt : kDt;
        // ODE's exact solver: QuickStep shuffles its rows with ODE's one random sequence, which the
        // two worlds would share.
        joints.step(dt, OdePlasticJoints::Stepper::Exact);
        alone.before_step(dt);
        dWorldStep(by_hand.world, dt);
        alone.after_step(dt);
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(dBodyGetPosition(a)[k], dBodyGetPosition(b)[k]) << "step " << i;
            ASSERT_EQ(dBodyGetAngularVel(a)[k], dBodyGetAngularVel(b)[k]) << "step " << i;
        }
        ASSERT_EQ(in_group.law().dissipated(), alone.law().dissipated()) << "step " << i;
        dissipated = alone.law().dissipated();
    }
    EXPECT_GT(dissipated, 0.1);  // the dofs flowed: the plans mattered
}

// A group whose joints' state passes kPrefetchFromBytes loads each joint a few places ahead
// (prefetch.hpp): a hint that must change nothing. Every block of such a group flows as the
// oscillator says, the last ones (past the last joint loaded ahead) as the first.
TEST(OdeLifecycle, AGroupThatLoadsItsJointsAheadFlowsAsTheOscillatorSays) {
    OdeWorld ode;
    const std::size_t count = kPrefetchFromBytes / OdePlasticJoint::state_bytes() + kPrefetchAhead + 2;
    OdePlasticJoints joints(ode.world);
    std::vector<dBodyID> blocks;
    for (std::size_t i = 0; i < count; ++i) {
        blocks.push_back(ode.box(-0.5));
        dBodySetPosition(blocks.back(), 2.0 * static_cast<double>(i), -0.5, 0);
        joints.add(nullptr, blocks.back(), Pose{{2.0 * static_cast<double>(i), 0, 0}}, axial(18.0));
    }
    ASSERT_GT(count * OdePlasticJoint::state_bytes(), kPrefetchFromBytes);
    const int steps = 10;
    for (int i = 0; i < steps; ++i) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    for (std::size_t i = 0; i < count; ++i)
        ASSERT_NEAR(dBodyGetPosition(blocks[i])[1], -0.5 - drop_after(steps, 18.0), 1e-9) << "block " << i;
}

// ODE's rows carry what must be solved; a spring's force is known before the step, so ODE's joint
// puts it on the bodies (their force accumulators) instead of giving ODE a row to iterate (issue 16).
// Applied once a step — also when a change of dt makes the group plan again what it planned as it
// settled — the block moves as the oscillator's recurrence says, and the joint reports the spring's
// force as what it applied.
TEST(OdeLifecycle, ASpringPushesTheBodiesOnceAStepAsTheOscillatorSays) {
    const double k = 1200.0;  // ω·dt = √(k/m)·dt = 0.2 ≤ 0.25: an elastic row (eq. 3.2)
    OdeWorld ode;
    const dBodyID block = ode.box(-0.5);
    OdePlasticJoints joints(ode.world);
    joints.add(nullptr, block, Pose{}, axial_spring(k));
    std::vector<double> steps;
    for (int i = 0; i < 60; ++i) steps.push_back(i >= 20 && i < 30 ? 0.5 * kDt : kDt);
    const std::vector<double> drops = spring_drops(k, steps);
    double peak = 0.0;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const double before = -0.5 - dBodyGetPosition(block)[1];
        joints.step(steps[i], OdePlasticJoints::Stepper::Exact);
        ASSERT_NEAR(-0.5 - dBodyGetPosition(block)[1], drops[i], 1e-9) << "step " << i;
        // The law's force on b along N: tension, the spring's k·u of the step's start.
        ASSERT_NEAR(joints[0].forces()[index(Dof::N)], k * before, 1e-9) << "step " << i;
        peak = std::max(peak, drops[i]);
    }
    EXPECT_NEAR(peak, 2.0 * kMass * kG / k, 0.1 * 2.0 * kMass * kG / k);  // 2W/k = 0.05 m, to O(ω·dt)
}

// A joint whose one held dof is a spring keeps that spring as a row (an unreachable rate bounded by
// its force): ODE writes a joint's feedback, by which the joint tells that a step solved it, only
// for a joint with rows. Every other dof free, the block still drops as the oscillator says.
TEST(OdeLifecycle, AJointOfOneSpringKeepsItAsARow) {
    const double k = 1200.0;
    PlasticJointSettings spring_only = axial_spring(k);
    for (Dof dof : kAllDofs)
        if (dof != Dof::N) spring_only.modes[index(dof)] = DofMode::Free;
    OdeWorld ode;
    const dBodyID block = ode.box(-0.5);
    OdePlasticJoints joints(ode.world);
    joints.add(nullptr, block, Pose{}, spring_only);
    const std::vector<double> drops = spring_drops(k, std::vector<double>(30, kDt));
    for (std::size_t i = 0; i < drops.size(); ++i) {
        joints.step(kDt, OdePlasticJoints::Stepper::Exact);
        ASSERT_TRUE(joints[0].solved()) << "step " << i;
        ASSERT_NEAR(-0.5 - dBodyGetPosition(block)[1], drops[i], 1e-9) << "step " << i;
    }
}

// A push no step took is taken back: while the block sleeps (ODE keeps a disabled body's force
// accumulator) the joint, planned again every step because it counts its rows' work, leaves one
// push on the block, not one per step; when it is severed, asleep, it takes that push back, and the
// block falls freely from rest.
TEST(OdeLifecycle, ASleepingSpringLeavesOnePushAndItsBreakTakesItBack) {
    const double k = 1200.0;
    OdeWorld ode;
    const dBodyID block = ode.box(-0.5);
    OdePlasticJoints joints(ode.world);
    joints.add(nullptr, block, Pose{}, axial_spring(k)).count_rows_work();
    for (int i = 0; i < 7; ++i) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    dBodyDisable(block);  // asleep, at rest, as ODE's auto-disable leaves a body
    dBodySetLinearVel(block, 0, 0, 0);
    const double u = -0.5 - dBodyGetPosition(block)[1];
    ASSERT_GT(u, 0.01);
    for (int i = 0; i < 20; ++i) {
        joints.step(kDt, OdePlasticJoints::Stepper::Exact);
        ASSERT_FALSE(joints[0].solved());
        ASSERT_NEAR(dBodyGetForce(block)[1], k * u, 1e-9) << "asleep, step " << i;  // the spring holds b up
    }
    joints[0].sever();
    joints.step(kDt, OdePlasticJoints::Stepper::Exact);  // breaks at the step's end, wakes the block
    ASSERT_TRUE(dBodyIsEnabled(block));
    EXPECT_EQ(dBodyGetForce(block)[1], 0.0);
    const double y = dBodyGetPosition(block)[1];
    for (int i = 0; i < 10; ++i) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    EXPECT_NEAR(y - dBodyGetPosition(block)[1], 0.5 * kG * kDt * kDt * 10 * 11, 1e-9);  // free fall from rest
}

// Two free bodies (no gravity) pulled apart by their speeds, joined on a joint that breaks after
// 0.05 m of flow: joined(), then the callback once, then not joined.
TEST(OdeLifecycle, ABrokenJointCallsBackOnceAndItsBodiesCollideAgain) {
    OdeWorld ode;
    dWorldSetGravity(ode.world, 0, 0, 0);
    const dBodyID a = ode.box(0.5), b = ode.box(-0.5);
    dBodySetLinearVel(a, 0, 1, 0);
    dBodySetLinearVel(b, 0, -1, 0);
    OdePlasticJoints joints(ode.world);
    int breaks = 0;
    joints.add(a, b, Pose{}, axial(1.0, 0.05)).on_break([&](const JointBreak&) { ++breaks; });
    EXPECT_TRUE(joints.joined(a, b));
    EXPECT_TRUE(joints.joined(b, a));
    for (int i = 0; i < 100; ++i) joints.step(kDt);
    EXPECT_EQ(breaks, 1);
    EXPECT_FALSE(joints.joined(a, b));
}

// collide(): two overlapping boxes held by a hinge get no contacts while it holds, and do once it
// breaks. The hinge's translations are rigid (one ball joint, so no contact rows of its own); its Mz
// flows at 1 N·m and breaks after 0.05 rad while the boxes spin apart about z.
TEST(OdeLifecycle, CollideSkipsJoinedBodiesUntilTheirJointBreaks) {
    OdeWorld ode;
    dWorldSetGravity(ode.world, 0, 0, 0);
    const dSpaceID space = dSimpleSpaceCreate(nullptr);
    const dJointGroupID contacts = dJointGroupCreate(0);
    const dBodyID a = ode.box(0.5), b = ode.box(-0.5);
    dGeomSetBody(dCreateBox(space, 1.02, 1.02, 1.02), a);  // overlapping by 2 cm
    dGeomSetBody(dCreateBox(space, 1.02, 1.02, 1.02), b);
    dBodySetAngularVel(a, 0, 0, 2);
    dBodySetAngularVel(b, 0, 0, -2);
    PlasticJointSettings hinge;
    hinge.modes.fill(DofMode::Rigid);
    hinge.modes[index(Dof::Mz)] = DofMode::Plastic;
    hinge.laws[index(Dof::Mz)] = {1.0, 1.0, std::nullopt};
    hinge.max_plastic_rotation = 0.05;
    OdePlasticJoints joints(ode.world);
    joints.add(a, b, Pose{}, hinge);
    dSurfaceParameters surface{};
    surface.mode = dContactApprox1;
    surface.mu = 0.25;
    const auto contacts_of_a = [&] {
        int n = 0;
        for (int i = 0; i < dBodyGetNumJoints(a); ++i) n += dJointGetType(dBodyGetJoint(a, i)) == dJointTypeContact;
        return n;
    };
    int before_break = 0, after_break = 0;
    for (int i = 0; i < 30; ++i) {
        joints.collide(space, contacts, surface);
        (joints[0].law().broken() ? after_break : before_break) += contacts_of_a();
        joints.step(kDt);
        dJointGroupEmpty(contacts);
    }
    EXPECT_TRUE(joints[0].law().broken());
    EXPECT_EQ(before_break, 0);
    EXPECT_GT(after_break, 0);
    dJointGroupDestroy(contacts);
    dSpaceDestroy(space);
}

// As the Bullet test: ODE's auto-disabling (off by default; on here) would freeze the creeping block
// within ten steps; the yielding joint keeps enabling it.
TEST(OdeLifecycle, AYieldingJointKeepsItsBodiesAwake) {
    const double F = kMass * kG * (1 - 1.0 / 600);
    OdeWorld ode;
    dWorldSetAutoDisableFlag(ode.world, 1);
    const dBodyID block = ode.box(-0.5);
    OdePlasticJoints joints(ode.world);
    joints.add(nullptr, block, Pose{}, axial(F));
    const int steps = 500;
    for (int i = 0; i < steps; ++i) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    EXPECT_TRUE(dBodyIsEnabled(block));
    EXPECT_NEAR(-0.5 - dBodyGetPosition(block)[1], drop_after(steps, F), 1e-6 * drop_after(steps, F));
}

// The same creep on QuickStep with split corrections (a warm start, and the position corrections in
// a pass of their own): the row at its capacity lets the block accelerate at (m·g − F)/m, as the
// oscillator says, and the pass, with nothing to correct along a flowing row, adds no motion.
TEST(OdeLifecycle, SplitCorrectionsLetAYieldingJointCreepAsTheOscillatorSays) {
    const double F = kMass * kG * (1 - 1.0 / 600);
    OdeWorld ode;
    const dBodyID block = ode.box(-0.5);
    OdePlasticJoints joints(ode.world);
    joints.add(nullptr, block, Pose{}, axial(F));
    const int steps = 500;
    for (int i = 0; i < steps; ++i) joints.step(kDt, OdePlasticJoints::Stepper::QuickSplit);
    EXPECT_NEAR(-0.5 - dBodyGetPosition(block)[1], drop_after(steps, F), 1e-6 * drop_after(steps, F));
    EXPECT_NEAR(joints[0].law().plastic_displacement(), drop_after(steps, F), 1e-6 * drop_after(steps, F));
}

// A joint whose bodies sleep costs a glance: ODE skips their island, so the joint is neither settled
// nor planned (solved() false) — its law stays as it was, its clock runs on — and when the block is
// woken and pushed past the capacity, the rows planned before it slept flow at once, as the
// oscillator says for the load m·g + P against F: a = (m·g + P − F)/m.
TEST(OdeLifecycle, ASleepingJointIsSkippedAndFlowsWhenWoken) {
    const double F = 2.0 * kMass * kG, push = 1.5 * kMass * kG;
    OdeWorld ode;
    dWorldSetAutoDisableFlag(ode.world, 1);
    const dBodyID block = ode.box(-0.5);
    OdePlasticJoints joints(ode.world);
    joints.add(nullptr, block, Pose{}, axial(F));
    int steps = 0;
    for (; steps < 100 && dBodyIsEnabled(block); ++steps) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    ASSERT_FALSE(dBodyIsEnabled(block)) << "ODE's auto-disable did not put the hanging block to sleep";
    // ODE disables idle bodies as a step starts: the step that found the block asleep skipped it.
    EXPECT_EQ(joints.solved_joints(), 0u);
    const double y = dBodyGetPosition(block)[1];
    const PerDof<double> forces = joints[0].forces();
    for (int i = 0; i < 40; ++i) {
        joints.step(kDt, OdePlasticJoints::Stepper::Exact);
        ASSERT_EQ(joints.solved_joints(), 0u) << "asleep, step " << i;
        ASSERT_FALSE(joints[0].solved());
    }
    EXPECT_EQ(dBodyGetPosition(block)[1], y);
    EXPECT_EQ(joints[0].forces(), forces);                // no settle: what the rows last applied
    EXPECT_NEAR(forces[index(Dof::N)], kMass * kG, 1e-6);  // holding the weight
    EXPECT_EQ(joints[0].law().plastic_displacement(), 0.0);
    EXPECT_NEAR(joints[0].time(), (steps + 40) * kDt, 1e-12);

    dBodyEnable(block);
    const int flowing = 30;
    for (int i = 0; i < flowing; ++i) {
        dBodyAddForce(block, 0, -push, 0);
        joints.step(kDt, OdePlasticJoints::Stepper::Exact);
        ASSERT_EQ(joints.solved_joints(), 1u) << "awake, step " << i;
    }
    const double a = (kMass * kG + push - F) / kMass;
    const double expected = 0.5 * a * kDt * kDt * flowing * (flowing + 1);
    EXPECT_NEAR(y - dBodyGetPosition(block)[1], expected, 1e-9);
    EXPECT_NEAR(joints[0].law().plastic_displacement(), expected, 1e-9);
}

// A sleeping joint that is severed (a member removed) still breaks at the end of the next step: the
// callback fires once, at that time, and the block wakes and falls.
TEST(OdeLifecycle, ASleepingJointBreaksWhenSevered) {
    OdeWorld ode;
    dWorldSetAutoDisableFlag(ode.world, 1);
    const dBodyID block = ode.box(-0.5);
    OdePlasticJoints joints(ode.world);
    joints.add(nullptr, block, Pose{}, axial(2.0 * kMass * kG));
    std::vector<double> breaks;
    joints[0].on_break([&](const JointBreak& b) { breaks.push_back(b.time); });
    int steps = 0;
    for (; steps < 100 && dBodyIsEnabled(block); ++steps) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    ASSERT_FALSE(dBodyIsEnabled(block));
    joints[0].sever();
    joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    ASSERT_EQ(breaks.size(), 1u);
    EXPECT_NEAR(breaks[0], (steps + 1) * kDt, 1e-12);
    EXPECT_TRUE(dBodyIsEnabled(block));
    const double y = dBodyGetPosition(block)[1];
    for (int i = 0; i < 10; ++i) joints.step(kDt, OdePlasticJoints::Stepper::Exact);
    EXPECT_NEAR(y - dBodyGetPosition(block)[1], 0.5 * kG * kDt * kDt * 10 * 11, 1e-9);  // free fall from rest
    EXPECT_EQ(breaks.size(), 1u);
}
#endif

}  // namespace
}  // namespace plascap
