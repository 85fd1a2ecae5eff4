// A Scene in ODE: boxes as dBody + dGeom (static boxes: a geom without a body), joints as
// OdePlasticJoints, collisions through a hash space (OdePlasticJoints::collide: joined bodies skip)
// with contacts of friction 0.25 and no bounce (Bullet's default: 0.5 per body, multiplied).
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "exact_step_cost.hpp"
#include "joint_schedule.hpp"
#include "plascap/adapters/ode_plastic_joints.hpp"
#include "scene_engine.hpp"

namespace plascap {
namespace {

constexpr double kFriction = 0.25;
constexpr int kMaxContacts = 8;

// ODE reports through process-wide handlers. Errors and failed internal assertions would abort():
// they become exceptions (plastic-sim exits 1 with the message). Messages (e.g. the Dantzig LCP's
// "internal error, s <= 0", after which ODE carries on with a degraded step) are counted and shown.
struct OdeMessages {
    std::size_t count = 0;
    std::string first;
};
OdeMessages& ode_messages() {
    static OdeMessages messages;
    return messages;
}

std::string format(int number, const char* text, va_list ap) {
    char buffer[512];
    std::vsnprintf(buffer, sizeof buffer, text, ap);
    return "ODE " + std::to_string(number) + ": " + buffer;
}

void throw_error(int number, const char* text, va_list ap) { throw std::runtime_error(format(number, text, ap)); }

void count_message(int number, const char* text, va_list ap) {
    OdeMessages& m = ode_messages();
    if (m.count++ == 0) m.first = format(number, text, ap);
}

struct OdeLibrary {
    OdeLibrary() {
        dInitODE2(0);
        dSetErrorHandler(&throw_error);
        dSetDebugHandler(&throw_error);
        dSetMessageHandler(&count_message);
    }
};

class OdeScene : public SceneEngine {
public:
    OdeScene(const Scene& scene, bool quick)
        : scene_(scene), quick_(quick), schedule_(scene), world_(new_world()), joints_(world_) {
        dWorldSetGravity(world_, scene.gravity[0], scene.gravity[1], scene.gravity[2]);
        dWorldSetQuickStepNumIterations(world_, scene.iterations);
        space_ = dHashSpaceCreate(nullptr);
        contacts_ = dJointGroupCreate(0);
        for (const SceneBody& b : scene.bodies) add_body(b);
        for (const SceneJoint& j : scene.joints) {
            const dBodyID a = j.a ? bodies_[*j.a] : nullptr;  // a static body holds like the world
            joints_.add(a, bodies_[j.b], j.frame(), j.settings, j.engage_at).count_rows_work();  // for the energy ledger
        }
        if (!quick) slow_steps_ = exact_step_warning(scene);
    }

    ~OdeScene() override {
        joints_ = OdePlasticJoints(world_);  // the joints go before their world
        dJointGroupDestroy(contacts_);
        dSpaceDestroy(space_);  // destroys the geoms
        dWorldDestroy(world_);  // and the bodies
    }

    std::string description() const override {
        const bool double_precision = dCheckConfiguration("ODE_double_precision") != 0;
        return std::string("ODE, ") + (double_precision ? "double" : "single") + " precision, " +
               (quick_ ? "dWorldQuickStep, split corrections" : "dWorldStep");
    }

    void step() override {
        for (std::size_t i : schedule_.severed(time_)) joints_[i].sever();
        joints_.collide(space_, contacts_, surface_, kMaxContacts, skip_segments_);
        joints_.step(scene_.dt, quick_ ? OdePlasticJoints::Stepper::QuickSplit : OdePlasticJoints::Stepper::Exact);
        dJointGroupEmpty(contacts_);
        ++steps_;
        time_ = static_cast<double>(steps_) * scene_.dt;
    }

    double time() const override { return time_; }
    double contact_work() const override { return joints_.contact_work(); }
    double correction_work() const override { return joints_.correction_work(); }

    void apply_load(std::size_t index, const Vec3& force, const Vec3& point, const Vec3& moment) override {
        if (!bodies_[index]) return;  // a static body takes no load
        dBodyAddForceAtPos(bodies_[index], force[0], force[1], force[2], point[0], point[1], point[2]);
        dBodyAddTorque(bodies_[index], moment[0], moment[1], moment[2]);
    }

