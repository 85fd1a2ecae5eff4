#include "plascap/adapters/ode_plastic_joints.hpp"

#include <algorithm>
#include <vector>

#include "plascap/adapters/prefetch.hpp"
#include "ode_body_velocity.hpp"
#include "ode_world_bodies.hpp"

namespace plascap {

namespace {

// Below this largest correction rate [m/s | rad/s] the pass is skipped: a structure at rest has
// nothing to correct (as plascap's Bullet solver skips its pushes).
constexpr double kNothingToCorrect = 1e-6;

void set_velocity(dBodyID body, const BodyVelocity& v) {
    dBodySetLinearVel(body, v.linear[0], v.linear[1], v.linear[2]);
    dBodySetAngularVel(body, v.angular[0], v.angular[1], v.angular[2]);
}

}  // namespace

OdePlasticJoints::OdePlasticJoints(dWorldID world) : world_(world) {}

OdePlasticJoints::~OdePlasticJoints() = default;
OdePlasticJoints::OdePlasticJoints(OdePlasticJoints&&) noexcept = default;
OdePlasticJoints& OdePlasticJoints::operator=(OdePlasticJoints&&) noexcept = default;

OdePlasticJoint& OdePlasticJoints::add(dBodyID a, dBodyID b, const Pose& frame_in_world,
                                       const PlasticJointSettings& settings, double takes_hold_at) {
    joints_.push_back({std::make_unique<OdePlasticJoint>(world_, a, b, frame_in_world, settings), takes_hold_at});
    if (split_) joints_.back().joint->split_corrections(true);
    if (a) joined_.insert(std::minmax(a, b));
    return *joints_.back().joint;
}

void OdePlasticJoints::step(double dt, Stepper stepper) {
    // Has the joint kPrefetchAhead places after i loaded while i computes, once the joints' state
    // passes kPrefetchFromBytes (prefetch.hpp); in the first loop, only joints it will plan.
    // A joint's plan made as the last step settled it is for a step of the last step's dt. With a dt
    // that changes from step to step every such plan would be made again, so plans are made ahead
    // only once the dt has repeated, and used only while it does.
    if ((stepper == Stepper::QuickSplit) != split_) {
        split_corrections(stepper == Stepper::QuickSplit);
        last_dt_ = std::numeric_limits<double>::quiet_NaN();  // plans made ahead were for the other stepper
    }
    const bool dt_repeats = dt == last_dt_;
    last_dt_ = dt;
    const auto planned = [&](const Entry& e) { return dt_repeats && e.ready; };
    const bool loads_ahead = joints_.size() * OdePlasticJoint::state_bytes() > kPrefetchFromBytes;
    const auto prefetch_ahead_of = [&](std::size_t i, bool unplanned_only) {
        if (!loads_ahead) return;
        const auto wanted = [&](std::size_t j) { return j < joints_.size() && !(unplanned_only && planned(joints_[j])); };
        if (wanted(i + kPrefetchAhead)) joints_[i + kPrefetchAhead].joint->prefetch();
        if (wanted(i + kPrefetchRowsAhead)) joints_[i + kPrefetchRowsAhead].joint->prefetch_rows();
    };
    for (std::size_t i = 0; i < joints_.size(); ++i) {
        prefetch_ahead_of(i, true);
        Entry& e = joints_[i];
        if (planned(e)) continue;  // planned when the last step settled it
        // Due when the step starts within half a step of the time asked for (no drift from summing dt).
        if (!e.joint->engaged() && e.takes_hold_at < time_ + 0.5 * dt) e.joint->engage(time_);
        if (e.joint->engaged()) e.joint->before_step(dt);
    }
    for (Contact& contact : contacts_)
        for (int k = 0; k < 2; ++k) contact.start[k] = body_velocity(contact.body[k]);
    if (stepper == Stepper::Quick) {
        dWorldQuickStep(world_, dt);
        book_contact_work(dt);
    } else if (stepper == Stepper::QuickSplit) {
        split_step(dt);  // books the contacts' work before its correction pass
    } else {
        dWorldStep(world_, dt);
        book_contact_work(dt);
    }
    contacts_.clear();  // their joints go with the caller's contact group
    solved_joints_ = 0;
    for (std::size_t i = 0; i < joints_.size(); ++i) {
        prefetch_ahead_of(i, false);
        Entry& e = joints_[i];
        e.ready = false;
        if (!e.joint->engaged()) continue;
        const OdePlasticJoint::Settled settled =
            dt_repeats ? e.joint->after_step_and_plan(dt) : OdePlasticJoint::Settled{e.joint->after_step(dt), false};
        e.ready = settled.ready;
        solved_joints_ += e.joint->solved() ? 1 : 0;
        if (settled.event == JointEvent::Broke && e.joint->body_a())
            joined_.erase(joined_.find(std::minmax(e.joint->body_a(), e.joint->body_b())));
    }
    time_ += dt;
}

void OdePlasticJoints::split_corrections(bool on) {
    split_ = on;
    for (Entry& e : joints_) e.joint->split_corrections(on);
}

void OdePlasticJoints::split_step(double dt) {
    // Whether the step needs a correction pass is known from the rows planned for it: a structure at
    // rest needs none, and then neither the bodies' loads nor the pass.
    double largest = 0.0;
    for (const Entry& e : joints_)
        if (e.joint->engaged()) largest = std::max(largest, e.joint->largest_correction());
    const bool correcting = largest >= kNothingToCorrect;
    dVector3 gravity;
    dWorldGetGravity(world_, gravity);
    if (correcting) record_loads(gravity);
    dWorldQuickStep(world_, dt);
    book_contact_work(dt);
    if (correcting) correction_pass(dt, gravity);
}

void OdePlasticJoints::record_loads(const dVector3 gravity) {
    // The accumulators hold the caller's loads and the joints' pushes and warm starts (which
    // end_correction_pass takes back out); gravity is ODE's to add.
    if (!bodies_) bodies_ = std::make_unique<OdeWorldBodies>(world_);
    records_.clear();
    for (dBodyID body : bodies_->list()) {
        const dReal* f = dBodyGetForce(body);
        const dReal* t = dBodyGetTorque(body);
        BodyRecord r{body, {{f[0], f[1], f[2]}, {t[0], t[1], t[2]}}, {}};
        if (dBodyGetGravityMode(body)) {
            dMass m;
            dBodyGetMass(body, &m);
            for (int k = 0; k < 3; ++k) r.load.force[k] += m.mass * gravity[k];
        }
        records_.push_back(r);
    }
}

void OdePlasticJoints::correction_pass(double dt, const dVector3 gravity) {
    // From rest, with no gravity or loads: the bodies move by the corrections alone. Every joint of
    // the world takes part: contacts keep the bodies out of one another (and make their own
    // position corrections once more), the caller's joints make theirs once more.
    dWorldSetGravity(world_, 0, 0, 0);
    for (BodyRecord& r : records_) {
        r.velocity = body_velocity(r.body);
        set_velocity(r.body, {});
    }
    for (Entry& e : joints_) e.joint->begin_correction_pass();
    // Half the step's iterations, as plascap's Bullet solver gives its pushes (bullet_plastic_solver.hpp).
    const int iterations = dWorldGetQuickStepNumIterations(world_);
    dWorldSetQuickStepNumIterations(world_, std::max(1, iterations / 2));
    dWorldQuickStep(world_, dt);
    dWorldSetQuickStepNumIterations(world_, iterations);
    // The loads did work over the pass's motion that no velocity carried (as Bullet's pushes: the
    // ledger's `corrections`).
    for (const BodyRecord& r : records_) correction_work_ -= held_load_work(r.load, body_velocity(r.body), dt);
    for (Entry& e : joints_) correction_work_ += e.joint->end_correction_pass(dt);
    dWorldSetGravity(world_, gravity[0], gravity[1], gravity[2]);
    for (const BodyRecord& r : records_) set_velocity(r.body, r.velocity);
}

// Each contact's force and torque on each body (its feedback, constant over the step) times dt is the
// impulse it gave that body: its work from the body's velocities before and after (impulse_work.hpp).
void OdePlasticJoints::book_contact_work(double dt) {
    for (const Contact& contact : contacts_) {
        const dJointFeedback& f = contact.feedback;
        const dReal* force[2] = {f.f1, f.f2};
        const dReal* torque[2] = {f.t1, f.t2};
        for (int k = 0; k < 2; ++k) {
            if (!contact.body[k]) continue;
            const Vec3 impulse{force[k][0] * dt, force[k][1] * dt, force[k][2] * dt};
            const Vec3 angular{torque[k][0] * dt, torque[k][1] * dt, torque[k][2] * dt};
            contact_work_ += impulse_work(impulse, angular, contact.start[k], body_velocity(contact.body[k]));
        }
    }
}

bool OdePlasticJoints::joined(dBodyID a, dBodyID b) const { return joined_.count(std::minmax(a, b)) > 0; }

void OdePlasticJoints::attach_contact(dJointGroupID group, const dContact& contact, dBodyID b1, dBodyID b2) {
    const dJointID joint = dJointCreateContact(world_, group, &contact);
    dJointAttach(joint, b1, b2);
    // ODE puts a lone body first (dJointAttach swaps 0 into the second place), and its feedback with it.
    contacts_.push_back({{b1 ? b1 : b2, b1 ? b2 : nullptr}, {}, {}});
    dJointSetFeedback(joint, &contacts_.back().feedback);  // a deque's elements stay where they are
}

struct OdePlasticJoints::Collision {
    OdePlasticJoints& joints;
    dJointGroupID contacts;
    const dSurfaceParameters& surface;
    std::vector<dContact> buffer;
    const std::function<bool(dBodyID, dBodyID)>& skip;
};

void OdePlasticJoints::near_callback(void* data, dGeomID g1, dGeomID g2) {
    Collision& c = *static_cast<Collision*>(data);
    const dBodyID b1 = dGeomGetBody(g1), b2 = dGeomGetBody(g2);
    if (!b1 && !b2) return;                                // static against static
    if (b1 && b2 && c.joints.joined(b1, b2)) return;     // held by a plastic joint
    if (c.skip && c.skip(b1, b2)) return;
    const int n = dCollide(g1, g2, static_cast<int>(c.buffer.size()), &c.buffer[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
        c.buffer[i].surface = c.surface;
        c.joints.attach_contact(c.contacts, c.buffer[i], b1, b2);
    }
}

void OdePlasticJoints::collide(dSpaceID space, dJointGroupID contacts, const dSurfaceParameters& surface, int max_contacts,
                               const std::function<bool(dBodyID, dBodyID)>& skip) {
    Collision c{*this, contacts, surface, std::vector<dContact>(static_cast<std::size_t>(std::max(1, max_contacts))), skip};
    dSpaceCollide(space, &c, &near_callback);
}

}  // namespace plascap
