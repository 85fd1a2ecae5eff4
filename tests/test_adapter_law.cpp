// The engine-neutral runtime law (adapters/common) against hand calculations, with no engine:
// one dof's force, return mapping, dissipation and regimes; a load reversal with F⁺ ≠ F⁻; the flow
// criterion against solver noise, a sustained load at capacity and an impact; the
// joint's breaking rule; the world-to-joint load decomposition for a turned joint and for
// non-orthogonal Euler axes; the frame measurement near its singular angle; the row effective
// masses of two moving bodies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "plascap/adapters/flow_criterion.hpp"
#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/joint_loads.hpp"
#include "plascap/adapters/plastic_joint_law.hpp"
#include "plascap/adapters/row_effective_mass.hpp"
#include "plascap/adapters/yield_condition.hpp"

namespace {

using namespace plascap;

const double kPi = std::acos(-1.0);

// Elastic–perfectly-plastic spring k = 100 N/m, F⁺ = 10 N, F⁻ = 20 N, on a mass whose ω·dt is
// small (m = 100 kg, dt = 0.01 s: ω·dt = 0.01). Hand calculation, step by step (Simo & Hughes §1.2):
TEST(ElasticPlasticLaw, ForceReturnMappingDissipationAndReversal) {
    ElasticPlasticLaw law(DofLaw{10.0, 20.0, 100.0});
    law.start(0.0);
    // x = 0.05: f = −k·x = −5 N, elastic; ½·k·x² = 0.125 J stored.
    RowCommand c = law.plan(0.05, 0.01, 100.0);
    EXPECT_EQ(c.kind, RowCommand::Kind::Push);
    EXPECT_DOUBLE_EQ(c.force, -5.0);
    EXPECT_EQ(law.regime(), Regime::ElasticPlastic);
    EXPECT_NEAR(law.omega_dt(), 0.01, 1e-15);
    law.settle(0.05, c.force);
    EXPECT_DOUBLE_EQ(law.accumulated_plastic(), 0.0);
    EXPECT_DOUBLE_EQ(law.elastic_energy(0.05), 0.125);
    // x = 0.15: trial −15 N passes F⁺ = 10: the force is capped at −10 and x_p returns to
    // x − F⁺/k = 0.05; dissipated F⁺·Δx_p = 10 · 0.05 = 0.5 J.
    c = law.plan(0.15, 0.01, 100.0);
    EXPECT_DOUBLE_EQ(c.force, -10.0);
    law.settle(0.15, c.force);
    EXPECT_NEAR(law.plastic_offset(), 0.05, 1e-15);
    EXPECT_NEAR(law.accumulated_plastic(), 0.05, 1e-15);
    EXPECT_NEAR(law.dissipated(), 0.5, 1e-14);
    EXPECT_NEAR(law.elastic_energy(0.15), 0.5 * 100 * 0.1 * 0.1, 1e-14);  // on the capacity: F²/(2k)
    // Reversal to x = −0.2: trial −k·(x − x_p) = 25 N passes F⁻ = 20: capped at +20, x_p returns to
    // x + F⁻/k = 0; Δx_p = 0.05, dissipated += 20 · 0.05 = 1 J.
    c = law.plan(-0.2, 0.01, 100.0);
    EXPECT_DOUBLE_EQ(c.force, 20.0);
    law.settle(-0.2, c.force);
    EXPECT_NEAR(law.plastic_offset(), 0.0, 1e-15);
    EXPECT_NEAR(law.accumulated_plastic(), 0.1, 1e-15);
    EXPECT_NEAR(law.dissipated(), 1.5, 1e-14);
    // Unloading back inside the elastic range moves nothing.
    c = law.plan(-0.1, 0.01, 100.0);
    EXPECT_DOUBLE_EQ(c.force, 10.0);
    law.settle(-0.1, c.force);
    EXPECT_NEAR(law.accumulated_plastic(), 0.1, 1e-15);
}

// Rigid-plastic (no stiffness): a Hold row bounded by the capacity of the side being loaded; it
// flows only in steps where the row reached its bound (here each such step moves far beyond solver
// slack: flow_criterion.hpp), and the row's work −f·Δx is dissipated.
TEST(ElasticPlasticLaw, RigidPlasticHoldsBelowAndFlowsAtEachSidesCapacity) {
    ElasticPlasticLaw law(DofLaw{10.0, 20.0, std::nullopt});
    law.start(0.0);
    RowCommand c = law.plan(0.0, 0.01, 1.0);
    EXPECT_EQ(c.kind, RowCommand::Kind::Hold);
    EXPECT_EQ(law.regime(), Regime::RigidPlastic);
    EXPECT_DOUBLE_EQ(c.bound, 10.0);  // before any load: the smaller capacity
    EXPECT_DOUBLE_EQ(c.velocity, 0.0);
    // Pulled the negative way, at the bound: b moved −1 mm, the row pushed +10 N.
    law.settle(-0.001, 10.0);
    EXPECT_NEAR(law.plastic_offset(), -0.001, 1e-15);
    EXPECT_NEAR(law.dissipated(), 0.01, 1e-15);  // −f·Δx = −10 · (−0.001)
    // Loaded on the negative side, the bound is F⁻ = 20 N from now on.
    c = law.plan(-0.001, 0.01, 1.0);
    EXPECT_DOUBLE_EQ(c.bound, 20.0);
    // Below the bound (15 N of 20), a drift of 0.5 mm the solver let through is no flow; the next
    // step drives it back at kHoldCorrection · 0.5 mm / dt = 0.01 m/s.
    law.settle(-0.0015, 15.0);
    EXPECT_NEAR(law.plastic_offset(), -0.001, 1e-15);
    c = law.plan(-0.0015, 0.01, 1.0);
    EXPECT_NEAR(c.velocity, kHoldCorrection * 0.0005 / 0.01, 1e-15);
    // The load reverses: once the row pushed the other way, the bound is F⁺ = 10 N. (A symmetric
    // row bound takes the side last loaded, so the first reversed step is bounded by F⁻; issue 16's
    // own constraint gives each side its bound.)
    law.settle(-0.001, -8.0);
    c = law.plan(-0.001, 0.01, 1.0);
    EXPECT_DOUBLE_EQ(c.bound, 10.0);
    law.settle(0.001, -10.0);  // at F⁺: flows +2 mm, absorbs 10 · 0.002
    EXPECT_NEAR(law.plastic_offset(), 0.001, 1e-15);
    EXPECT_NEAR(law.dissipated(), 0.01 + 0.02, 1e-15);
    EXPECT_NEAR(law.accumulated_plastic(), 0.003, 1e-15);
}

// Issue 20: an unconverged solver leaves a row loaded to about 0.9 of its bound anywhere between
// 0.8 and the bound from step to step, at the bound in a fifth of the steps: no flow.
TEST(FlowCriterion, SolverNoiseBelowCapacityNeverFlows) {
    FlowCriterion criterion;
    unsigned state = 12345;
    int at_bound = 0;
    for (int step = 0; step < 10000; ++step) {
        state = state * 1103515245u + 12345u;  // a linear congruential sequence (glibc's constants)
        const double noise = static_cast<double>((state >> 8) % 1000) / 999.0;  // in [0, 1]
        const double share = std::min(1.0, 0.8 + 0.25 * noise);                 // 0.8–1.05, clamped
        EXPECT_FALSE(criterion.flowed(share, 0.01)) << "step " << step;
        at_bound += criterion.at_bound();
    }
    EXPECT_GT(at_bound, 1500);  // the row did touch its bound, often
}

// A load held at the bound flows once the mean share reaches kConfirmedShare: 1 − 0.9ⁿ ≥ 0.985
// first at n = ⌈ln 0.015 / ln 0.9⌉ = 40 steps from rest.
TEST(FlowCriterion, ASustainedLoadAtCapacityFlowsOnceItsMeanConfirmsIt) {
    FlowCriterion criterion;
    for (int step = 1; step < 40; ++step) EXPECT_FALSE(criterion.flowed(-1.0, 0.001)) << "step " << step;
    EXPECT_TRUE(criterion.flowed(-1.0, 0.001));
    EXPECT_TRUE(criterion.flowed(-1.0, 0.0));
    EXPECT_FALSE(criterion.flowed(-0.9, 0.0));  // off the bound: held
}

// An impact (motion far beyond slack) flows at once, goes on flowing while the row stays at its
// bound, and stops when it leaves it; touching the bound again with a low mean is no flow.
TEST(FlowCriterion, AnImpactFlowsAtOnceAndGoesOnWhileAtTheBound) {
    FlowCriterion criterion;
    for (int step = 0; step < 20; ++step) EXPECT_FALSE(criterion.flowed(0.3, 0.0));
    EXPECT_TRUE(criterion.flowed(1.0, 2.0));     // 2 bounds' worth of motion to stop
    EXPECT_TRUE(criterion.flowed(1.0, 0.001));   // still at the bound: continues
    EXPECT_FALSE(criterion.flowed(-1.0, 0.001)); // the other side, slack-sized: not the same flow
    EXPECT_FALSE(criterion.flowed(0.95, 0.0));
    EXPECT_FALSE(criterion.flowed(1.0, 0.001));  // mean ≈ 0.5: the solver's
}

// A flow the mean confirms late books the steps at the bound before it: 1 µm per step against a
// 10 N bound (mass 1 kg, dt 0.01 s: m·|Δx|/dt² = 1 % of the bound, within slack), held 39 steps,
// then the 40th confirms: 40 µm of flow and 10 N × 40 µm of work.
TEST(ElasticPlasticLaw, ALateConfirmedFlowBooksTheStepsAtTheBoundBeforeIt) {
    ElasticPlasticLaw law(DofLaw{10.0, 10.0, std::nullopt});
    law.start(0.0);
    for (int step = 1; step <= 40; ++step) {
        law.plan(-(step - 1) * 1e-6, 0.01, 1.0);
        law.settle(-step * 1e-6, 10.0);
        if (step < 40) {
            EXPECT_EQ(law.plastic_offset(), 0.0) << "step " << step;
        }
    }
    EXPECT_NEAR(law.plastic_offset(), -40e-6, 1e-18);
    EXPECT_NEAR(law.accumulated_plastic(), 40e-6, 1e-18);
    EXPECT_NEAR(law.dissipated(), 10.0 * 40e-6, 1e-15);
    EXPECT_TRUE(law.at_capacity());
}

// Motion that position corrections made (Bullet's split-impulse pushes) is booked with the flow it is
// part of, and reported apart: the same 40 steps, 0.25 µm of each step's 1 µm made by pushes, book
// 10 N × 40 × 0.25 µm = 0.1 mJ of the 0.4 mJ as dissipated by corrections; steps the hold takes back
// (below the bound) book none, and a reversal's work counts with its sign.
TEST(ElasticPlasticLaw, FlowDrivenByPositionCorrectionsIsBookedApart) {
    ElasticPlasticLaw law(DofLaw{10.0, 10.0, std::nullopt});
    law.start(0.0);
    for (int step = 1; step <= 40; ++step) {
        law.plan(-(step - 1) * 1e-6, 0.01, 1.0);
        law.settle(-step * 1e-6, 10.0, -0.25e-6);
    }
    EXPECT_NEAR(law.dissipated(), 10.0 * 40e-6, 1e-15);
    EXPECT_NEAR(law.dissipated_by_corrections(), 10.0 * 40 * 0.25e-6, 1e-15);
    // Below the bound: the hold takes the motion back, pushes or not; nothing is booked.
    const double before = law.dissipated_by_corrections();
    law.plan(-40e-6, 0.01, 1.0);
    law.settle(-40.5e-6, 5.0, -0.5e-6);
    EXPECT_EQ(law.dissipated_by_corrections(), before);
    EXPECT_NEAR(law.dissipated(), 10.0 * 40e-6, 1e-15);

    // On a joint: the per-dof motions pass through to each dof's law, and the joint sums them.
    PlasticJointSettings settings;
    settings.modes[index(Dof::Mx)] = settings.modes[index(Dof::N)] = DofMode::Plastic;
    settings.laws[index(Dof::Mx)] = settings.laws[index(Dof::N)] = DofLaw{10.0, 10.0, std::nullopt};
    PlasticJointLaw joint(settings);
    joint.start({});
    PerDof<double> at{}, force{}, pushed{};
    force[index(Dof::Mx)] = 10.0, force[index(Dof::N)] = -10.0;  // both at their bounds, opposite ways
    pushed[index(Dof::Mx)] = -1e-3, pushed[index(Dof::N)] = 2e-3;
    for (int step = 1; step <= 3; ++step) {
        joint.plan(at, 0.01, {1.0, 1.0, 1.0, 1.0, 1.0, 1.0});
        at[index(Dof::Mx)] = -step * 0.1, at[index(Dof::N)] = step * 0.1;  // an impact: flows at once
        joint.settle(at, force, 0.01 * step, pushed);
    }
    EXPECT_NEAR(joint.dissipated(), 3 * (10.0 * 0.1 + 10.0 * 0.1), 1e-12);
    EXPECT_NEAR(joint.dissipated_by_corrections(), 3 * (10.0 * 1e-3 + 10.0 * 2e-3), 1e-12);
}

// Paper eq. 3.2: a spring with √(k/m)·dt > 0.25 is too stiff to sample and holds rigid-plastic.
TEST(ElasticPlasticLaw, StiffSpringsFallBackToRigidPlastic) {
    ElasticPlasticLaw law(DofLaw{10.0, 10.0, 1e6});
    law.start(0.0);
    RowCommand c = law.plan(0.0, 0.01, 1.0);  // ω·dt = 1000 · 0.01 = 10
    EXPECT_EQ(law.regime(), Regime::StiffRigidPlastic);
    EXPECT_EQ(c.kind, RowCommand::Kind::Hold);
    EXPECT_NEAR(law.omega_dt(), 10.0, 1e-12);
    c = law.plan(0.0, 0.0025, 1.0);  // ω·dt = 2.5 still
    EXPECT_EQ(law.regime(), Regime::StiffRigidPlastic);
    c = law.plan(0.0, 0.0002, 1.0);  // ω·dt = 0.2 ≤ 0.25: elastic-plastic
    EXPECT_EQ(law.regime(), Regime::ElasticPlastic);
    EXPECT_EQ(c.kind, RowCommand::Kind::Push);
}

// ω·dt = √(k/m)·dt (paper eq. 3.2), as the law reports it: derived from the m/dt² it keeps, so 0
// before any plan, and infinite for a row of no effective mass (which holds rigid-plastic).
TEST(ElasticPlasticLaw, ReportsOmegaDtOfTheLastPlan) {
    ElasticPlasticLaw law(DofLaw{10.0, 10.0, 400.0});
    law.start(0.0);
    EXPECT_EQ(law.omega_dt(), 0.0);
    law.plan(0.0, 0.01, 4.0);  // √(400/4)·0.01 = 0.1
    EXPECT_NEAR(law.omega_dt(), 0.1, 1e-15);
    EXPECT_EQ(law.regime(), Regime::ElasticPlastic);
    law.plan(0.0, 0.01, 0.0);
    EXPECT_EQ(law.omega_dt(), INFINITY);
    EXPECT_EQ(law.regime(), Regime::StiffRigidPlastic);
    ElasticPlasticLaw rigid(DofLaw{10.0, 10.0, std::nullopt});
    rigid.start(0.0);
    rigid.plan(0.0, 0.01, 4.0);
    EXPECT_EQ(rigid.omega_dt(), 0.0);  // no spring
}

// A law moved into place (as a joint's laws are) keeps its books.
TEST(ElasticPlasticLaw, AMovedLawKeepsItsBooks) {
    ElasticPlasticLaw law(DofLaw{10.0, 20.0, 100.0});
    law.start(0.0);
    law.plan(0.0, 0.01, 1.0);
    law.settle(0.3, 0.0);  // trial −30 passes −10: x_p moves to 0.3 − 10/100 = 0.2
    ElasticPlasticLaw moved(std::move(law));
    EXPECT_NEAR(moved.plastic_offset(), 0.2, 1e-15);
    EXPECT_NEAR(moved.accumulated_plastic(), 0.2, 1e-15);
    EXPECT_NEAR(moved.dissipated(), 10.0 * 0.2, 1e-14);  // capacity × plastic motion
    EXPECT_TRUE(moved.moved());
}

// A copy of a law is a law of its own: stepping it leaves the original's books as they were.
TEST(ElasticPlasticLaw, ACopyKeepsBooksOfItsOwn) {
    ElasticPlasticLaw law(DofLaw{10.0, 20.0, 100.0});
    law.start(0.0);
    law.plan(0.0, 0.01, 1.0);
    law.settle(0.3, 0.0);  // x_p → 0.2, dissipated 10 · 0.2
    ElasticPlasticLaw copy = law;
    copy.plan(0.3, 0.01, 1.0);
    copy.settle(0.5, 0.0);  // trial −100·(0.5 − 0.2) = −30 passes −10: x_p → 0.4, another 10 · 0.2
    EXPECT_NEAR(copy.accumulated_plastic(), 0.4, 1e-15);
    EXPECT_NEAR(copy.dissipated(), 4.0, 1e-14);
    EXPECT_NEAR(law.accumulated_plastic(), 0.2, 1e-15);
    EXPECT_NEAR(law.dissipated(), 2.0, 1e-14);
    law = copy;  // and assigned, it takes the copy's books
    EXPECT_NEAR(law.dissipated(), 4.0, 1e-14);
}

// The joint breaks when Σ|Δx_p| over the translations passes its limit, and stays broken.
TEST(PlasticJointLaw, BreaksAtTheSummedPlasticDisplacementAndStaysBroken) {
    PlasticJointSettings s;
    s.modes.fill(DofMode::Rigid);
    s.modes[index(Dof::N)] = DofMode::Plastic;
    s.modes[index(Dof::Qx)] = DofMode::Plastic;
    s.modes[index(Dof::Mz)] = DofMode::Plastic;
    s.laws[index(Dof::N)] = DofLaw{10.0, 10.0, std::nullopt};
    s.laws[index(Dof::Qx)] = DofLaw{5.0, 5.0, std::nullopt};
    s.laws[index(Dof::Mz)] = DofLaw{1.0, 1.0, std::nullopt};
    s.max_plastic_displacement = 0.01;
    s.max_plastic_rotation = 0.1;
    PlasticJointLaw joint(s);
    PerDof<double> x{};
    joint.start(x);
    const PerDof<double> masses{1, 1, 1, 1, 1, 1};
    for (int step = 1; step <= 3; ++step) {
        joint.plan(x, 0.01, masses);
        x[index(Dof::N)] -= 0.003;   // flows 3 mm per step at +10 N
        x[index(Dof::Qx)] -= 0.001;  // and 1 mm at +5 N
        x[index(Dof::Mz)] -= 0.01;   // and 0.01 rad at +1 N·m (its own limit is far)
        const PerDof<double> f{5.0, 10.0, 0.0, 0.0, 0.0, 1.0};
        const bool broke = joint.settle(x, f, 0.01 * step);
        EXPECT_EQ(broke, step == 3) << step;  // 4, 8, then 12 mm > 10 mm
    }
    ASSERT_TRUE(joint.broken());
    EXPECT_NEAR(*joint.broken_at(), 0.03, 1e-15);
    EXPECT_NEAR(joint.plastic_displacement(), 0.012, 1e-15);
    EXPECT_NEAR(joint.plastic_rotation(), 0.03, 1e-15);
    EXPECT_NEAR(joint.dissipated(), 3 * (10 * 0.003 + 5 * 0.001 + 1 * 0.01), 1e-14);
    x[index(Dof::N)] -= 1.0;
    EXPECT_FALSE(joint.settle(x, PerDof<double>{5.0, 10.0, 0, 0, 0, 1.0}, 0.04));  // ignored
    EXPECT_NEAR(joint.plastic_displacement(), 0.012, 1e-15);
    EXPECT_EQ(joint.law(Dof::Qz), nullptr);  // rigid dofs have no law
}

// A joint turned 90° about the world z: x_j = (0, 1, 0), y_j = (−1, 0, 0), z_j = (0, 0, 1); the
// anchor at the origin, b's centre at (1, 0, 0). F = (3, 4, 5) N on b, no torque about the centre:
// moment about the anchor = (c − anchor) × F = (1, 0, 0) × (3, 4, 5) = (0, −5, 4).
TEST(JointLoads, TurnedJointTakesComponentsAndTransfersTheMoment) {
    JointAxesInWorld axes;
    axes.anchor = {0, 0, 0};
    axes.translation = {Vec3{0, 1, 0}, Vec3{-1, 0, 0}, Vec3{0, 0, 1}};
    axes.rotation = axes.translation;
    const PerDof<double> q = joint_frame_loads(WorldLoad{{3, 4, 5}, {0, 0, 0}}, {1, 0, 0}, axes);
    EXPECT_DOUBLE_EQ(q[index(Dof::Qx)], 4.0);
    EXPECT_DOUBLE_EQ(q[index(Dof::N)], -3.0);
    EXPECT_DOUBLE_EQ(q[index(Dof::Qz)], 5.0);
    EXPECT_DOUBLE_EQ(q[index(Dof::Mx)], -5.0);
    EXPECT_DOUBLE_EQ(q[index(Dof::My)], 0.0);
    EXPECT_DOUBLE_EQ(q[index(Dof::Mz)], 4.0);
    // A torque about the centre adds as it is.
    const PerDof<double> t = joint_frame_loads(WorldLoad{{0, 0, 0}, {0, 0, 2}}, {1, 0, 0}, axes);
    EXPECT_DOUBLE_EQ(t[index(Dof::Mz)], 2.0);
}

// Euler rows are not orthogonal: the moment is split in their basis. M = (1, 1, 0) on
// e0 = (1, 0, 0), e1 = (1, 1, 0)/√2, e2 = (0, 0, 1) is 0·e0 + √2·e1 + 0·e2 (projections would
// give 1, √2, 0).
TEST(JointLoads, NonOrthogonalRotationAxesSplitTheMomentExactly) {
    JointAxesInWorld axes;
    axes.translation = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    axes.rotation = {Vec3{1, 0, 0}, Vec3{1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0}, Vec3{0, 0, 1}};
    const PerDof<double> q = joint_frame_loads(WorldLoad{{0, 0, 0}, {1, 1, 0}}, {0, 0, 0}, axes);
    EXPECT_NEAR(q[index(Dof::Mx)], 0.0, 1e-15);
    EXPECT_NEAR(q[index(Dof::My)], std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(q[index(Dof::Mz)], 0.0, 1e-15);
}

Mat3 rotation_x(double a) { return {{{1, 0, 0}, {0, std::cos(a), -std::sin(a)}, {0, std::sin(a), std::cos(a)}}}; }
Mat3 rotation_y(double a) { return {{{std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}}}; }
Mat3 rotation_z(double a) { return {{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}}}; }
Mat3 product(const Mat3& a, const Mat3& b) {
    Mat3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
    return m;
}

// R = Aᵀ·B = Rz(θz)·Ry(θy)·Rx(θx): the measured angles are the ones put in, also within a degree of
// the singular θy = 90°, and the translation is b's anchor minus a's along a's axes.
TEST(JointFrame, MeasuresEulerAnglesUpToADegreeFromTheSingularTwist) {
    for (double theta_y_degrees : {0.0, 30.0, -60.0, 89.0, -89.0}) {
        const double ty = theta_y_degrees * kPi / 180.0, tx = 0.3, tz = -0.4;
        Pose a;
        a.rotation = rotation_z(0.7);  // a itself turned
        a.origin = {1, 2, 3};
        Pose b;
        b.rotation = product(a.rotation, product(rotation_z(tz), product(rotation_y(ty), rotation_x(tx))));
        const Vec3 offset_in_a = {0.01, -0.02, 0.03};
        b.origin = {a.origin[0], a.origin[1], a.origin[2]};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) b.origin[i] += a.rotation[i][j] * offset_in_a[j];
        const JointFrameState s = measure_joint(a, b);
        EXPECT_NEAR(s.positions[index(Dof::Mx)], tx, 1e-9) << theta_y_degrees;
        EXPECT_NEAR(s.positions[index(Dof::My)], ty, 1e-9) << theta_y_degrees;
        EXPECT_NEAR(s.positions[index(Dof::Mz)], tz, 1e-9) << theta_y_degrees;
        EXPECT_NEAR(s.positions[index(Dof::Qx)], 0.01, 1e-12);
        EXPECT_NEAR(s.positions[index(Dof::N)], -0.02, 1e-12);
        EXPECT_NEAR(s.positions[index(Dof::Qz)], 0.03, 1e-12);
    }
}

