#pragma once
// A Bullet dynamics world with everything it owns (collision configuration, dispatcher, broadphase,
// sequential-impulse solver — BulletPlasticSolver, which warm-starts plascap's rows and corrects
// their drift by split impulses), and a box body. Installed on purpose: a program that only wants plastic
// joints in a plain world needs nothing more (examples/consumer/bullet_main.cpp), and plascap's
// tools, tests and benchmarks use the same. Bodies and constraints stay owned by the caller, and a
// body joins the world only through world().addRigidBody().
#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "plascap/adapters/bullet_plastic_solver.hpp"
#include "plascap/adapters/impulse_work.hpp"

namespace plascap {

// The world's constraint solver: plascap's (warm-started rows, split-impulse corrections) or
// Bullet's own btSequentialImpulseConstraintSolver (every joint row cold, Baumgarte in its velocity).
enum class BulletSolverKind { Plascap, Bullet };

class BulletWorld {
public:
    // gravity [m/s²] in world coordinates; iterations: the solver's iterations per step.
    BulletWorld(const btVector3& gravity, int iterations, BulletSolverKind solver = BulletSolverKind::Plascap);
    ~BulletWorld();
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;

    btDiscreteDynamicsWorld& world() { return *world_; }
    // The work of the split-impulse position corrections so far (BulletPlasticSolver::correction_work;
    // 0 with Bullet's own solver) [J].
    double correction_work() const { return plascap_solver_ ? plascap_solver_->correction_work() : 0.0; }
    // From the next step on, count the work the contacts' impulses (normal and friction) do on the
    // bodies: contact_work(), summed over the steps counted [J], negative where impacts and friction
    // took energy (impulse_work.hpp). Split-impulse pushes out of a deep penetration move bodies
    // without a velocity and are not in it. Off by default: it records every body's velocities at
    // each step's start, O(bodies) a step.
    void count_contact_work() { counting_contacts_ = true; }
    double contact_work() const { return contact_work_; }
    // One fixed step of dt seconds (no interpolation sub-steps).
    void step(double dt);

private:
    // A body's centre and velocities at the step's start, by its place in the world's object array.
    struct BodyStart {
        btVector3 centre;
        BodyVelocity velocity;
    };
    void note_step_start();
    double contact_work_of_step() const;

    std::vector<BodyStart> start_;
    bool counting_contacts_ = false;
    double contact_work_ = 0.0;
    std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btDbvtBroadphase> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    const BulletPlasticSolver* plascap_solver_ = nullptr;  // solver_, when it is plascap's
    std::unique_ptr<btDiscreteDynamicsWorld> world_;
};

// A box body of half extents `half` [m], mass [kg] (0: static), at `transform`; never sleeps, so a
// slow plastic flow is never frozen by deactivation. Owns its shape and motion state. `inertia`, the
// principal moments about the box's axes [kg·m²], replaces the solid box's (a beam segment's mass
// is its section's, not a box's).
class BulletBox {
public:
    BulletBox(const btVector3& half, double mass, const btTransform& transform, const btVector3* inertia = nullptr);
    ~BulletBox();
    BulletBox(const BulletBox&) = delete;
    BulletBox& operator=(const BulletBox&) = delete;
    btRigidBody& body() { return *body_; }

private:
    std::unique_ptr<btBoxShape> shape_;
    std::unique_ptr<btDefaultMotionState> motion_;
    std::unique_ptr<btRigidBody> body_;
};

}  // namespace plascap
