// plascap's ODE joint (adapters/ode/src/ode_plastic_rows.hpp) is an object of ODE 0.16's joint
// class, whose layout plascap declares itself (ode_joint_object.hpp) because ODE installs no header
// for it. These tests check that declaration against the ODE library the build links: if a
// different ODE lays its joints out otherwise, they fail here rather than the engine corrupting
// memory. The rows themselves are checked by the analytic tests of every engine
// (test_plastic_joint_engines.cpp and others).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "../adapters/ode/src/ode_plastic_rows.hpp"
#include "../adapters/ode/src/ode_world_bodies.hpp"
#include "plascap/adapters/ode_plastic_joint.hpp"

namespace plascap {
namespace {

struct OdeWorld {
    OdeWorld() {
        dInitODE();
        world = dWorldCreate();
        a = dBodyCreate(world);
        b = dBodyCreate(world);
    }
    ~OdeWorld() {
        dWorldDestroy(world);
        dCloseODE();
    }
    dWorldID world;
    dBodyID a, b;
};

TEST(OdeJointObject, HasTheSizeOfOdesOwnNullJoint) {
    OdeWorld w;
    // ODE's null joint adds no member to the joint class; size() is read through the virtual
    // function table as plascap declares it, which checks that slot too.
    dJointID null_joint = dJointCreateNull(w.world, nullptr);
    EXPECT_EQ(null_joint->size(), sizeof(dxJoint));
    EXPECT_EQ(null_joint->type(), dJointTypeNull);
    dJointDestroy(null_joint);
}

// ODE lists no world's bodies; OdeWorldBodies walks the world's own list (dObject's next), found
// through a body made and destroyed at once: it must find exactly the bodies made, before and after
// it was set up, and none destroyed.
TEST(OdeWorldBodies, ListsEveryBodyOfTheWorldAndNoOther) {
    OdeWorld w;
    OdeWorldBodies bodies(w.world);
    const dBodyID c = dBodyCreate(w.world);
    const dBodyID d = dBodyCreate(w.world);
    EXPECT_EQ(bodies.list(), (std::vector<dBodyID>{d, c, w.b, w.a}));  // ODE's order: newest first
    dBodyDestroy(c);
    EXPECT_EQ(bodies.list(), (std::vector<dBodyID>{d, w.b, w.a}));
    dBodyDestroy(d);
    dBodyDestroy(w.b);
    dBodyDestroy(w.a);
    EXPECT_TRUE(bodies.list().empty());
}

TEST(OdeJointObject, ReadsWhereOdeKeepsAJointsWorldBodiesAndFeedback) {
    OdeWorld w;
    dJointFeedback feedback{};
    dJointID fixed = dJointCreateFixed(w.world, nullptr);  // made by ODE, read through plascap's layout
    dJointAttach(fixed, w.b, w.a);
    dJointSetFeedback(fixed, &feedback);
    EXPECT_EQ(fixed->world, w.world);
    EXPECT_EQ(fixed->node[0].body, w.b);
    EXPECT_EQ(fixed->node[1].body, w.a);
    EXPECT_EQ(fixed->node[0].joint, fixed);
    EXPECT_EQ(fixed->feedback, &feedback);
    EXPECT_EQ(fixed->type(), dJointTypeFixed);
    dJointDisable(fixed);
    EXPECT_FALSE(fixed->isEnabled());
    dJointDestroy(fixed);
}

TEST(OdeJointObject, PlascapsJointIsOneOfTheWorldsJoints) {
    OdeWorld w;
    OdePlasticRows* rows = OdePlasticRows::create(w.world, w.b, w.a);
    dJointFeedback feedback{};
    dJointSetFeedback(rows, &feedback);
    // ODE's public API sees it as a joint of the world between b and a.
    EXPECT_EQ(dJointGetBody(rows, 0), w.b);
    EXPECT_EQ(dJointGetBody(rows, 1), w.a);
    EXPECT_EQ(dJointGetType(rows), dJointTypeNull);
    EXPECT_TRUE(dAreConnected(w.a, w.b));
    EXPECT_EQ(dBodyGetNumJoints(w.b), 1);
    EXPECT_EQ(dJointGetFeedback(rows), &feedback);
    dJointDestroy(rows);  // ODE frees it with plascap's destructor
    EXPECT_FALSE(dAreConnected(w.a, w.b));
}

// One rigid translation row along x, b joined to the world, pushed along x by a force: the row
// holds b and its feedback carries the force back, as ODE's own joints' do.
TEST(OdeJointObject, ARowHoldsItsBodyAndReportsItsForce) {
    OdeWorld w;
    dMass m;
    dMassSetBoxTotal(&m, 2.0, 1.0, 1.0, 1.0);
    dBodySetMass(w.b, &m);
    dWorldSetGravity(w.world, 0.0, 0.0, 0.0);
    OdePlasticRows* rows = OdePlasticRows::create(w.world, w.b, nullptr);
    dJointFeedback feedback{};
    dJointSetFeedback(rows, &feedback);
    JointFrameState state;
    state.axes.anchor = {0.0, 0.0, 0.0};
    state.axes.translation = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    rows->set_rows(state, [](std::size_t dof) {  // one rigid row, along x
        return dof == 0 ? std::optional<OdeRowTarget>(OdeRowTarget{0.0, -dInfinity, dInfinity}) : std::nullopt;
    });
    dBodyAddForce(w.b, 10.0, 4.0, 0.0);  // [N]
    dWorldStep(w.world, 0.01);
    const dReal* v = dBodyGetLinearVel(w.b);
    EXPECT_NEAR(v[0], 0.0, 1e-9);             // held along x
    EXPECT_NEAR(v[1], 4.0 / 2.0 * 0.01, 1e-9);  // free along y: F·dt/m
    EXPECT_NEAR(feedback.f1[0], -10.0, 1e-6);    // the row's force on b
    EXPECT_NEAR(feedback.f1[1], 0.0, 1e-9);
}

// What the ODE joint's rows now carry: both capacities as the two bounds of a Hold row (as plascap's
// Bullet constraint, tests/test_bullet_plastic_constraint.cpp), where the AMotor and contact rows it
// replaced had one symmetric bound, that of the side last loaded. A 10 kg block without gravity
// hangs from the world at its top; N is rigid-plastic with 1,000 N in tension (the dof's negative
// side: pulling the block down moves b's anchor along −y) and 3,000 N in compression; every other
// dof is rigid. Phases of (force along −y on the block [N], steps of 1/240 s).
double axial_plastic_after_on_ode(const std::vector<std::pair<double, int>>& phases) {
    OdeWorld w;
    dWorldSetGravity(w.world, 0.0, 0.0, 0.0);
    dMass m;
    dMassSetBoxTotal(&m, 10.0, 0.2, 1.0, 0.2);
    dBodySetMass(w.b, &m);
    dBodySetPosition(w.b, 0.0, -0.5, 0.0);
    PlasticJointSettings s;
    s.modes.fill(DofMode::Rigid);
    s.modes[index(Dof::N)] = DofMode::Plastic;
    s.laws[index(Dof::N)] = {3000.0, 1000.0, std::nullopt};
    OdePlasticJoint joint(w.world, nullptr, w.b, Pose{}, s);
    const double dt = 1.0 / 240;
    joint.engage(0.0);
    for (const auto& [force, steps] : phases) {
        for (int i = 0; i < steps; ++i) {
            dBodyAddForce(w.b, 0.0, -force, 0.0);
            joint.before_step(dt);
            dWorldStep(w.world, dt);
            joint.after_step(dt);
        }
    }
    return joint.law().plastic_displacement();
}

TEST(OdePlasticRows, LoadReversalMeetsTheCapacityOfItsOwnSideFromItsFirstStep) {
    // 800 N of tension, then 2,500 N of compression: both below their side's capacity, nothing flows.
    EXPECT_LT(axial_plastic_after_on_ode({{800.0, 120}, {-2500.0, 120}}), 1e-9);
}

TEST(OdePlasticRows, CompressionPastItsCapacityFlowsAtThatCapacity) {
    // 3,300 N against N_neg = 3,000 N after 800 N of tension: the block accelerates at 300 N / 10 kg,
    // so after n steps of h (semi-implicit Euler) it has moved a·h²·n(n+1)/2.
    const int n = 120;
    const double a = (3300.0 - 3000.0) / 10.0, h = 1.0 / 240;
    const double expected = a * h * h * n * (n + 1) / 2;
    EXPECT_NEAR(axial_plastic_after_on_ode({{800.0, 60}, {-3300.0, n}}), expected, 0.01 * expected);
}

// The law plans with each row's effective mass 1/(J·M⁻¹·Jᵀ) (row_effective_mass.hpp), from the
// inverse inertia in the world the ODE joint forms itself (ode_plastic_joint.cpp). Here the body's
// inertia is not diagonal in its own frame (a box's, turned by dMassRotate) and the body is turned
// again in the world, so every entry of I_world⁻¹ counts. The reference inverts I_world = R·I·Rᵀ
// after turning it (Baraff, "Rigid Body Simulation I", eq. 2-37ff), where the joint turns the
// inverse: the same matrix by another route. With k = 1, ω·dt = √(J·M⁻¹·Jᵀ)·dt (paper eq. 3.2).
using M3 = std::array<std::array<double, 3>, 3>;

M3 inverse_by_cofactors(const M3& m) {
    M3 inv{};
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {  // inv[i][j] = cofactor of m[j][i] / det
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            inv[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
        }
    }
    return inv;
}

double quadratic(const M3& m, const std::array<double, 3>& v) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) sum += v[i] * m[i][j] * v[j];
    return sum;
}