// The pose of b for Euler angles (θx, θy, θz) relative to a = the world (joint_frame.hpp's R = Rz·Ry·Rx).
Pose euler_pose(double tx, double ty, double tz) {
    Pose b;
    b.rotation = product(rotation_z(tz), product(rotation_y(ty), rotation_x(tx)));
    return b;
}

// The rotation vector of the small turn from R0 to R1 (world frame): the axial vector of R1·R0ᵀ's
// antisymmetric part, exact to second order in the turn.
Vec3 small_turn(const Mat3& r0, const Mat3& r1) {
    Mat3 d{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) d[i][j] += r1[i][k] * r0[j][k];
    return {0.5 * (d[2][1] - d[1][2]), 0.5 * (d[0][2] - d[2][0]), 0.5 * (d[1][0] - d[0][1])};
}

// A bending row flowing at capacity C on a hinge twisted by θy = 60°: the work its moment −C·e_x does
// is Σ −C·e_x·Δφ over the turns Δφ of b (measured here from the poses, not from the law's formula),
// and the law must book that as dissipated, C·cos θy·Δθx — half of C·Δθx.
TEST(PlasticJointLaw, ATwistedHingeDissipatesTheWorkItsRowsDo) {
    PlasticJointSettings s;
    s.modes.fill(DofMode::Rigid);
    s.modes[index(Dof::Mx)] = DofMode::Plastic;
    const double C = 10.0, ty = kPi / 3, tz = 0.2;
    s.laws[index(Dof::Mx)] = DofLaw{C, C, std::nullopt};
    PlasticJointLaw joint(s);
    JointFrameState state = measure_joint(Pose{}, euler_pose(0, ty, tz));
    joint.start(state.positions);
    double work = 0.0;
    for (int k = 1; k <= 100; ++k) {
        joint.plan(state.positions, 0.01, {});
        const JointFrameState next = measure_joint(Pose{}, euler_pose(0.001 * k, ty, tz));
        const Vec3 turn = small_turn(euler_pose(0.001 * (k - 1), ty, tz).rotation, euler_pose(0.001 * k, ty, tz).rotation);
        const Vec3& e = state.axes.rotation[0];  // the row's axis at the step's start
        work += C * (e[0] * turn[0] + e[1] * turn[1] + e[2] * turn[2]);  // the resisting moment's work, sign flipped
        PerDof<double> f{};
        f[index(Dof::Mx)] = -C;  // at capacity, against the motion
        joint.settle(next.positions, f, 0.01 * k);
        state = next;
    }
    EXPECT_NEAR(joint.plastic_rotation(), 0.1, 1e-12);
    EXPECT_NEAR(work, C * 0.1 * std::cos(ty), 1e-4 * work);  // the kinematics: e_x·g_x = cos θy
    EXPECT_NEAR(joint.dissipated(), work, 1e-4 * work);
}

