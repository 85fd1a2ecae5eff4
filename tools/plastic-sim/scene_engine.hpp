#pragma once
// What plastic-sim needs from a physics engine running a Scene; one implementation per engine
// (bullet_scene.cpp, ode_scene.cpp). Everything engine-neutral (reading the scene,
// the run loop, reports) stays out of the implementations.
#include <memory>
#include <string>
#include <vector>

#include "plascap/adapters/plastic_joint_law.hpp"
#include "plascap/adapters/vec3.hpp"
#include "scene.hpp"

namespace plascap {

struct BodyState {
    Vec3 position{};          // centre of mass [m]
    Vec3 velocity{};          // [m/s]
    Vec3 angular_velocity{};  // [rad/s]
    Quaternion orientation{1, 0, 0, 0};  // w, x, y, z
};

class SceneEngine {
public:
    virtual ~SceneEngine() = default;
    virtual std::string description() const = 0;  // e.g. "Bullet 3.24, double precision"
    // Engages the joints whose time has come, then advances the world by the scene's dt.
    virtual void step() = 0;
    // Adds a force at a world point and a moment (world directions) to a body for the next step only.
    virtual void apply_load(std::size_t body, const Vec3& force, const Vec3& point, const Vec3& moment) = 0;
    virtual double time() const = 0;
    virtual BodyState body(std::size_t index) const = 0;
    // nullptr until the joint engages.
    virtual const PlasticJointLaw* joint_law(std::size_t index) const = 0;
    // The generalised forces the joint's rows applied to its body b in the last step [N, N·m].
    virtual PerDof<double> joint_forces(std::size_t index) const = 0;
    // The joint's dof positions now: b relative to a in the joint frame [m, rad].
    virtual PerDof<double> joint_positions(std::size_t index) = 0;
    // What the engine reported as going wrong but survived (e.g. ODE's "LCP internal error"): the
    // results may be unreliable; and, from the start, what it foresees (a run that will take hours).
    // An engine error it cannot survive is thrown as std::runtime_error.
    virtual std::vector<std::string> warnings() const { return {}; }
    // The work the engine's position corrections did outside its velocity solve (Bullet's split
    // impulses), summed over the run [J]; 0 for engines that correct positions in their velocities.
    virtual double correction_work() const { return 0.0; }
    // The work the contacts did on the bodies, summed over the run [J]: negative where impacts and
    // friction took energy (plascap/adapters/impulse_work.hpp).
    virtual double contact_work() const { return 0.0; }
    // The work the joint's rows did on its bodies since it took hold [J] (plascap/adapters/rows_work.hpp).
    virtual double joint_rows_work(std::size_t index) const = 0;
};

// The engines this build has, by --engine name.
std::vector<std::string> available_engines();
// Throws InputError for an unknown engine or one this build lacks.
std::unique_ptr<SceneEngine> make_engine(const std::string& name, const Scene& scene);

}  // namespace plascap
