#pragma once
// The joint-level law: six dof laws, the breaking rule, and the totals reports need. Engine
// adapters call plan() before each step and settle() after it; nothing here knows an engine.
// With a yield condition in the settings, the plastic dofs yield together on it (coupled_yield.hpp).
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "plascap/adapters/dof.hpp"
#include "plascap/adapters/elastic_plastic_law.hpp"
#include "plascap/adapters/plastic_joint_settings.hpp"
#include "plascap/adapters/row_capabilities.hpp"

namespace plascap {

class PlasticJointLaw {
public:
    // `rows`: what the engine's rows measure and carry (row_capabilities.hpp).
    explicit PlasticJointLaw(const PlasticJointSettings& settings, RowCapabilities rows = {});
    ~PlasticJointLaw();
    PlasticJointLaw(PlasticJointLaw&&) noexcept;
    PlasticJointLaw& operator=(PlasticJointLaw&&) noexcept;

    // When the joint takes hold (it may be built before, on bodies that have moved since): these
    // positions are its unloaded state. Engines lock rigid dofs at them too. Every call takes the
    // positions as measured; rotations are unwrapped across ±π against the previous call's.
    void start(const PerDof<double>& positions);

    // Row commands for the plastic dofs (empty for free and rigid ones), from the dof positions,
    // the step and each row's effective mass.
    PerDof<std::optional<RowCommand>> plan(const PerDof<double>& positions, double dt,
                                           const PerDof<double>& effective_masses);

    // After a step that ended at `time`: the new positions and the generalised forces the rows
    // applied to body b. Returns true when the joint broke in this step. A broken joint ignores
    // further calls: broken stays broken.
    // `corrected_motion`: per dof, the part of the step's motion that position corrections made
    // outside the velocity solve (elastic_plastic_law.hpp; zeros on engines without them).
    bool settle(const PerDof<double>& positions, const PerDof<double>& forces, double time,
                const PerDof<double>& corrected_motion = {});

    // Breaks the joint at `time` whatever its deformation (a member removed, a charge fired); no-op
    // if broken already.
    void sever(double time) {
        if (!broken()) broken_at_ = time;  // a time is not NaN
    }

    DofMode mode(Dof dof) const { return modes_[index(dof)]; }
    // The law of a plastic dof; nullptr for free and rigid ones.
    const ElasticPlasticLaw* law(Dof dof) const;

    bool broken() const { return !std::isnan(broken_at_); }
    // A rigid-plastic row was at its bound in the last step (flowing or not).
    bool at_capacity() const { return summary_.at_capacity; }
    // A rigid-plastic row carried at least half its bound in the last step.
    bool near_capacity() const { return summary_.near_capacity; }
    std::optional<double> broken_at() const { return broken() ? std::optional<double>(broken_at_) : std::nullopt; }
    double plastic_displacement() const { return summary_.plastic_displacement; }  // Σ over translations of Σ|Δx_p| [m]
    double plastic_rotation() const { return summary_.plastic_rotation; }          // Σ over rotations [rad]
    double dissipated() const;            // [J]
    // The part of dissipated() that flow driven by position corrections booked [J]: an energy
    // ledger counts it with the corrections (Bullet's split impulses), not the velocity solve.
    double dissipated_by_corrections() const;
    double elastic_energy(const PerDof<double>& positions) const;  // [J]
    // How close the last step's loads came to what the joint carries: U of the coupled condition, or
    // without one the largest |load|/capacity of its side over the plastic dofs (the paper's
    // independent limits, eq. 2.10–2.14); 1 at yield, 0 before the first step. For reports. With a
    // condition and Σ|s_j|/C_j ≤ 1/2 (far inside), that sum, an upper bound of U, without a solve.
    double utilisation() const;
    // The generalised forces the rows applied to b in the last settled step [N, N·m].
    const PerDof<double>& forces() const { return last_forces_; }
    const PlasticJointSettings& settings() const { return *settings_; }

private:
    // What the dof laws say after a settle: kept, not recomputed, because the driver and the
    // adapters ask every step for every joint (issue 16: their cost per joint).
    struct Summary {
        double plastic_displacement = 0.0, plastic_rotation = 0.0;
        bool at_capacity = false, near_capacity = false;
    };
    void summarise();

    PerDof<ElasticPlasticLaw*> plastic_laws();
    // The measured positions with the rotations unwrapped against the last ones seen (angles wrap at ±π).
    PerDof<double> continuous(const PerDof<double>& measured) const;
    void track(const PerDof<double>& measured, const PerDof<double>& continuous_positions);
    // The section loads of the last step (−forces on b, on the continuous angles' branch): utilisation, coupling.
    PerDof<double> last_loads() const;

    bool euler_rows() const { return rows_.rotations == RotationMeasure::EulerXYZ; }
    // Whether dof i has a law (the constructor makes one for each plastic dof, none for the others).
    // Read from the modes, not from laws_[i]'s own flag: a step then never touches the slot of a
    // rigid or free dof (112 B each; docs/adapters.md, ODE "Cost").
    bool plastic(std::size_t i) const { return modes_[i] == DofMode::Plastic; }
    // Σ over the plastic dofs of of_law(law, i): the joint's dissipated and elastic energies.
    template <class OfLaw>
    double sum_over_plastic(OfLaw of_law) const;

    // What a coupled yield condition needs beside the dof laws (plastic_joint_law.cpp). Only a joint
    // with one carries it, and the settings stay out of the joint's own bytes but for what each
    // step reads: a step of 10,000 joints waits on memory for every byte of theirs (issue 16,
    // docs/adapters.md "Cost").
    struct Coupling;

    std::shared_ptr<const PlasticJointSettings> settings_;  // as given, for settings()
    PerDof<DofMode> modes_;
    RowCapabilities rows_;  // two bytes, beside the six modes in one word
    double max_plastic_displacement_, max_plastic_rotation_;  // settings_'s, read every step
    std::unique_ptr<Coupling> coupling_;  // none without a yield condition
    // Each plastic dof's law; a slot of a rigid or free dof holds no law (and no std::optional's
    // flag either: 8 B a slot less for a step to touch, issue 16). plastic(i) tells which.
    PerDof<ElasticPlasticLaw> laws_;
    double broken_at_ = NAN;  // NaN: not broken (no std::optional's flag: 8 B less a joint, issue 16)
    // The generalised forces the rows applied to b in the last step, as the engine reported them (the
    // driver and the adapters read them here: one copy a joint, issue 16).
    PerDof<double> last_forces_{};
    // The rotations (Mx, My, Mz) as last measured and as unwrapped: translations need no unwrapping,
    // so the law keeps only the angles (48 B less for a step to touch, issue 16).
    using Rotations = std::array<double, 3>;
    static Rotations rotations_of(const PerDof<double>& positions) {
        return {positions[index(Dof::Mx)], positions[index(Dof::My)], positions[index(Dof::Mz)]};
    }
    static constexpr std::size_t angle_index(Dof rotation) { return index(rotation) - index(Dof::Mx); }  // in Rotations
    Rotations last_measured_{}, last_continuous_{};
    Summary summary_;
};

}  // namespace plascap
