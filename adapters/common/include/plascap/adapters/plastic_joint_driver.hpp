#pragma once
// One plastic joint's step cycle, the same in every engine: when it takes hold, plan the rows of the
// next step from where the joint is, read back what the rows applied, settle the law, and report
// what the step did (yielded, broke) — once, to whoever listens. An engine adapter only measures the
// joint, sets its rows and acts on the report (wake the bodies, disable the rows); everything else
// lives here, so Bullet and ODE cannot drift apart.
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/joint_loads.hpp"
#include "plascap/adapters/plastic_joint_law.hpp"
#include "plascap/adapters/row_effective_mass.hpp"

namespace plascap {

// What one step did to a joint.
enum class JointEvent {
    None,     // held (or stayed elastic)
    Yielded,  // a dof flowed: plastic deformation grew
    AtCapacity,  // a rigid-plastic row was at its capacity but did not flow (yet: flow_criterion.hpp)
    Broke,    // it passed a breaking limit; its rows are gone for good
};

struct JointBreak {
    double time = 0.0;                  // the end of the step it broke in [s]
    double plastic_displacement = 0.0;  // accumulated then [m]
    double plastic_rotation = 0.0;      // [rad]
    double dissipated = 0.0;            // [J]
};

using BreakCallback = std::function<void(const JointBreak&)>;

class PlasticJointDriver {
public:
    // `rows`: what the adapter's rows measure and carry (row_capabilities.hpp).
    explicit PlasticJointDriver(const PlasticJointSettings& settings, RowCapabilities rows = {});

    // The joint takes hold at `now` [s]; `positions` (as measured) are its unloaded state, and where
    // its rigid dofs are held.
    void engage(const PerDof<double>& positions, double now);
    bool engaged() const { return engaged_; }
    const PerDof<double>& engaged_positions() const { return engaged_positions_; }

    // The row commands of the next step of dt, from the joint as measured at its start. `inertias()` → {b, a (nullopt: the
    // world)} is called only when the rows' effective masses are needed: for a spring (eq. 3.2), or
    // for a rigid-plastic row that may reach its bound (flow_criterion.hpp); a joint far below its
    // capacities keeps the masses it last had. `solved_masses`: the rows' effective masses as the
    // engine's solver formed them for the last step, per dof (NaN: not known); used instead of
    // computing them when every plastic dof's is known.
    template <class Inertias>
    PerDof<std::optional<RowCommand>> plan(const JointFrameState& state, double dt, Inertias&& inertias, const PerDof<double>& solved_masses = kUnknownMasses) {
        if (knows_every_plastic_mass(solved_masses)) {
            masses_ = solved_masses;
            masses_known_ = true;
        } else if (springs_ || !masses_known_ || law_.near_capacity()) {
            const std::pair<BodyInertia, std::optional<BodyInertia>> bodies = inertias();
            masses_ = row_effective_masses(state.axes, bodies.first, bodies.second);
            masses_known_ = true;
        }
        return law_.plan(state.positions, dt, masses_);
    }

    // After the step: the generalised forces the rows applied to b during it (joint_frame_loads of
    // their feedback, on the axes and b's centre of mass the step was planned with: the adapter's
    // rows keep them) and the dof positions now; `corrected_motion`, per dof, the part of the step's
    // motion position corrections made outside the velocity solve (plastic_joint_law.hpp). A broken
    // joint reports None ever after.
    JointEvent settle(const PerDof<double>& forces_on_b, const PerDof<double>& positions, double dt,
                      const PerDof<double>& corrected_motion = {});

    // A step the engine did not solve the joint in (its bodies asleep: their island was not
    // stepped): nothing moved and no row acted, so the law stays as it is — only the clock runs on,
    // and a severed joint breaks. The rows planned for the joint stay valid for a next step of dt.
    JointEvent idle(double dt);

    // The joint breaks at the end of the next step whatever its load (a member removed): settle()
    // then reports Broke, and the adapter drops its rows as for any break.
    void sever() { sever_ = true; }

    // Called once, from settle(), when the joint breaks.
    void on_break(BreakCallback callback) {
        on_break_ = callback ? std::make_unique<BreakCallback>(std::move(callback)) : nullptr;
    }

    const PlasticJointLaw& law() const { return law_; }
    bool broken() const { return law_.broken(); }
    // The generalised forces the rows applied to b during the last step [N, N·m].
    const PerDof<double>& forces() const { return law_.forces(); }
    double time() const { return time_; }

private:
    static constexpr PerDof<double> kUnknownMasses = {NAN, NAN, NAN, NAN, NAN, NAN};
    bool knows_every_plastic_mass(const PerDof<double>& masses) const {
        for (std::size_t i = 0; i < kDofCount; ++i) {
            if (law_.mode(kAllDofs[i]) == DofMode::Plastic && std::isnan(masses[i])) return false;
        }
        return true;
    }

    // After a step, settled or idle: a severed joint breaks; a broken law calls on_break_ and
    // reports Broke, else None.
    JointEvent break_if_due();

    // The flags share one word: a step of 10,000 joints waits on memory for every byte of theirs
    // (issue 16, docs/adapters.md ODE "Cost").
    PlasticJointLaw law_;
    bool springs_ = false;  // a plastic dof has a stiffness
    bool masses_known_ = false;
    bool engaged_ = false;
    bool sever_ = false;
    PerDof<double> masses_{};  // the rows' effective masses as last computed
    PerDof<double> engaged_positions_{};
    double time_ = 0.0;
    // Apart from the joint's own bytes: 8 B where a std::function is 32.
    std::unique_ptr<BreakCallback> on_break_;
};

}  // namespace plascap
