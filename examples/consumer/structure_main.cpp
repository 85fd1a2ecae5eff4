// A structure from members and nodes on Bullet, through an installed plascap: the cantilever of
// cantilever_structure.hpp (plascap::structures) carries a tip load P at C. At 0.9 P_c = 0.9 M_p/L
// the support holds (no plastic rotation), at 1.1 P_c it turns into a hinge.
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_vec3.hpp"
#include "plascap/adapters/bullet_world.hpp"
#include "plascap/adapters/structure_model.hpp"

#include "cantilever_structure.hpp"

namespace {

// The support's plastic rotation [rad] after a tip load of `load` [N], ramped over 1 s and held 1 s.
double support_rotation(const plascap::StructureModel& model, const plascap::Vec3& load) {
    const double dt = 0.002;
    plascap::BulletWorld world(btVector3(0, 0, 0), 50);
    std::vector<std::unique_ptr<plascap::BulletBox>> bodies;
    for (const plascap::StructureSegment& s : model.segments) {
        const btQuaternion q(s.orientation[1], s.orientation[2], s.orientation[3], s.orientation[0]);
        const btVector3 inertia = plascap::to_bt(s.inertia);
        bodies.push_back(std::make_unique<plascap::BulletBox>(plascap::to_bt(s.size) * 0.5, s.mass, btTransform(q, plascap::to_bt(s.position)), &inertia));
        world.world().addRigidBody(&bodies.back()->body());
    }
    std::vector<std::unique_ptr<plascap::BulletPlasticJoint>> joints;
    for (const plascap::StructureJoint& j : model.joints) {
        btRigidBody* a = j.a ? &bodies[*j.a]->body() : nullptr;  // none: the world
        joints.push_back(std::make_unique<plascap::BulletPlasticJoint>(a, bodies[j.b]->body(), plascap::to_transform(j.frame()), j.settings));
        joints.back()->attach(world.world(), dt);
    }
    const plascap::BodyPoint tip = model.nodes.back().at;  // node C, carried by the last segment
    btRigidBody& end = bodies[tip.body]->body();
    for (int i = 0; i < 1000; ++i) {
        const double ramp = std::fmin(1.0, i * dt);
        end.applyForce(plascap::to_bt(load) * ramp, end.getWorldTransform().getBasis() * plascap::to_bt(tip.local));
        world.step(dt);
    }
    const double rotation = joints.back()->law().plastic_rotation();  // the support, the last joint
    joints.clear();  // each leaves the world as it is destroyed
    for (auto& b : bodies) world.world().removeRigidBody(&b->body());
    return rotation;
}

}  // namespace

int main() {
    const double L = kCantileverLength, Mp = kCantileverMp;
    const plascap::StructureModel model = cantilever_model();

    const double holds = support_rotation(model, {0, -0.9 * Mp / L, 0}), folds = support_rotation(model, {0, -1.1 * Mp / L, 0});
    std::printf("%zu segments, %zu joints; support's plastic rotation at 0.9 Mp/L: %.5f rad, at 1.1 Mp/L: %.3f rad\n",
                model.segments.size(), model.joints.size(), holds, folds);
    return model.joints.size() == 4 && holds < 1e-3 && folds > 0.05 ? 0 : 1;
}