// A hinge twisting through 90°: engines report |θy| ≤ 90°, so past it the measured triple jumps to
// the other branch (θx + π, π − θy, θz + π), and the engine's twist runs backwards. A bending row
// flowing at capacity 1 mrad a step must accumulate only that motion — not the π jumps — and a
// twisting row flowing at capacity, its force against the engine's twist rate as a row's is, must
// dissipate C·|Δθy| (positive work), not book the second half as energy created.
TEST(PlasticJointLaw, AHingeTwistingThroughNinetyDegreesStaysContinuous) {
    PlasticJointSettings s;
    s.modes.fill(DofMode::Free);
    s.modes[index(Dof::Mx)] = DofMode::Plastic;
    s.modes[index(Dof::My)] = DofMode::Plastic;
    s.laws[index(Dof::Mx)] = DofLaw{1.0, 1.0, std::nullopt};
    s.laws[index(Dof::My)] = DofLaw{2.0, 2.0, std::nullopt};
    PlasticJointLaw joint(s);
    const auto measured = [](int k) { return measure_joint(Pose{}, euler_pose(0.2 + 0.001 * k, 1.4 + 0.01 * k, -0.3)).positions; };
    joint.start(measured(0));
    bool crossed = false;
    for (int k = 1; k <= 40; ++k) {  // θy from 1.4 to 1.8 rad
        joint.plan(measured(k - 1), 0.01, {});
        const PerDof<double> x = measured(k);
        crossed = crossed || std::abs(x[index(Dof::Mx)] - 0.2) > 1.0;  // the engine's branch has jumped
        PerDof<double> f{};
        f[index(Dof::Mx)] = -1.0;
        f[index(Dof::My)] = x[index(Dof::My)] > measured(k - 1)[index(Dof::My)] ? -2.0 : 2.0;  // against the engine's rate
        joint.settle(x, f, 0.01 * k);
    }
    EXPECT_TRUE(crossed);
    EXPECT_NEAR(joint.plastic_rotation(), 0.04 + 0.4, 1e-9);
    EXPECT_NEAR(joint.law(Dof::Mx)->plastic_offset(), 0.24, 1e-9);  // continuous: 0.2 + 40 mrad
    EXPECT_NEAR(joint.law(Dof::My)->plastic_offset(), 1.8, 1e-9);
    EXPECT_NEAR(joint.law(Dof::My)->dissipated(), 2.0 * 0.4, 1e-9);
}

