// A Scene in Bullet: boxes as btRigidBody, joints as BulletPlasticJoint.
#include <memory>

#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>
#include <vector>

#include "plascap/adapters/bullet_plastic_joint.hpp"
#include "plascap/adapters/bullet_vec3.hpp"
#include "plascap/adapters/bullet_world.hpp"
#include "joint_schedule.hpp"
#include "scene_engine.hpp"

namespace plascap {
namespace {

// The collision group of a structure's segments (a bit Bullet's default groups leave free).
constexpr int kStructureGroup = 64;

template <class Joint>
class BulletScene : public SceneEngine {
public:
    BulletScene(const Scene& scene, const char* constraint)
        : scene_(scene), constraint_(constraint), world_(to_bt(scene.gravity), scene.iterations), schedule_(scene) {
        // One solve for the world: Bullet's per-island solve finds each island's constraints by
        // scanning all of them, O(n²) per step (docs/adapters.md, "Cost"); the islands do not
        // interact, so one solve gives them the same rows.
        world_.world().getSimulationIslandManager()->setSplitIslands(false);
        world_.count_contact_work();  // the ledger's contacts (energy_ledger.hpp)
        for (const SceneBody& b : scene.bodies) {
            const btQuaternion q(b.orientation[1], b.orientation[2], b.orientation[3], b.orientation[0]);
            const btVector3 inertia = b.inertia ? to_bt(*b.inertia) : btVector3(0, 0, 0);
            boxes_.push_back(std::make_unique<BulletBox>(to_bt(b.size) * 0.5, b.is_static ? 0.0 : b.mass,
                                                         btTransform(q, to_bt(b.position)), b.inertia ? &inertia : nullptr));
            btRigidBody& body = boxes_.back()->body();
            body.setLinearVelocity(to_bt(b.velocity));
            body.setAngularVelocity(to_bt(b.angular_velocity));
            if (b.structure) {  // a structure's segments pass through each other, and collide with the rest
                world_.world().addRigidBody(&body, kStructureGroup, btBroadphaseProxy::AllFilter ^ kStructureGroup);
            } else {
                world_.world().addRigidBody(&body);
            }
        }
        for (const SceneJoint& j : scene.joints) {
            btRigidBody* a = j.a ? &boxes_[*j.a]->body() : nullptr;
            joints_.push_back(std::make_unique<Joint>(a, boxes_[j.b]->body(), to_transform(j.frame()), j.settings));
            joints_.back()->count_rows_work();  // for the energy ledger
        }
    }

    ~BulletScene() override {
        joints_.clear();  // each leaves the world as it is destroyed
        for (auto& box : boxes_) world_.world().removeRigidBody(&box->body());
    }

    std::string description() const override {
        return std::string("Bullet ") + std::to_string(btGetVersion() / 100) + "." + std::to_string(btGetVersion() % 100) +
               (sizeof(btScalar) == 8 ? ", double precision, " : ", single precision, ") + constraint_;
    }

    void step() override {
        for (std::size_t i : schedule_.due(time_)) joints_[i]->attach(world_.world(), scene_.dt, time_);
        for (std::size_t i : schedule_.severed(time_)) joints_[i]->sever();
        world_.step(scene_.dt);
        ++steps_;
        time_ = static_cast<double>(steps_) * scene_.dt;
    }

    double time() const override { return time_; }
    double correction_work() const override { return world_.correction_work(); }
    double contact_work() const override { return world_.contact_work(); }

    void apply_load(std::size_t index, const Vec3& force, const Vec3& point, const Vec3& moment) override {
        btRigidBody& b = boxes_[index]->body();
        b.applyForce(to_bt(force), to_bt(point) - b.getCenterOfMassPosition());
        b.applyTorque(to_bt(moment));
    }

    BodyState body(std::size_t index) const override {
        const btRigidBody& b = boxes_[index]->body();
        const btQuaternion q = b.getOrientation();
        return {to_vec3(b.getCenterOfMassPosition()), to_vec3(b.getLinearVelocity()), to_vec3(b.getAngularVelocity()),
                Quaternion{q.w(), q.x(), q.y(), q.z()}};
    }

    const PlasticJointLaw* joint_law(std::size_t index) const override {
        return schedule_.engaged(index) ? &joints_[index]->law() : nullptr;
    }

    PerDof<double> joint_forces(std::size_t index) const override { return joints_[index]->forces(); }
    double joint_rows_work(std::size_t index) const override { return joints_[index]->rows_work(); }
    PerDof<double> joint_positions(std::size_t index) override { return joints_[index]->positions(); }

private:
    const Scene& scene_;
    const char* constraint_;
    BulletWorld world_;
    JointSchedule schedule_;
    std::vector<std::unique_ptr<BulletBox>> boxes_;
    std::vector<std::unique_ptr<Joint>> joints_;
    std::size_t steps_ = 0;
    double time_ = 0.0;
};

}  // namespace

enum class BulletConstraint { Plascap, Spring2, Spring };

std::unique_ptr<SceneEngine> make_bullet_scene(const Scene& scene, BulletConstraint constraint) {
    switch (constraint) {
        case BulletConstraint::Spring:
            return std::make_unique<BulletScene<BulletPlasticJoint6DofSpring>>(scene, "btGeneric6DofSpringConstraint");
        case BulletConstraint::Spring2:
            return std::make_unique<BulletScene<BulletPlasticJointSpring2>>(scene, "btGeneric6DofSpring2Constraint");
        case BulletConstraint::Plascap: break;
    }
    return std::make_unique<BulletScene<BulletPlasticJoint>>(scene, "plascap::BulletPlasticConstraint");
}

}  // namespace plascap
