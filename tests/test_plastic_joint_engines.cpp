// Every engine adapter against the analytic references (issues 6 and 7, "Prove it" 1–8): the
// single-degree-of-freedom elastic–perfectly-plastic oscillator and the rigid-plastic block of
// docs/references.md, the paper's tension block (§3, Tables 3.5 and 3.6). Each test runs
// on Bullet (btGeneric6DofSpring2Constraint and btGeneric6DofSpringConstraint) and on ODE
// (dWorldQuickStep and dWorldStep), through the same scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine_scenes.hpp"
#include "engine_test_names.hpp"

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

// A held dof stays within a micrometre: Bullet holds it to round-off, ODE's rows are softened by its
// global CFM (1e-10 m/N per step in double precision: 0.6 µm under the 6000 kg block).
constexpr double kHeld = 1e-6;  // [m]

// Symplectic Euler from rest under constant acceleration a: x_n = a·h²·n(n+1)/2.
double flowed(double a, double h, double n) { return a * h * h * n * (n + 1) / 2; }

class Engine : public ::testing::TestWithParam<std::string> {};

TEST_P(Engine, RigidPlasticBelowCapacityHoldsAndCarriesTheWeight) {
    HangingBlock s;  // W = 10 N, F = 20 N
    const Trace t = run(GetParam(), s);
    EXPECT_LT(std::abs(t.position.back()), kHeld);
    EXPECT_NEAR(t.force.back(), s.mass * s.g, 1e-6 * s.mass * s.g);
    EXPECT_LT(max_of(t.plastic), 1e-9);
}

TEST_P(Engine, RigidPlasticAboveCapacityAcceleratesDissipatesAndBreaks) {
    HangingBlock s;
    s.mass = 3.0;
    s.capacity = 18.0;  // W = 30 N: a = (W − F)/m = 4 m/s²
    s.max_plastic_displacement = 0.5;
    s.steps = 200;
    const Trace t = run(GetParam(), s);
    const double a = (s.mass * s.g - s.capacity) / s.mass;
    const int n = 30;
    EXPECT_NEAR(-t.position[n - 1], flowed(a, s.dt, n), 0.01 * flowed(a, s.dt, n));  // acceleration within 1 %
    EXPECT_NEAR(t.force[n - 1], s.capacity, 1e-6 * s.capacity);
    EXPECT_NEAR(t.dissipated[n - 1], s.capacity * t.plastic[n - 1], 1e-6 * t.dissipated[n - 1]);  // F × plastic
    // 0.5 m has flowed first at n = 50 (t = 0.50 s); then it falls freely and stays broken.
    ASSERT_GT(t.broken_at, 0.0);
    EXPECT_NEAR(t.broken_at, 0.50, 1e-6);  // a float build of Bullet sums its float step
    const std::size_t last = t.body_y.size() - 1;
    const double accel = (t.body_y[last] - 2 * t.body_y[last - 1] + t.body_y[last - 2]) / (s.dt * s.dt);
    EXPECT_NEAR(accel, -s.g, 1e-3 * s.g);  // a second difference of positions: float builds round at 5e-4
}

TEST_P(Engine, ElasticOscillatorPeaksAtTwiceTheStaticDeflection) {
    HangingBlock s;  // m = 1, k = 100: ω = 10, ω·dt = 0.1
    s.stiffness = 100.0;
    s.capacity = 25.0;  // W = 10 ≤ F/2: stays elastic
    s.steps = 400;
    const Trace t = run(GetParam(), s);
    const double statical = s.mass * s.g / *s.stiffness;  // W/k
    EXPECT_NEAR(-min_of(t.position), 2 * statical, 0.02 * 2 * statical);
    double mean = 0;
    const int whole_periods = static_cast<int>(std::lround(6 * 2 * M_PI / 10 / s.dt));
    for (int i = 0; i < whole_periods; ++i) mean += t.position[i];
    EXPECT_NEAR(-mean / whole_periods, statical, 0.02 * statical);
    EXPECT_EQ(max_of(t.plastic), 0.0);
}

