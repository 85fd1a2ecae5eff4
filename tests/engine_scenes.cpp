#include "engine_scenes.hpp"

#include <cmath>

namespace plascap::test {
namespace {

using Mat = std::array<Vec3, 3>;  // rows

Mat rotation(const Turn& t) {  // Rodrigues
    const double c = std::cos(t.angle), s = std::sin(t.angle), C = 1 - c;
    const auto& [x, y, z] = t.axis;
    return {{{c + x * x * C, x * y * C - z * s, x * z * C + y * s},
             {y * x * C + z * s, c + y * y * C, y * z * C - x * s},
             {z * x * C - y * s, z * y * C + x * s, c + z * z * C}}};
}

Quaternion quaternion(const Turn& t) {
    const double s = std::sin(t.angle / 2);
    return {std::cos(t.angle / 2), s * t.axis[0], s * t.axis[1], s * t.axis[2]};
}

Vec3 rotate(const Mat& m, const Vec3& v) {
    Vec3 r{};
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    return r;
}

Scene one_body_one_joint(double dt, int steps, int iterations, double g, const Turn& turn, SceneBody body, Mat frame,
                         Dof plastic, const DofLaw& law) {
    const Mat r = rotation(turn);
    Scene s;
    s.dt = dt;
    s.duration = steps * dt;
    s.iterations = iterations;
    const Vec3 up = rotate(r, {0, 1, 0});
    s.gravity = {-g * up[0], -g * up[1], -g * up[2]};
    body.position = rotate(r, body.position);
    body.orientation = quaternion(turn);
    s.bodies = {body};
    SceneJoint j;
    j.name = "joint";
    j.b = 0;
    j.anchor = {0, 0, 0};
    for (std::size_t k = 0; k < 3; ++k) j.axes[k] = rotate(r, {frame[0][k], frame[1][k], frame[2][k]});
    j.settings.modes.fill(DofMode::Rigid);
    j.settings.modes[index(plastic)] = DofMode::Plastic;
    j.settings.laws[index(plastic)] = law;
    s.joints = {j};
    return s;
}

Trace record(const std::string& engine_name, const Scene& scene, Dof dof, const Turn& turn, double g) {
    const std::unique_ptr<SceneEngine> engine = make_engine(engine_name, scene);
    const Vec3 up = rotate(rotation(turn), {0, 1, 0});
    const double y0 = dot(scene.bodies[0].position, up);
    Trace t;
    for (std::size_t i = 0; i < scene.steps(); ++i) {
        engine->step();
        const BodyState s = engine->body(0);
        const PlasticJointLaw* joint = engine->joint_law(0);
        const PerDof<double> x = joint ? engine->joint_positions(0) : PerDof<double>{};
        const ElasticPlasticLaw* law = joint ? joint->law(dof) : nullptr;
        const double y = dot(s.position, up);
        t.time.push_back(engine->time());
        t.position.push_back(x[index(dof)]);
        t.force.push_back(joint ? engine->joint_forces(0)[index(dof)] : 0.0);
        t.plastic.push_back(law ? law->accumulated_plastic() : 0.0);
        t.dissipated.push_back(law ? law->dissipated() : 0.0);
        t.elastic.push_back(joint ? joint->elastic_energy(x) : 0.0);
        t.body_y.push_back(y);
        t.energy.push_back(kinetic_energy(scene.bodies[0], s) + scene.bodies[0].mass * g * (y - y0) + t.elastic.back() +
                           t.dissipated.back());
        if (joint && joint->broken() && t.broken_at < 0) t.broken_at = *joint->broken_at();
    }
    return t;
}

}  // namespace

Trace run(const std::string& engine_name, const TwoBodies& t) {
    Scene s;
    s.dt = t.dt;
    s.duration = t.steps * t.dt;
    s.iterations = t.iterations;
    s.gravity = {0, 0, 0};
    SceneBody a, b;
    a.name = "a", b.name = "b";
    a.size = b.size = {0.2, 0.2, 0.2};
    a.mass = t.mass_a, b.mass = t.mass_b;
    a.position = {0, -0.5, 0}, b.position = {0, 0.5, 0};
    // Centre of mass at rest: a moves −m_b/(m_a + m_b)·u0, b +m_a/(m_a + m_b)·u0.
    a.velocity = {0, -t.u0 * t.mass_b / (t.mass_a + t.mass_b), 0};
    b.velocity = {0, t.u0 * t.mass_a / (t.mass_a + t.mass_b), 0};
    s.bodies = {a, b};
    SceneJoint j;
    j.name = "joint";
    j.a = 0;
    j.b = 1;
    j.anchor = {0, 0, 0};
    j.axes = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    j.settings.modes.fill(DofMode::Rigid);
    j.settings.modes[index(Dof::N)] = DofMode::Plastic;
    j.settings.laws[index(Dof::N)] = DofLaw{t.capacity_tension, t.capacity_compression, t.stiffness};
    s.joints = {j};
    const std::unique_ptr<SceneEngine> engine = make_engine(engine_name, s);
    Trace trace;
    for (std::size_t i = 0; i < s.steps(); ++i) {
        engine->step();
        const PlasticJointLaw* joint = engine->joint_law(0);
        const PerDof<double> x = engine->joint_positions(0);
        const ElasticPlasticLaw* law = joint->law(Dof::N);
        trace.time.push_back(engine->time());
        trace.position.push_back(x[index(Dof::N)]);
        trace.force.push_back(engine->joint_forces(0)[index(Dof::N)]);
        trace.plastic.push_back(law->accumulated_plastic());
        trace.dissipated.push_back(law->dissipated());
        trace.elastic.push_back(joint->elastic_energy(x));
        trace.energy.push_back(kinetic_energy(s.bodies[0], engine->body(0)) + kinetic_energy(s.bodies[1], engine->body(1)) +
                               trace.elastic.back() + trace.dissipated.back());
        trace.body_y.push_back(engine->body(1).position[1]);
    }
    return trace;
}

Trace run(const std::string& engine, const HangingBlock& h) {
    SceneBody block;
    block.name = "block";
    block.size = {0.2, 0.2, 0.2};
    block.mass = h.mass;
    block.position = {0, -0.5, 0};
    Scene s = one_body_one_joint(h.dt, h.steps, h.iterations, h.g, h.turn, block, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                                 Dof::N, DofLaw{h.capacity, h.capacity, h.stiffness});
    s.joints[0].settings.max_plastic_displacement = h.max_plastic_displacement;
    s.joints[0].engage_at = h.engage_after_steps * h.dt;  // the paper's joint acts from step 2
    return record(engine, s, Dof::N, h.turn, h.g);
}

Trace run(const std::string& engine, const Cantilever& c) {
    // The rod lies along world x from the anchor; the joint's beam axis y is the rod's axis and its
    // x axis is world up, so z = x × y = −world z and gravity bends the rod about +z: the Mz dof.
    SceneBody rod;
    rod.name = "rod";
    rod.size = {c.length, c.thickness, c.thickness};
    rod.mass = c.mass;
    rod.position = {c.length / 2, 0, 0};
    const Scene s = one_body_one_joint(c.dt, c.steps, c.iterations, c.g, c.turn, rod,
                                       {{{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}},  // columns x, y, z
                                       Dof::Mz, DofLaw{c.capacity, c.capacity, c.stiffness});
    return record(engine, s, Dof::Mz, c.turn, c.g);
}

}  // namespace plascap::test
