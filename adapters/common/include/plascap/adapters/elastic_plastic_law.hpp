#pragma once
// One dof's elastic–perfectly-plastic law, shared by every engine adapter.
//
// Force on body b: f = −k·(x − x_p), capped at −capacity_positive ≤ f ≤ capacity_negative, where x is
// the dof position and x_p the plastic offset (the spring's moving equilibrium). When the elastic
// trial force passes a capacity, x_p moves so the force equals it (return mapping; Simo & Hughes,
// Computational Inelasticity, 1998, §1.2). Without a stiffness (or past eq. 3.2) the dof is
// rigid-plastic: x_p follows x in the steps where the row flowed at its capacity (flow_criterion.hpp
// tells flow from the slack of an unconverged solve); motion the engine's iterative solver let
// through otherwise is not plastic and is corrected back towards x_p (Baumgarte, with Bullet's and
// ODE's usual factor kHoldCorrection). The work the dof absorbs in plastic flow is the dissipated
// energy.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "plascap/adapters/flow_criterion.hpp"
#include "plascap/adapters/regime.hpp"
#include "plascap/adapters/row_command.hpp"

namespace plascap {

// The share of a rigid-plastic dof's position error corrected per step (Baumgarte; the default ERP
// of Bullet and ODE is 0.2).
inline constexpr double kHoldCorrection = 0.2;

struct DofLaw {
    double capacity_positive = 0.0;    // resists positive motion of b (N, Mx, Mz: tension side) [N | N·m]
    double capacity_negative = 0.0;    // resists negative motion (N_neg, Mx_neg, Mz_neg)      [N | N·m]
    std::optional<double> stiffness;   // k [N/m | N·m/rad]; none = rigid-plastic
};

// Throws InputError naming `where` unless the capacities are positive and finite and the
// stiffness, if any, is positive and finite.
void validate_dof_law(const DofLaw& law, const char* where);

class ElasticPlasticLaw {
public:
    // `two_sided_bounds`: the engine's Hold row carries both capacities (row_capabilities.hpp), so a
    // load reversal meets the capacity of its own side from its first step.
    explicit ElasticPlasticLaw(const DofLaw& law, bool two_sided_bounds = false);
    // No law yet: a slot a joint keeps for a dof that is not plastic (plastic_joint_law.hpp). Only
    // assigning a law to it is meaningful.
    ElasticPlasticLaw() : books_(nullptr) {}

    // When the joint takes hold: the dof's position then is its unloaded, unyielded state.
    void start(double position);

    // Before a step: the row command from the current position, the step and the row's effective
    // mass (for eq. 3.2). `hold_bound`, from a joint's coupled yield condition, replaces the
    // capacity as the rigid-plastic row's bound this step.
    RowCommand plan(double position, double dt, double effective_mass, std::optional<double> hold_bound = {});

    // After the step: the new position and the force the row applied (generalised, on b).
    // `corrected_motion`: the part of the step's motion that position corrections made outside the
    // velocity solve (Bullet's split-impulse pushes; 0 on engines without them). A rigid-plastic row
    // that flows books its work on that motion too, and reports it apart
    // (dissipated_by_corrections): an energy ledger counts it with the corrections that drove it.
    void settle(double position, double applied_force, double corrected_motion = 0.0);

    // Part of a joint with a coupled yield condition (plastic_joint_law.hpp): the spring force is not
    // capped at this dof's own capacities and settle() leaves its return mapping to the joint,
    // which moves the plastic offset through flow().
    void couple() { coupled_ = true; }

    // The work the row does per unit of the dof's motion, per unit of its force, for the next
    // settle() or flow(): 1 but for Euler-angle rotation rows (plastic_joint_law.cpp).
    void set_work_factor(double factor) { books_->work_factor = factor; }
    // The plastic offset moves by `step` under `load` (the section load, −force on b): the
    // accumulated plastic motion grows by |step| and the dissipated energy by load·step.
    void flow(double step, double load);