TEST_P(Engine, SuddenLoadPeakAndResidualWithin2PercentUpToOmegaDt01) {
    for (double omega_dt : {0.01, 0.03, 0.1}) {
        HangingBlock s;
        s.stiffness = 100.0;
        s.dt = omega_dt / 10.0;
        s.capacity = 10.0 / 0.75;  // W = 0.75 F
        s.steps = static_cast<int>(4.0 / s.dt);
        const Trace t = run(GetParam(), s);
        const Oscillator o{s.mass * s.g, s.capacity, *s.stiffness};
        EXPECT_NEAR(-min_of(t.position), o.peak(), 0.02 * o.peak()) << "ω·dt = " << omega_dt;
        EXPECT_NEAR(t.plastic.back(), o.residual(), 0.02 * o.residual()) << "ω·dt = " << omega_dt;
        EXPECT_NEAR(t.dissipated.back(), o.F * o.residual(), 0.02 * o.F * o.residual()) << "ω·dt = " << omega_dt;
    }
}

TEST_P(Engine, UnloadsWithSlopeK) {
    HangingBlock s;
    s.stiffness = 100.0;
    s.dt = 0.005;
    s.capacity = 10.0 / 0.75;
    s.steps = 800;
    const Trace t = run(GetParam(), s);
    // After the peak: Δf/Δx = −k; a step's force comes from the position at its start.
    const std::size_t peak = std::min_element(t.position.begin(), t.position.end()) - t.position.begin();
    const std::size_t i = peak + 10, j = peak + 25;
    const double slope = (t.force[j] - t.force[i]) / (t.position[j - 1] - t.position[i - 1]);
    EXPECT_NEAR(slope, -*s.stiffness, 0.03 * *s.stiffness);
}

TEST_P(Engine, RotationalDofWithALeverArm) {
    Cantilever s;  // the weight's moment about the anchor: m·g·L/2 = 10 N·m
    const double moment = s.mass * s.g * s.length / 2;
    s.capacity = moment / 0.75;
    s.dt = 0.001;
    s.stiffness = 100.0 * 100.0 * s.inertia_about_anchor();  // ω·dt = 0.1 about the anchor
    s.steps = 300;
    const Trace t = run(GetParam(), s);
    const Oscillator o{moment, s.capacity, *s.stiffness};
    EXPECT_NEAR(max_of(t.position), o.peak(), 0.02 * o.peak());
    EXPECT_NEAR(t.plastic.back(), o.residual(), 0.02 * o.residual());
}

TEST_P(Engine, RotationalDofFlowsAtItsCapacity) {
    Cantilever s;  // rigid-plastic: M = 10 N·m against M_p = 6 N·m
    s.capacity = 6.0;
    s.steps = 20;
    const Trace t = run(GetParam(), s);
    const double alpha = (s.mass * s.g * s.length / 2 - s.capacity) / s.inertia_about_anchor();
    EXPECT_NEAR(t.position.back(), flowed(alpha, s.dt, s.steps), 0.01 * flowed(alpha, s.dt, s.steps));
    EXPECT_NEAR(t.force.back(), -s.capacity, 0.01 * s.capacity);
}

TEST_P(Engine, TurnedScenesGiveTheSameResults) {
    const Turn turn{{0.3 / 0.9110434, -0.7 / 0.9110434, 0.5 / 0.9110434}, 1.1};
    HangingBlock h;
    h.stiffness = 100.0;
    h.capacity = 10.0 / 0.75;
    Cantilever c;
    c.capacity = 10.0 / 0.75;
    c.dt = 0.001;
    c.stiffness = 100.0 * 100.0 * c.inertia_about_anchor();
    HangingBlock ht = h;
    ht.turn = turn;
    Cantilever ct = c;
    ct.turn = turn;
    const Trace a = run(GetParam(), h), b = run(GetParam(), ht), p = run(GetParam(), c), q = run(GetParam(), ct);
    for (std::size_t i = 0; i < a.position.size(); ++i) {
        ASSERT_NEAR(a.position[i], b.position[i], 1e-6) << "hanging block, step " << i;
        ASSERT_NEAR(a.plastic[i], b.plastic[i], 1e-6) << "hanging block, step " << i;
    }
    for (std::size_t i = 0; i < p.position.size(); ++i) {
        ASSERT_NEAR(p.position[i], q.position[i], 1e-6) << "cantilever, step " << i;
        ASSERT_NEAR(p.plastic[i], q.plastic[i], 1e-6) << "cantilever, step " << i;
    }
    EXPECT_GT(p.plastic.back(), 0.0);
    EXPECT_GT(a.plastic.back(), 0.0);
}

