#pragma once
// Every plastic joint of one ODE world, stepped with it in one call, so a user cannot forget a step
// of the cycle: step(dt) engages the joints whose time has come, plans every joint's rows, steps the
// world (dWorldQuickStep or dWorldStep), and settles every joint. It owns its joints. Each joint is
// settled and planned for a next step of the same dt in one pass (OdePlasticJoint::
// after_step_and_plan) once the dt has repeated, so a run at a constant dt reads each joint's state
// once a step.
//
// Collisions: ODE has no built-in contact handling. collide() does the usual dSpaceCollide with a
// near callback that skips bodies held by an intact plastic joint (as Bullet does for a
// constraint's bodies; once the joint breaks they collide again) — call it before step() and empty
// the contact group after. A caller with its own near callback skips pairs for which joined(a, b).
// The contacts collide() makes report their forces, and step() books their work (contact_work()).
#include <ode/ode.h>

#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "plascap/adapters/impulse_work.hpp"
#include "plascap/adapters/joint_loads.hpp"
#include "plascap/adapters/ode_plastic_joint.hpp"

namespace plascap {

class OdeWorldBodies;  // src/ode_world_bodies.hpp

class OdePlasticJoints {
public:
    enum class Stepper {
        Quick,  // dWorldQuickStep: iterative, O(rows)
        Exact,  // dWorldStep: the direct LCP solver, O(rows³) per island — 0.18 s a step at 1,206 rows,
                // 85 s at 7,050 (a 2-core VM; docs/structures.md, "Known limits")
        // dWorldQuickStep with split corrections: the joints' rows start from the forces of the
        // step before (a warm start) and hold their rates without position corrections; a second
        // QuickStep, from rest, without gravity or loads, then makes the corrections, and every
        // body gets its velocity of the first back (as Bullet's split impulses). A structure under
        // load then no longer sags by what QuickStep's iterations leave (docs/adapters.md, "ODE:
        // split corrections"). Up to twice QuickStep's cost; the pass is skipped where nothing
        // needs correcting. Every joint of the world acts in the pass too: contacts keep bodies
        // apart, and contacts and the caller's own joints make their ODE corrections once more.
        QuickSplit,
    };

    explicit OdePlasticJoints(dWorldID world);
    ~OdePlasticJoints();
    OdePlasticJoints(OdePlasticJoints&&) noexcept;
    OdePlasticJoints& operator=(OdePlasticJoints&&) noexcept;

    // A joint between a (nullptr: the world) and b whose frame is `frame_in_world` now (origin = the
    // anchor, columns = the joint's x, y (beam axis), z). It takes hold at the first step that starts
    // at or after `takes_hold_at` [s] (by default the next one); its positions then are its unloaded
    // state.
    OdePlasticJoint& add(dBodyID a, dBodyID b, const Pose& frame_in_world, const PlasticJointSettings& settings,
                         double takes_hold_at = 0.0);

    // One step of dt [s] for the world and every joint in it.
    void step(double dt, Stepper stepper = Stepper::Quick);

    // Whether an intact plastic joint joins a and b (in either order): such pairs do not collide.
    bool joined(dBodyID a, dBodyID b) const;

    // Collides `space` (dSpaceCollide) and attaches a contact joint of `surface`, in `contacts`, at each
    // of up to `max_contacts` points of every touching pair of geoms — but for pairs of bodies that
    // joined() holds, pairs of static geoms, and pairs for which `skip` (if given) returns true.
    void collide(dSpaceID space, dJointGroupID contacts, const dSurfaceParameters& surface, int max_contacts = 8,
                 const std::function<bool(dBodyID, dBodyID)>& skip = {});

    // The work the contact joints that collide() made did on their bodies, summed over the steps so far
    // [J]: negative where impacts and friction took energy (impulse_work.hpp). Contact joints a caller
    // makes itself are not counted.
    double contact_work() const { return contact_work_; }
    // The work the caller's loads and gravity did over the motion the correction passes made
    // (Stepper::QuickSplit), summed over the steps so far [J]: work no velocity carried, which an
    // energy ledger books apart, as Bullet's split-impulse pushes.
    double correction_work() const { return correction_work_; }

    double time() const { return time_; }  // [s], the sum of the steps taken
    // How many joints the last step solved (OdePlasticJoint::solved): those whose bodies slept, broken
    // ones and ones yet to take hold cost a glance, not a settle and a plan.
    std::size_t solved_joints() const { return solved_joints_; }
    std::size_t size() const { return joints_.size(); }
    OdePlasticJoint& operator[](std::size_t i) { return *joints_[i].joint; }
    const OdePlasticJoint& operator[](std::size_t i) const { return *joints_[i].joint; }

private:
    struct Entry {
        std::unique_ptr<OdePlasticJoint> joint;
        double takes_hold_at;
        // Ready for a next step of the last step's dt (after_step_and_plan). Kept here, beside the
        // pointer, so a step passes over a ready joint without loading it.
        bool ready = false;
    };
    // A contact joint of the coming step: its bodies (either may be 0, the static world), their
    // velocities at the step's start, and the forces ODE reports back (at a stable address).
    struct Contact {
        dBodyID body[2];
        BodyVelocity start[2];
        dJointFeedback feedback;
    };
    struct Collision;
    static void near_callback(void* data, dGeomID g1, dGeomID g2);
    // Makes a contact joint and has it report its forces into contacts_.
    void attach_contact(dJointGroupID group, const dContact& contact, dBodyID b1, dBodyID b2);
    void book_contact_work(double dt);
    // Stepper::QuickSplit: the step itself; the bodies' loads in it (records_), taken before it; and
    // the correction pass after it.
    void split_step(double dt);
    void record_loads(const dVector3 gravity);
    void correction_pass(double dt, const dVector3 gravity);
    // Tells every joint whether its rows are split (on a change of stepper).
    void split_corrections(bool on);

    dWorldID world_;
    std::vector<Entry> joints_;
    std::multiset<std::pair<dBodyID, dBodyID>> joined_;  // intact joints' body pairs, ordered
    std::deque<Contact> contacts_;  // those collide() made for the coming step
    double contact_work_ = 0.0;
    double correction_work_ = 0.0;
    bool split_ = false;  // the joints' rows are split (the last step's stepper was QuickSplit)
    // Per body of the world, for the correction pass: the loads of the caller and gravity in the
    // step, and the velocities the step ended with.
    struct BodyRecord {
        dBodyID body;
        WorldLoad load;
        BodyVelocity velocity;
    };
    std::vector<BodyRecord> records_;
    std::unique_ptr<OdeWorldBodies> bodies_;  // made at the first split step
    double time_ = 0.0;
    std::size_t solved_joints_ = 0;
    double last_dt_ = std::numeric_limits<double>::quiet_NaN();  // the dt of the last step; NaN before the first
};

}  // namespace plascap
