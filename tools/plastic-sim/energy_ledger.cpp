#include "energy_ledger.hpp"

#include <algorithm>
#include <cmath>

#include "body_energy.hpp"

namespace plascap {

std::vector<AppliedLoad> apply_scene_loads(const Scene& scene, SceneEngine& engine) {
    std::vector<AppliedLoad> applied;
    for (const SceneLoad& load : scene.loads) {
        const double f = load.factor(engine.time());
        AppliedLoad a;
        a.body = load.at.body;
        a.local = load.at.local;
        a.point = world_point(engine.body(a.body), a.local);
        for (int i = 0; i < 3; ++i) a.force[i] = f * load.force[i], a.moment[i] = f * load.moment[i];
        engine.apply_load(a.body, a.force, a.point, a.moment);
        applied.push_back(a);
    }
    return applied;
}

// The rows' work less its booked counterpart: −(elastic + dissipated by the velocity solve).
double unbooked_work(const PlasticJointLaw& law, double elastic, double rows_work) {
    return rows_work + elastic + law.dissipated() - law.dissipated_by_corrections();
}

double unbooked_work(SceneEngine& engine, std::size_t joint) {
    const PlasticJointLaw* law = engine.joint_law(joint);
    return law ? unbooked_work(*law, law->elastic_energy(engine.joint_positions(joint)), engine.joint_rows_work(joint)) : 0.0;
}

EnergyAccount::EnergyAccount(const Scene& scene, const SceneEngine& engine) : scene_(scene) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const BodyState s = engine.body(i);
        start_.push_back(s.position);
        if (!scene.bodies[i].is_static) ledger_.initial += kinetic_energy(scene.bodies[i], s);
    }
    ledger_.kinetic = ledger_.initial;
    ledger_.handled = ledger_.initial;
}

void EnergyAccount::after_step(SceneEngine& engine, const std::vector<AppliedLoad>& loads) {
    EnergyLedger& l = ledger_;
    l.kinetic = l.gravitational = l.elastic = l.dissipated = 0.0;
    double flow_by_corrections = 0.0;
    l.joints_unbooked = 0.0;
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
        if (scene_.bodies[i].is_static) continue;
        const BodyState s = engine.body(i);
        l.kinetic += kinetic_energy(scene_.bodies[i], s);
        l.gravitational -= scene_.bodies[i].mass * dot(scene_.gravity, difference(s.position, start_[i]));
    }
    for (std::size_t j = 0; j < scene_.joints.size(); ++j) {
        if (const PlasticJointLaw* law = engine.joint_law(j)) {
            const double elastic = law->elastic_energy(engine.joint_positions(j));
            l.elastic += elastic;
            l.dissipated += law->dissipated();
            flow_by_corrections += law->dissipated_by_corrections();
            l.joints_unbooked += unbooked_work(*law, elastic, engine.joint_rows_work(j));
        }
    }
    for (const AppliedLoad& a : loads) {
        const BodyState s = engine.body(a.body);
        l.external_work += dot(a.force, difference(world_point(s, a.local), a.point)) +
                           dot(a.moment, s.angular_velocity) * scene_.dt;
    }
    // The pushes' work against the loads and gravity, and the dissipation the joints booked on flow
    // the pushes drove (plastic_joint_law.hpp): neither is the velocity solve's.
    l.corrections = engine.correction_work() + flow_by_corrections;
    l.contacts = engine.contact_work();
    l.handled = std::max({l.handled, std::abs(l.kinetic), std::abs(l.gravitational), std::abs(l.elastic),
                          std::abs(l.dissipated), std::abs(l.external_work)});
}

}  // namespace plascap