TEST_P(Engine, HugeStiffnessFallsBackToRigidPlasticWithoutNaN) {
    for (double k : {1e6, 1e9, 1e12}) {
        for (double capacity : {20.0, 4.0}) {
            HangingBlock s;
            s.stiffness = k;
            s.capacity = capacity;
            s.dt = 1.0 / 30;
            s.steps = 60;
            const Trace t = run(GetParam(), s);
            for (double x : t.position) ASSERT_TRUE(std::isfinite(x)) << "k = " << k;
            const double a = std::max(0.0, (s.mass * s.g - capacity) / s.mass);
            EXPECT_NEAR(-t.position.back(), flowed(a, s.dt, s.steps), 1e-6 + 0.01 * flowed(a, s.dt, s.steps))
                << "k = " << k << ", F = " << capacity;
        }
    }
}

TEST_P(Engine, PaperTensionBlockMatchesTable35) {
    // 6000 kg, capacity 80 kN (4e-4 m² of 200 MPa steel), g = 10, dt = 1/60, 10 iterations; the
    // paper's joint takes hold in the second step.
    HangingBlock s;
    s.mass = 6000.0;
    s.capacity = 80e3;
    s.dt = 1.0 / 60;
    s.steps = 60;
    s.engage_after_steps = 1;
    const Trace t = run(GetParam(), s);
    // Table 3.5: location −0.0028 (free), −0.0046, −0.0056, −0.0056 m; impulse 1330, 1330, 1330,
    // then 1000 (the weight) at rest.
    EXPECT_NEAR(t.body_y[0] + 0.5, -0.0028, 0.00005);
    EXPECT_NEAR(t.body_y[1] + 0.5, -0.0046, 0.00005);
    EXPECT_NEAR(t.body_y[2] + 0.5, -0.0056, 0.00005);
    EXPECT_NEAR(t.body_y[3] + 0.5, -0.0056, 0.00005);
    for (int i = 1; i < 4; ++i) EXPECT_NEAR(t.force[i] * s.dt, 1333.3, 0.5) << "step " << i + 1;
    EXPECT_NEAR(t.force.back() * s.dt, 1000.0, 0.5);
    EXPECT_NEAR(t.plastic.back(), 0.0028, 0.0001);  // small and positive
    EXPECT_NEAR(t.body_y.back() + 0.5, -0.0056, 0.00005);  // at rest where it stopped
    EXPECT_LT(t.broken_at, 0.0);
}

TEST_P(Engine, StiffnessLimitedJointDoesNotMoveAsTable36) {
    HangingBlock s;
    s.mass = 6000.0;
    s.capacity = 80e3;
    s.stiffness = 200e9 * 4e-4 / 3.0;  // EA/L of the steel: ω·dt = 1.1 > 0.25
    s.dt = 1.0 / 60;
    s.steps = 30;
    const Trace t = run(GetParam(), s);
    EXPECT_NEAR(t.force[0] * s.dt, 1000.0, 0.5);
    EXPECT_LT(std::abs(t.position.back()), kHeld);
}

TEST_P(Engine, NoJointCreatesEnergy) {
    // Kinetic + potential + elastic + dissipated stays at its start (0) when only gravity works.
    // Symplectic Euler (both engines' integrator) keeps it within an O(ω·dt) band without drift:
    // allow 1 % of the energy the joint handled.
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
    for (const Trace& t : {run(GetParam(), elastic), run(GetParam(), rigid), run(GetParam(), rod)}) {
        const double scale = max_of(t.dissipated) + max_of(t.elastic);
        ASSERT_GT(scale, 0.0);
        EXPECT_LT(max_of(t.energy), 0.01 * scale);
        EXPECT_GT(min_of(t.energy), -0.01 * scale);
    }
}