// Two moving bodies on one row, 1/(J·M⁻¹·Jᵀ) by hand: b (2 kg, I⁻¹ = diag(1, 1/2, 1/3), centre
// (0, 1, 0)) and a (4 kg, I⁻¹ = diag(1/4), centre (0, −1, 0)), anchor at the origin. The x row:
// b's lever (0, −1, 0) × x = (0, 0, 1) → 1/2 + 1/3; a's (0, 1, 0) × x = (0, 0, −1) → 1/4 + 1/4;
// m = 1/(4/3) = 0.75 kg. The rotation row about z: 1/(1/3 + 1/4) = 12/7 kg·m².
TEST(RowEffectiveMass, TwoMovingBodiesMatchTheClosedForm) {
    JointAxesInWorld axes;
    axes.anchor = {0, 0, 0};
    axes.translation = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    axes.rotation = axes.translation;
    const BodyInertia b{0.5, {{{1, 0, 0}, {0, 0.5, 0}, {0, 0, 1.0 / 3}}}, {0, 1, 0}};
    const BodyInertia a{0.25, {{{0.25, 0, 0}, {0, 0.25, 0}, {0, 0, 0.25}}}, {0, -1, 0}};
    const PerDof<double> m = row_effective_masses(axes, b, a);
    EXPECT_NEAR(m[index(Dof::Qx)], 0.75, 1e-15);
    EXPECT_NEAR(m[index(Dof::N)], 1.0 / (0.5 + 0.25), 1e-15);  // along the levers: no rotation
    EXPECT_NEAR(m[index(Dof::Mz)], 12.0 / 7.0, 1e-14);
    EXPECT_NEAR(m[index(Dof::Mx)], 1.0 / (1.0 + 0.25), 1e-15);
    // Against the world (a absent) only b counts.
    EXPECT_NEAR(row_effective_masses(axes, b, std::nullopt)[index(Dof::Qx)], 1.0 / (0.5 + 1.0 / 3), 1e-15);
}

}  // namespace