    BodyState body(std::size_t index) const override {
        BodyState s;
        if (!bodies_[index]) {
            s.position = scene_.bodies[index].position;
            s.orientation = scene_.bodies[index].orientation;
            return s;
        }
        const dReal* p = dBodyGetPosition(bodies_[index]);
        const dReal* v = dBodyGetLinearVel(bodies_[index]);
        const dReal* w = dBodyGetAngularVel(bodies_[index]);
        s.position = {p[0], p[1], p[2]};
        s.velocity = {v[0], v[1], v[2]};
        s.angular_velocity = {w[0], w[1], w[2]};
        const dReal* q = dBodyGetQuaternion(bodies_[index]);
        s.orientation = {q[0], q[1], q[2], q[3]};
        return s;
    }

    const PlasticJointLaw* joint_law(std::size_t index) const override {
        return joints_[index].engaged() ? &joints_[index].law() : nullptr;
    }

    PerDof<double> joint_forces(std::size_t index) const override { return joints_[index].forces(); }
    double joint_rows_work(std::size_t index) const override { return joints_[index].rows_work(); }
    PerDof<double> joint_positions(std::size_t index) override { return joints_[index].positions(); }

    std::vector<std::string> warnings() const override {
        std::vector<std::string> w;
        if (slow_steps_) w.push_back(*slow_steps_);
        const OdeMessages& m = ode_messages();
        if (m.count != 0)
            w.push_back(std::to_string(m.count) + " message(s) from ODE, the first: \"" + m.first + "\"; the steps concerned are unreliable");
        return w;
    }

private:
    static dWorldID new_world() {
        static OdeLibrary library;  // dInitODE2 once per process
        ode_messages() = {};
        dRandSetSeed(0);  // QuickStep reorders rows at random: the same scene gives the same run
        return dWorldCreate();
    }

    void add_body(const SceneBody& b) {
        dGeomID geom = dCreateBox(space_, b.size[0], b.size[1], b.size[2]);
        const dQuaternion q = {b.orientation[0], b.orientation[1], b.orientation[2], b.orientation[3]};
        if (b.is_static) {
            dGeomSetPosition(geom, b.position[0], b.position[1], b.position[2]);
            dGeomSetQuaternion(geom, q);
            bodies_.push_back(nullptr);
            return;
        }
        dBodyID body = dBodyCreate(world_);
        dMass mass;
        if (b.inertia) {
            dMassSetParameters(&mass, b.mass, 0, 0, 0, (*b.inertia)[0], (*b.inertia)[1], (*b.inertia)[2], 0, 0, 0);
        } else {
            dMassSetBoxTotal(&mass, b.mass, b.size[0], b.size[1], b.size[2]);
        }
        dBodySetMass(body, &mass);
        dGeomSetBody(geom, body);
        dBodySetPosition(body, b.position[0], b.position[1], b.position[2]);
        dBodySetQuaternion(body, q);
        dBodySetLinearVel(body, b.velocity[0], b.velocity[1], b.velocity[2]);
        dBodySetAngularVel(body, b.angular_velocity[0], b.angular_velocity[1], b.angular_velocity[2]);
        bodies_.push_back(body);
        if (b.structure) structure_.insert(body);
    }

    static dSurfaceParameters contact_surface() {
        dSurfaceParameters surface{};
        surface.mode = dContactApprox1;
        surface.mu = kFriction;
        return surface;
    }

    const Scene& scene_;
    bool quick_;
    std::optional<std::string> slow_steps_;  // dWorldStep on a large island (exact_step_cost.hpp)
    JointSchedule schedule_;  // for severing; OdePlasticJoints engages
    dWorldID world_;
    OdePlasticJoints joints_;
    dSpaceID space_ = nullptr;
    dJointGroupID contacts_ = nullptr;
    std::vector<dBodyID> bodies_;  // nullptr for static bodies
    std::set<dBodyID> structure_;
    const dSurfaceParameters surface_ = contact_surface();
    // A structure's segments do not collide with each other (joined bodies never do).
    const std::function<bool(dBodyID, dBodyID)> skip_segments_ = [this](dBodyID a, dBodyID b) {
        return structure_.count(a) > 0 && structure_.count(b) > 0;
    };
    std::size_t steps_ = 0;
    double time_ = 0.0;
};

}  // namespace

std::unique_ptr<SceneEngine> make_ode_scene(const Scene& scene, bool quick) { return std::make_unique<OdeScene>(scene, quick); }

}  // namespace plascap