// Two moving bodies, F⁺ = 20 N ≠ F⁻ = 10 N, elastic-plastic (k = 100 N/m, μ = 1 kg: ω·dt = 0.01),
// flying apart at u0 = 4 m/s. By energy: the tension side yields at F⁺ and flows
// δ⁺ = (½μu0² − F⁺²/(2k))/F⁺ = 0.3 m; the rebound reaches F⁺ > F⁻ in compression, so the
// reversal yields at F⁻ and flows δ⁻ = (F⁺² − F⁻²)/(2k·F⁻) = 0.15 m; afterwards it rings
// elastically at amplitude F⁻/k. Dissipated F⁺δ⁺ + F⁻δ⁻ = 7.5 J of the 8 J.
TEST_P(Engine, TwoMovingBodiesYieldOnEachSidesCapacityThroughAReversal) {
    TwoBodies t;
    t.stiffness = 100.0;
    const Trace trace = run(GetParam(), t);
    const double k = *t.stiffness, Fp = t.capacity_tension, Fn = t.capacity_compression;
    const double delta_plus = (0.5 * t.reduced_mass() * t.u0 * t.u0 - Fp * Fp / (2 * k)) / Fp;
    const double delta_minus = (Fp * Fp - Fn * Fn) / (2 * k * Fn);
    std::printf("%s: plastic %.5f m (exact %.5f), dissipated %.4f J (exact %.4f)\n", GetParam().c_str(),
                trace.plastic.back(), delta_plus + delta_minus, trace.dissipated.back(), Fp * delta_plus + Fn * delta_minus);
    EXPECT_NEAR(trace.plastic.back(), delta_plus + delta_minus, 0.01 * (delta_plus + delta_minus));
    EXPECT_NEAR(trace.dissipated.back(), Fp * delta_plus + Fn * delta_minus, 0.01 * (Fp * delta_plus + Fn * delta_minus));
    // The largest tension the row applied is F⁺ and the largest compression F⁻ (forces on b).
    EXPECT_NEAR(-min_of(trace.force), Fp, 1e-6 * Fp);
    EXPECT_NEAR(max_of(trace.force), Fn, 1e-6 * Fn);
    // The peak elongation: the plastic offset δ⁺ plus the elastic F⁺/k.
    EXPECT_NEAR(max_of(trace.position), delta_plus + Fp / k, 0.01 * (delta_plus + Fp / k));
    // Energy: kinetic + elastic + dissipated stays within 1 % of the 8 J handled.
    const double handled = 0.5 * t.reduced_mass() * t.u0 * t.u0;
    for (double e : trace.energy) EXPECT_NEAR(e, handled, 0.01 * handled);
}

// Rigid-plastic, the bodies closing at 4 m/s: the row holds at F⁻ = 10 N (the smaller capacity,
// which a fresh row takes, so the first step is right too) until the relative motion stops after
// δ = μu0²/(2F⁻) = 0.8 m, absorbing all ½μu0² = 8 J; then the joint holds.
TEST_P(Engine, TwoMovingBodiesRigidPlasticStopAtTheCompressionCapacity) {
    TwoBodies t;
    t.u0 = -4.0;
    t.dt = 5e-4;
    const Trace trace = run(GetParam(), t);
    const double delta = t.reduced_mass() * t.u0 * t.u0 / (2 * t.capacity_compression);
    std::printf("%s: flowed %.5f m (exact %.5f), dissipated %.4f J (exact 8)\n", GetParam().c_str(), -trace.position.back(),
                delta, trace.dissipated.back());
    EXPECT_NEAR(-trace.position.back(), delta, 0.01 * delta);
    EXPECT_NEAR(trace.plastic.back(), delta, 0.01 * delta);
    EXPECT_NEAR(trace.dissipated.back(), 8.0, 0.01 * 8.0);
    EXPECT_NEAR(max_of(trace.force), t.capacity_compression, 1e-6 * t.capacity_compression);
    // At rest relative to each other by the end: the last 100 steps move less than a micrometre.
    EXPECT_LT(std::abs(trace.position.back() - trace.position[trace.position.size() - 100]), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(PlasticJoints, Engine, ::testing::ValuesIn(available_engines()), engine_test_name);

}  // namespace
}  // namespace plascap::test
