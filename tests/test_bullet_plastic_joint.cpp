// The Bullet adapter against analytic references (issue 6, "Prove it" 1–8). The single-degree-of-
// freedom elastic–perfectly-plastic oscillator and the rigid-plastic block are from
// ../shared/reference/values.md; the tension block is the paper's §3 (Table 3.5, 3.6).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bullet_scenes.hpp"

namespace plascap::test {
namespace {

double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
double min_of(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// Suddenly loaded elastic–perfectly-plastic oscillator, F/2 < W < F (values.md): peak d, residual.
struct Oscillator {
    double W, F, k;
    double peak() const { return F * F / (2 * k * (F - W)); }
    double residual() const { return peak() - F / k; }
};

TEST(BulletPrecision, LinkedLibraryComputesInTheHeadersPrecision) {
    // Free fall under symplectic Euler: y_n = −g·h²·n(n+1)/2 exactly. A library built for the
    // other btScalar would read the bodies' fields at the wrong offsets or round at 1e-7.
    HangingBlock s;
    s.capacity = 1e-9;  // the joint holds nothing: free fall
    s.g = 9.81;
    s.steps = 200;
    const Trace t = run(s);
    const double n = s.steps;
    const double a = s.g - s.capacity / s.mass;
    const double exact = -0.5 - a * s.dt * s.dt * n * (n + 1) / 2;
    const double tolerance = sizeof(btScalar) == 8 ? 1e-12 : 1e-5;
    EXPECT_NEAR(t.body_y.back(), exact, tolerance * std::abs(exact));
#ifdef BT_USE_DOUBLE_PRECISION
    static_assert(sizeof(btScalar) == 8, "BT_USE_DOUBLE_PRECISION must mean a double btScalar");
#endif
}

TEST(BulletRigidPlastic, BelowCapacityHoldsAndCarriesTheWeight) {
    HangingBlock s;  // W = 10 N, F = 20 N
    const Trace t = run(s);
    EXPECT_LT(std::abs(t.position.back()), 1e-9);
    EXPECT_NEAR(t.force.back(), s.mass * s.g, 1e-6 * s.mass * s.g);
    EXPECT_LT(max_of(t.plastic), 1e-9);
}

TEST(BulletRigidPlastic, AboveCapacityAcceleratesDissipatesAndBreaks) {
    HangingBlock s;
    s.mass = 3.0;
    s.capacity = 18.0;  // W = 30 N: a = (W − F)/m = 4 m/s²
    s.max_plastic_displacement = 0.5;
    s.steps = 200;
    const Trace t = run(s);
    const double a = (s.mass * s.g - s.capacity) / s.mass;
    // Before breaking: x_n = −a·h²·n(n+1)/2 (symplectic Euler); the acceleration within 1 %.
    const int n = 30;
    const double expected = -a * s.dt * s.dt * n * (n + 1) / 2;
    EXPECT_NEAR(t.position[n - 1], expected, 0.01 * std::abs(expected));
    EXPECT_NEAR(t.force[n - 1], s.capacity, 1e-6 * s.capacity);
    // Dissipated energy = F × plastic displacement.
    EXPECT_NEAR(t.dissipated[n - 1], s.capacity * t.plastic[n - 1], 1e-9 * t.dissipated[n - 1]);
    // Breaks once 0.5 m has flowed: a·h²·n(n+1)/2 > 0.5 first at n = 50 (t = 0.50 s).
    ASSERT_GT(t.broken_at, 0.0);
    EXPECT_NEAR(t.broken_at, 0.50, 1e-9);
    // Then it falls freely (g) and stays broken.
    const std::size_t last = t.body_y.size() - 1;
    const double accel = (t.body_y[last] - 2 * t.body_y[last - 1] + t.body_y[last - 2]) / (s.dt * s.dt);
    EXPECT_NEAR(accel, -s.g, 1e-6 * s.g);
}

TEST(BulletElasticPlastic, ElasticOscillatorPeaksAtTwiceTheStaticDeflection) {
    HangingBlock s;  // m = 1, k = 100: ω = 10, ω·dt = 0.1
    s.stiffness = 100.0;
    s.capacity = 25.0;  // W = 10 ≤ F/2: stays elastic
    s.steps = 400;
    const Trace t = run(s);
    const double statical = s.mass * s.g / *s.stiffness;  // W/k
    EXPECT_NEAR(-min_of(t.position), 2 * statical, 0.02 * 2 * statical);
    // The mean over whole periods is the static deflection.
    double mean = 0;
    const int period_steps = static_cast<int>(std::lround(2 * M_PI / 10 / s.dt * 6));  // ≈ 6 periods
    for (int i = 0; i < period_steps; ++i) mean += t.position[i];
    EXPECT_NEAR(-mean / period_steps, statical, 0.02 * statical);
    EXPECT_EQ(max_of(t.plastic), 0.0);
}

class SuddenLoad : public ::testing::TestWithParam<double> {};  // ω·dt

TEST_P(SuddenLoad, PeakAndResidualPlasticDisplacementWithin2Percent) {
    HangingBlock s;
    s.stiffness = 100.0;
    s.dt = GetParam() / 10.0;
    s.capacity = 10.0 / 0.75;  // W = 0.75 F
    s.steps = static_cast<int>(4.0 / s.dt);
    const Trace t = run(s);
    const Oscillator o{s.mass * s.g, s.capacity, *s.stiffness};
    EXPECT_NEAR(-min_of(t.position), o.peak(), 0.02 * o.peak());
    EXPECT_NEAR(t.plastic.back(), o.residual(), 0.02 * o.residual());
    EXPECT_NEAR(t.dissipated.back(), o.F * o.residual(), 0.02 * o.F * o.residual());
}

INSTANTIATE_TEST_SUITE_P(OmegaDt, SuddenLoad, ::testing::Values(0.01, 0.03, 0.1));

// The paper develops both of Bullet's 6-dof spring constraints: the first one
// (btGeneric6DofSpringConstraint) gives the same results through BulletPlasticJoint6DofSpring.
TEST(BulletFirstSpringConstraint, SameAnalyticResultsAsSpring2) {
    HangingBlock oscillator;
    oscillator.stiffness = 100.0;
    oscillator.capacity = 10.0 / 0.75;
    oscillator.steps = 400;
    HangingBlock flow;
    flow.mass = 3.0;
    flow.capacity = 18.0;
    flow.max_plastic_displacement = 0.5;
    flow.steps = 100;
    Cantilever rod;
    rod.capacity = 10.0 / 0.75;
    rod.dt = 0.001;
    rod.stiffness = 100.0 * 100.0 * rod.inertia_about_anchor();
    for (bool spring1 : {false, true}) {
        oscillator.spring1 = flow.spring1 = rod.spring1 = spring1;
        const Trace o = run(oscillator), f = run(flow), r = run(rod);
        const Oscillator linear{oscillator.mass * oscillator.g, oscillator.capacity, *oscillator.stiffness};
        EXPECT_NEAR(o.plastic.back(), linear.residual(), 0.02 * linear.residual()) << "spring1 " << spring1;
        EXPECT_NEAR(f.broken_at, 0.50, 1e-9) << "spring1 " << spring1;
        const Oscillator angular{rod.mass * rod.g * rod.length / 2, rod.capacity, *rod.stiffness};
        EXPECT_NEAR(r.plastic.back(), angular.residual(), 0.02 * angular.residual()) << "spring1 " << spring1;
    }
}

TEST(BulletElasticPlastic, UnloadsWithSlopeK) {
    HangingBlock s;
    s.stiffness = 100.0;
    s.dt = 0.005;
    s.capacity = 10.0 / 0.75;
    s.steps = 800;
    const Trace t = run(s);
    // After the peak the dof springs back elastically: Δf/Δx = −k between two later samples. The
    // force of step i comes from the position at its start, the end of step i − 1.
    const std::size_t peak = std::min_element(t.position.begin(), t.position.end()) - t.position.begin();
    const std::size_t i = peak + 10, j = peak + 25;
    const double slope = (t.force[j] - t.force[i]) / (t.position[j - 1] - t.position[i - 1]);
    EXPECT_NEAR(slope, -*s.stiffness, 0.03 * *s.stiffness);
}

TEST(BulletElasticPlastic, RotationalDofWithALeverArm) {
    Cantilever s;  // moment of the weight about the anchor: m·g·L/2 = 10 N·m
    const double moment = s.mass * s.g * s.length / 2;
    s.capacity = moment / 0.75;
    s.dt = 0.001;
    const double omega = 0.1 / s.dt;  // ω·dt = 0.1 about the anchor; rotations stay below 0.005 rad
    s.stiffness = omega * omega * s.inertia_about_anchor();
    s.steps = 300;
    const Trace t = run(s);
    const Oscillator o{moment, s.capacity, *s.stiffness};
    EXPECT_NEAR(max_of(t.position), o.peak(), 0.02 * o.peak());
    EXPECT_NEAR(t.plastic.back(), o.residual(), 0.02 * o.residual());
}

TEST(BulletRigidPlastic, RotationalDofFlowsAtItsCapacity) {
    Cantilever s;  // rigid-plastic: M = 10 N·m against M_p = 6 N·m
    s.capacity = 6.0;
    s.steps = 20;
    const Trace t = run(s);
    const double alpha = (s.mass * s.g * s.length / 2 - s.capacity) / s.inertia_about_anchor();
    const double n = s.steps;
    EXPECT_NEAR(t.position.back(), alpha * s.dt * s.dt * n * (n + 1) / 2, 0.01 * alpha * s.dt * s.dt * n * (n + 1) / 2);
    EXPECT_NEAR(t.force.back(), -s.capacity, 0.01 * s.capacity);
}

TEST(BulletInvariance, TurnedScenesGiveTheSameResults) {
    const btQuaternion turn(btVector3(0.3, -0.7, 0.5).normalized(), 1.1);
    HangingBlock h;
    h.stiffness = 100.0;
    h.capacity = 10.0 / 0.75;
    Cantilever c;  // as RotationalDofWithALeverArm: ω·dt = 0.1 about the anchor
    c.capacity = 10.0 / 0.75;
    c.dt = 0.001;
    c.stiffness = 100.0 * 100.0 * c.inertia_about_anchor();
    c.steps = 300;
    HangingBlock ht = h;
    ht.turn = turn;
    Cantilever ct = c;
    ct.turn = turn;
    const Trace a = run(h), b = run(ht), p = run(c), q = run(ct);
    for (std::size_t i = 0; i < a.position.size(); ++i) {
        EXPECT_NEAR(a.position[i], b.position[i], 1e-9) << "hanging block, step " << i;
        EXPECT_NEAR(a.plastic[i], b.plastic[i], 1e-9) << "hanging block, step " << i;
    }
    for (std::size_t i = 0; i < p.position.size(); ++i) {
        EXPECT_NEAR(p.position[i], q.position[i], 1e-6) << "cantilever, step " << i;
        EXPECT_NEAR(p.plastic[i], q.plastic[i], 1e-6) << "cantilever, step " << i;
    }
    EXPECT_GT(p.plastic.back(), 0.0);
    EXPECT_GT(a.plastic.back(), 0.0);
}

TEST(BulletStiff, HugeStiffnessFallsBackToRigidPlasticWithoutNaN) {
    for (double k : {1e6, 1e9, 1e12}) {
        for (double capacity : {20.0, 4.0}) {
            HangingBlock s;
            s.stiffness = k;
            s.capacity = capacity;
            s.dt = 1.0 / 30;
            s.steps = 60;
            const Trace t = run(s);
            for (double x : t.position) ASSERT_TRUE(std::isfinite(x)) << "k = " << k;
            const double a = std::max(0.0, (s.mass * s.g - capacity) / s.mass);
            const double n = s.steps;
            EXPECT_NEAR(-t.position.back(), a * s.dt * s.dt * n * (n + 1) / 2, 1e-6 + 0.01 * a * n * n * s.dt * s.dt / 2)
                << "k = " << k << ", F = " << capacity;
        }
    }
}

TEST(BulletPaperBlock, TensionBlockMatchesTable35) {
    // 6000 kg, capacity 80 kN (4e-4 m² of 200 MPa steel), g = 10, dt = 1/60, 10 iterations; the
    // paper's joint takes hold in the second step.
    HangingBlock s;
    s.mass = 6000.0;
    s.capacity = 80e3;
    s.dt = 1.0 / 60;
    s.steps = 60;
    s.engage_after_steps = 1;
    const Trace t = run(s);
    // Table 3.5: location −0.0046, −0.0056, −0.0056 m (after the free first step, −0.0028);
    // impulse 1330, 1330, 1330, then 1000 (the weight) at rest.
    EXPECT_NEAR(t.body_y[0] + 0.5, -0.0046, 0.00005);
    EXPECT_NEAR(t.body_y[1] + 0.5, -0.0056, 0.00005);
    EXPECT_NEAR(t.body_y[2] + 0.5, -0.0056, 0.00005);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(t.force[i] * s.dt, 1333.3, 0.5) << "step " << i + 2;
    EXPECT_NEAR(t.force.back() * s.dt, 1000.0, 0.5);
    EXPECT_NEAR(t.plastic.back(), 0.0028, 0.0001);  // small and positive
    EXPECT_LT(t.broken_at, 0.0);
}

TEST(BulletPaperBlock, StiffnessLimitedJointDoesNotMoveAsTable36) {
    HangingBlock s;
    s.mass = 6000.0;
    s.capacity = 80e3;
    s.stiffness = 200e9 * 4e-4 / 3.0;  // EA/L of the steel: ω·dt = 1.1 > 0.25
    s.dt = 1.0 / 60;
    s.steps = 30;
    const Trace t = run(s);
    EXPECT_NEAR(t.force[0] * s.dt, 1000.0, 0.5);
    EXPECT_LT(std::abs(t.position.back()), 1e-9);
}

TEST(BulletEnergy, NoJointCreatesEnergy) {
    // Kinetic + potential + elastic + dissipated stays at its start (0) when only gravity works.
    // Symplectic Euler (Bullet's integrator) does not conserve it exactly but keeps it within an
    // O(ω·dt) band without drift: allow 1 % of the energy the joint handled.
    HangingBlock elastic;
    elastic.stiffness = 100.0;
    elastic.capacity = 10.0 / 0.75;
    elastic.steps = 1000;
    HangingBlock rigid;
    rigid.capacity = 6.0;
    rigid.steps = 100;
    Cantilever rod;
    rod.capacity = 10.0 / 0.75;
    rod.dt = 0.001;
    rod.stiffness = 100.0 * 100.0 * rod.inertia_about_anchor();
    for (const Trace& t : {run(elastic), run(rigid), run(rod)}) {
        const double scale = max_of(t.dissipated) + max_of(t.elastic);
        ASSERT_GT(scale, 0.0);
        EXPECT_LT(max_of(t.energy), 0.01 * scale);
        EXPECT_GT(min_of(t.energy), -0.01 * scale);
    }
}

}  // namespace
}  // namespace plascap::test