namespace {

// A coupled condition in closed form: a circle in (Mx, Mz) of radius C, U = √(Mx² + Mz²)/C, the
// other loads ignored (what a round bar's bending surface is at N = 0).
class CircleInMxMz final : public YieldCondition {
public:
    explicit CircleInMxMz(double c) : c_(c) {}
    YieldEvaluation evaluate(const PerDof<double>& l, YieldHint&) const override {
        const double mx = l[index(Dof::Mx)], mz = l[index(Dof::Mz)], r = std::hypot(mx, mz);
        YieldEvaluation e;
        e.utilisation = r / c_;
        if (r > 0) e.gradient[index(Dof::Mx)] = mx / (r * c_), e.gradient[index(Dof::Mz)] = mz / (r * c_);
        return e;
    }
    PerDof<double> axis_capacity(bool) const override { return {0, 0, 0, c_, 0, c_}; }

private:
    double c_;
};

PlasticJointSettings circle_joint(double c, std::optional<double> k) {
    PlasticJointSettings s;
    s.modes.fill(DofMode::Rigid);
    s.modes[index(Dof::Mx)] = s.modes[index(Dof::Mz)] = DofMode::Plastic;
    s.laws[index(Dof::Mx)] = s.laws[index(Dof::Mz)] = DofLaw{c, c, k};
    s.yield_condition = std::make_shared<CircleInMxMz>(c);
    return s;
}

PerDof<double> moments(double mx, double mz) {
    PerDof<double> f{};
    f[index(Dof::Mx)] = mx, f[index(Dof::Mz)] = mz;
    return f;
}

// Rigid-plastic rows on the circle C = 10 N·m. A load (−6, −6) on b (section load (6, 6), U = 0.6√2)
// gives each row the larger of the ray's point, 6/U = 10/√2 (where the rows saturate together), and
// the tangent plane's reach in its own component, 6 + (1 − U)/(∂U/∂s) = 10√2 − 6 = 8.14 (the box of
// independent limits would give 10). A row the last load did not use (no slope) keeps the
// cross-polytope's C·(1 − Σ others/C): after (0, −6) the Mx row gets 10·(1 − 0.6) = 4, the Mz row the
// radial 6/0.6 = 10.
TEST(CoupledYield, RigidPlasticRowBoundsFollowTheSurfaceAlongTheLastLoad) {
    PlasticJointLaw law(circle_joint(10.0, std::nullopt));
    const PerDof<double> zero{}, masses{1, 1, 1, 1, 1, 1};
    law.start(zero);
    auto plan = law.plan(zero, 0.01, masses);
    EXPECT_DOUBLE_EQ(plan[index(Dof::Mx)]->bound, 10.0);  // nothing known yet: the dof's own capacity
    law.settle(zero, moments(-6, -6), 0.01);
    plan = law.plan(zero, 0.01, masses);
    EXPECT_NEAR(plan[index(Dof::Mx)]->bound, 10.0 * std::sqrt(2.0) - 6.0, 1e-12);
    EXPECT_NEAR(plan[index(Dof::Mz)]->bound, 10.0 * std::sqrt(2.0) - 6.0, 1e-12);
    law.settle(zero, moments(0, -6), 0.02);
    plan = law.plan(zero, 0.01, masses);
    EXPECT_NEAR(plan[index(Dof::Mx)]->bound, 4.0, 1e-12);
    EXPECT_NEAR(plan[index(Dof::Mz)]->bound, 10.0, 1e-12);
    // At the bound the rows flow, and their work is dissipated.
    PerDof<double> moved = zero;
    moved[index(Dof::Mz)] = 0.01;
    law.settle(moved, moments(0, -10), 0.03);
    EXPECT_NEAR(law.dissipated(), 10 * 0.01, 1e-15);
}

// A sphere in (N, Mx, Mz): U = √((N/Cn)² + (Mx/C)² + (Mz/C)²), the other loads ignored; N rigid
// and the moments plastic, as a structure's segment joint has them (docs/structures.md).
class SphereInNMxMz final : public YieldCondition {
public:
    SphereInNMxMz(double cn, double c) : cn_(cn), c_(c) {}
    YieldEvaluation evaluate(const PerDof<double>& l, YieldHint&) const override {
        const double n = l[index(Dof::N)] / cn_, mx = l[index(Dof::Mx)] / c_, mz = l[index(Dof::Mz)] / c_;
        YieldEvaluation e;
        e.utilisation = std::sqrt(n * n + mx * mx + mz * mz);
        if (e.utilisation > 0) {
            e.gradient[index(Dof::N)] = n / (cn_ * e.utilisation);
            e.gradient[index(Dof::Mx)] = mx / (c_ * e.utilisation);
            e.gradient[index(Dof::Mz)] = mz / (c_ * e.utilisation);
        }
        return e;
    }
    PerDof<double> axis_capacity(bool) const override {
        const double none = std::numeric_limits<double>::infinity();
        return {none, cn_, none, c_, none, c_};
    }

private:
    double cn_, c_;
};

PlasticJointSettings sphere_joint(std::optional<double> k) {
    PlasticJointSettings s = circle_joint(10.0, k);
    s.yield_condition = std::make_shared<SphereInNMxMz>(100.0, 10.0);
    return s;
}

PerDof<double> axial(double n, double mx) {  // the row forces on b for section loads N, Mx
    PerDof<double> f{};
    f[index(Dof::N)] = -n, f[index(Dof::Mx)] = -mx;
    return f;
}

// Cn = 100 N, C = 10 N·m. A rigid N loaded to 50 leaves each unloaded moment row the cross-polytope's
// C·(1 − 50/100) = 5. Loaded past its axis capacity (200, which a rigid row lets through), N counts
// as 0.9·Cn (kRigidShare): each row keeps C·(1 − 0.9) = 1, the same as at N = 90 — not the 0 that
// made a fixed–fixed beam's catenary whirl its hinges.
TEST(CoupledYield, ARigidDofsLoadCountsOnTheSurfaceUpToNinetyPercentOfItsAxis) {
    const PerDof<double> zero{}, masses{1, 1, 1, 1, 1, 1};
    for (const auto& [n, bound] : {std::pair{50.0, 5.0}, std::pair{90.0, 1.0}, std::pair{200.0, 1.0}, std::pair{-1e6, 1.0}}) {
        PlasticJointLaw law(sphere_joint(std::nullopt));
        law.start(zero);
        law.settle(zero, axial(n, 0.0), 0.01);
        const auto plan = law.plan(zero, 0.01, masses);
        EXPECT_NEAR(plan[index(Dof::Mx)]->bound, bound, 1e-12) << "N = " << n;
        EXPECT_NEAR(plan[index(Dof::Mz)]->bound, bound, 1e-12) << "N = " << n;
    }
}

// Elastic-plastic moments (k = 1000 N·m/rad) beside a rigid N at 200 = 2·Cn: a spring load Mx = 4
// is inside the surface at N = 0.9·Cn (U = √(0.81 + 0.16) < 1) and does not flow; Mx = 5 returns to
// it, Mx = 10·√(1 − 0.81) = 4.359, Δθ_p = (5 − 4.359)/k (uncapped, U ≥ 2 would have flowed both).
TEST(CoupledYield, ElasticPlasticMomentsBesideARigidDofPastItsAxisReturnToTheCappedSurface) {
    const PerDof<double> zero{}, masses{1, 1, 1, 1, 1, 1};
    for (const auto& [theta, flow] : {std::pair{0.004, 0.0}, std::pair{0.005, (5.0 - 10.0 * std::sqrt(0.19)) / 1000.0}}) {
        PlasticJointLaw law(sphere_joint(1000.0));
        law.start(zero);
        law.plan(zero, 1e-3, masses);
        PerDof<double> at{};
        at[index(Dof::Mx)] = theta;
        law.settle(at, axial(200.0, 0.0), 1e-3);
        EXPECT_NEAR(law.law(Dof::Mx)->plastic_offset(), flow, 1e-9) << "Mx = " << 1000 * theta << " N m";
        EXPECT_EQ(law.law(Dof::Mz)->plastic_offset(), 0.0);
    }
}

// The report's utilisation: on the circle C = 10 the section load (6, 8) has U = |(6, 8)|/10 = 1
// (the exact U: the share 1.4 is past 1/2);
// without a condition, each plastic dof's load over its own side's capacity, the largest counting:
// N's load 6 of N⁺ = 10 (0.6), Mz's −3 of Mz⁻ = 4 (0.75); rigid dofs' loads do not count.
TEST(PlasticJointLaw, UtilisationIsTheSurfacesUOrTheLargestShareOfASidesCapacity) {
    PlasticJointLaw coupled(circle_joint(10.0, std::nullopt));
    const PerDof<double> zero{};
    coupled.start(zero);
    EXPECT_EQ(coupled.utilisation(), 0.0);
    coupled.settle(zero, moments(-6, -8), 0.01);
    EXPECT_NEAR(coupled.utilisation(), 1.0, 1e-14);
    coupled.settle(zero, moments(3, 0), 0.02);
    EXPECT_NEAR(coupled.utilisation(), 0.3, 1e-14);
    // Far inside (Σ|s|/C = 0.4 ≤ 1/2) the cheap upper bound, not U = √8/10 = 0.283.
    coupled.settle(zero, moments(2, 2), 0.03);
    EXPECT_NEAR(coupled.utilisation(), 0.4, 1e-14);

    PlasticJointSettings s;
    s.modes.fill(DofMode::Rigid);
    s.modes[index(Dof::N)] = s.modes[index(Dof::Mz)] = DofMode::Plastic;
    s.laws[index(Dof::N)] = DofLaw{10.0, 5.0, std::nullopt};
    s.laws[index(Dof::Mz)] = DofLaw{2.0, 4.0, std::nullopt};
    PlasticJointLaw box(s);
    box.start(zero);
    PerDof<double> f{};
    f[index(Dof::N)] = -6.0, f[index(Dof::Mz)] = 3.0, f[index(Dof::Qx)] = 1e6;
    box.settle(zero, f, 0.01);
    EXPECT_NEAR(box.utilisation(), 0.75, 1e-15);
    f[index(Dof::N)] = 4.5;  // load −4.5 on N⁻ = 5
    box.settle(zero, f, 0.02);
    EXPECT_NEAR(box.utilisation(), 0.9, 1e-15);
}

// Elastic-plastic, k = 1000 N·m/rad per dof, C = 10: a trial (12, 5) outside the circle returns to
// it along the normal, (12, 5)·10/13, with Δθ_p = (13 − 10)/k along (12, 5)/13 (radial return is
// exact for a circle with equal stiffnesses); the energy dissipated is the load times Δθ_p.
TEST(CoupledYield, ElasticPlasticReturnMappingIsAssociated) {
    PlasticJointLaw law(circle_joint(10.0, 1000.0));
    const PerDof<double> zero{}, masses{1, 1, 1, 1, 1, 1};
    law.start(zero);
    law.plan(zero, 1e-3, masses);
    PerDof<double> at{};
    at[index(Dof::Mx)] = 0.012, at[index(Dof::Mz)] = 0.005;  // spring loads 12 and 5 N·m
    law.settle(at, zero, 1e-3);
    const double dp = 3.0 / 1000.0;
    EXPECT_NEAR(law.law(Dof::Mx)->plastic_offset(), dp * 12 / 13, 1e-12);
    EXPECT_NEAR(law.law(Dof::Mz)->plastic_offset(), dp * 5 / 13, 1e-12);
    EXPECT_NEAR(law.dissipated(), 10.0 * dp, 1e-12);
    const auto plan = law.plan(at, 1e-3, masses);
    EXPECT_NEAR(std::hypot(plan[index(Dof::Mx)]->force, plan[index(Dof::Mz)]->force), 10.0, 1e-9);
}

}  // namespace