TEST(OdePlasticJoint, PlansWithTheEffectiveMassOfATurnedBodyWithATurnedInertia) {
    OdeWorld w;
    dWorldSetGravity(w.world, 0.0, 0.0, 0.0);
    dMass mass;
    dMassSetBoxTotal(&mass, 10.0, 0.2, 1.0, 0.4);
    dMatrix3 turn_mass, turn_body;
    dRFromAxisAndAngle(turn_mass, 1.0, 2.0, 0.5, 0.7);
    dRFromAxisAndAngle(turn_body, -0.3, 1.0, 2.0, 1.9);
    dMassRotate(&mass, turn_mass);
    dBodySetMass(w.b, &mass);
    dBodySetRotation(w.b, turn_body);
    const std::array<double, 3> centre = {0.1, -0.5, 0.2};
    dBodySetPosition(w.b, centre[0], centre[1], centre[2]);
    PlasticJointSettings s;
    for (Dof dof : kAllDofs) {
        s.modes[index(dof)] = DofMode::Plastic;
        s.laws[index(dof)] = {1e6, 1e6, 1.0};  // soft springs: every dof elastic-plastic (ω·dt ≪ 0.25)
    }
    OdePlasticJoint joint(w.world, nullptr, w.b, Pose{}, s);  // at the world's origin, on its axes
    const double dt = 1.0 / 60;
    joint.engage(0.0);
    joint.before_step(dt);

    M3 body_inertia{}, r{}, world_inertia{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) body_inertia[i][j] = mass.I[4 * i + j], r[i][j] = turn_body[4 * i + j];
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l) world_inertia[i][j] += r[i][k] * body_inertia[k][l] * r[j][l];
        }
    }
    const M3 inverse = inverse_by_cofactors(world_inertia);
    const std::array<double, 3> lever = {-centre[0], -centre[1], -centre[2]};  // anchor (origin) − centre
    for (int i = 0; i < 3; ++i) {
        std::array<double, 3> axis{};
        axis[i] = 1.0;
        const std::array<double, 3> moment = {lever[1] * axis[2] - lever[2] * axis[1],
                                              lever[2] * axis[0] - lever[0] * axis[2],
                                              lever[0] * axis[1] - lever[1] * axis[0]};
        const double translation = 1.0 / mass.mass + quadratic(inverse, moment);
        const double rotation = quadratic(inverse, axis);
        EXPECT_NEAR(joint.law().law(kAllDofs[i])->omega_dt(), std::sqrt(translation) * dt, 1e-12 * std::sqrt(translation) * dt) << i;
        EXPECT_NEAR(joint.law().law(kAllDofs[i + 3])->omega_dt(), std::sqrt(rotation) * dt, 1e-12 * std::sqrt(rotation) * dt) << i;
    }
}

}  // namespace
}  // namespace plascap