    DofLaw law() const { return {capacity_positive_, capacity_negative_, stiffness()}; }
    Regime regime() const { return regime_; }
    // ω·dt of the last plan (eq. 3.2); 0 without a stiffness or before the first plan.
    double omega_dt() const;
    double plastic_offset() const { return plastic_offset_; }
    double accumulated_plastic() const { return books_->accumulated; }  // Σ|Δx_p| [m | rad]
    double dissipated() const { return books_->dissipated; }            // [J]
    // The part of dissipated() booked on motion that position corrections made [J].
    double dissipated_by_corrections() const { return books_->dissipated_by_corrections; }
    // The plastic offset moved in the last settle() or flow() (accumulated_plastic() grew).
    bool moved() const { return moved_; }
    // A rigid-plastic row at its bound in the last step.
    bool at_capacity() const { return regime_ != Regime::ElasticPlastic && flow_.at_bound(); }
    // A rigid-plastic row carried at least half its bound in the last step.
    bool near_capacity() const { return regime_ != Regime::ElasticPlastic && std::abs(flow_.last_share()) >= 0.5; }
    // ½·k·(x − x_p)² in the elastic regime, else 0 [J].
    double elastic_energy(double position) const;

private:
    // A row's bound is symmetric, so take the capacity on the side the dof was last loaded; before
    // any load, the smaller one.
    double hold_bound() const {
        if (last_force_sign_ < 0) return capacity_positive_;
        if (last_force_sign_ > 0) return capacity_negative_;
        return capacity_positive_ < capacity_negative_ ? capacity_positive_ : capacity_negative_;
    }
    // The bound the last planned Hold row put on a force of this sign on b: both capacities, each on
    // its side, or one bound for both sides.
    double side_bound(double force) const {
        if (!held_on_both_capacities_) return last_bound_;
        return force >= 0.0 ? capacity_negative_ : capacity_positive_;
    }
    void settle_rigid_plastic(double position, double applied_force, double corrected_motion);
    void settle_elastic_plastic(double position);
    void clear_pending();

    // What a step reads only when the dof flows or is at its bound: the books of plastic work and
    // the flow not yet confirmed. Kept apart, so a step touches only the law's object itself (104 B
    // where it was 184): a step of 10,000 joints waits on memory for every byte it touches (issue
    // 16, docs/adapters.md ODE "Cost").
    struct Books {
        double accumulated = 0.0;  // Σ|Δx_p|
        double dissipated = 0.0;
        double dissipated_by_corrections = 0.0;
        // The motion and the row's work in the steps at its bound not yet confirmed as flow [m | rad, J].
        double pending_motion = 0.0, pending_work = 0.0;
        double pending_correction_work = 0.0;  // the part of pending_work on corrected motion [J]
        double work_factor = 1.0;
    };
    // The books in their own allocation, copied with the law (a law stays a value).
    class BooksApart {
    public:
        BooksApart() : books_(std::make_unique<Books>()) {}
        explicit BooksApart(std::nullptr_t) {}  // no books: a slot without a law
        BooksApart(const BooksApart& other) : books_(copy(other)) {}
        BooksApart& operator=(const BooksApart& other) {
            books_ = copy(other);
            return *this;
        }
        BooksApart(BooksApart&&) noexcept = default;
        BooksApart& operator=(BooksApart&&) noexcept = default;
        Books& operator*() const { return *books_; }
        Books* operator->() const { return books_.get(); }

    private:
        static std::unique_ptr<Books> copy(const BooksApart& other) {
            return other.books_ ? std::make_unique<Books>(*other.books_) : nullptr;  // none: moved from
        }
        std::unique_ptr<Books> books_;
    };

    // A stiffness is positive (validate_dof_law): 0 stands for none.
    bool has_stiffness() const { return stiffness_ > 0.0; }
    std::optional<double> stiffness() const { return has_stiffness() ? std::optional<double>(stiffness_) : std::nullopt; }

    // Members ordered so the small ones share one word. The DofLaw is kept as three doubles, its
    // stiffness without a std::optional's flag: 8 B a dof less for a step to touch (issue 16).
    double capacity_positive_ = 0.0, capacity_negative_ = 0.0;  // DofLaw's [N | N·m]
    double stiffness_ = 0.0;                                     // DofLaw's, 0: none [N/m | N·m/rad]
    Regime regime_ = Regime::RigidPlastic;
    bool two_sided_bounds_ = false;
    bool coupled_ = false;
    bool planned_ = false;
    bool moved_ = false;     // the plastic offset moved in the last settle or flow
    bool pending_ = false;   // the books hold flow not yet confirmed
    std::int8_t last_force_sign_ = 0;  // of the force the row applied in the last step: −1, 0 or 1
    bool held_on_both_capacities_ = false;  // the last Hold row's range was [−capacity_positive, capacity_negative]
    double planned_position_ = 0.0;  // the step as planned
    // m/dt², the force per unit of motion that stops the step's motion in one step [N/m | N·m/rad].
    double planned_stopping_stiffness_ = 0.0;
    double plastic_offset_ = 0.0;
    FlowCriterion flow_;  // rigid-plastic: is motion at the bound flow?
    double last_bound_ = 0.0;  // the last Hold row's bound on both sides, unless held on both capacities
    BooksApart books_;
};

}  // namespace plascap
