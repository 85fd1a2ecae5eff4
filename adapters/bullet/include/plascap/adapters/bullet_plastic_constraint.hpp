#pragma once
// plascap's own Bullet constraint for a plastic joint: it emits exactly the rows its dofs need —
// none for a free dof, a locked row for a rigid one, and for a plastic one what the shared law
// commands (Hold: a row with a rate target within the force range [lower, upper], both capacities
// at once; Push: exactly the spring force, which BulletPlasticSolver applies once, without a row:
// apply_pushes) — where Bullet's 6-dof springs, driven from outside, carry every axis's limit,
// motor and spring machinery and one symmetric motor bound.
//   translations: the components, along a's frame axes, of b's anchor minus a's; the rows act at
//     b's anchor on both bodies, which makes each row's rate the exact rate of its component;
//   rotations: swing and twist (swing_twist.hpp), the rows along their exact gradients — no
//     singularity at a 90° twist, and a row's force is its angle's generalised force.
// The frame is measured once per step: measure() caches it until a body moves, so the joint's
// settle-and-plan after a step and the rows of the next share one computation.
#include <btBulletDynamicsCommon.h>

#include <array>
#include <cmath>
#include <cstddef>

#include "plascap/adapters/dof.hpp"
#include "plascap/adapters/joint_frame.hpp"
#include "plascap/adapters/row_capabilities.hpp"
#include "plascap/adapters/row_command.hpp"

namespace plascap {

class BulletPlasticConstraint final : public btTypedConstraint {
public:
    static constexpr RowCapabilities kRows{RotationMeasure::SwingTwist, true};

    // b joined to a (nullptr: the world) at `frame_in_world`: origin = anchor, basis columns = the
    // joint's x, y (beam axis) and z.
    BulletPlasticConstraint(btRigidBody* a, btRigidBody& b, const btTransform& frame_in_world);

    // What dof i's row does from the next step on (dofs in Dof order: x, y, z, then rotations).
    void free_row(std::size_t i);
    void lock_row(std::size_t i, double at);  // held at position `at` [m | rad], errors corrected at the ERP
    void command_row(std::size_t i, const RowCommand& command);

    // The joint now, from the bodies' poses: dof positions of b relative to a, the rows' axes and
    // anchor in the world. Recomputed only when a body has moved since the last call.
    const JointFrameState& measure();

    // Set by BulletPlasticSolver before each solve: when on, the rows' velocity targets leave out
    // their position corrections (Baumgarte), which the solver applies as split-impulse pushes
    // instead; correction_rate(k) gives each written row's correction [m/s | rad/s].
    void split_corrections(bool on) { split_corrections_ = on; }
    double correction_rate(std::size_t k) const { return k < written_ ? rows_[written_dof_[k]].correction : 0.0; }
    // A row's Jacobian: J·v is its dof's rate; the linear part on b (−linear on a; zero for a rotation).
    struct RowJacobian {
        btVector3 linear, angular_a, angular_b;
    };
    // The Push dofs (the law's springs), which getInfo1 and getInfo2 leave out: a row whose force is
    // fixed before the solve takes no part in its iterations, and left in Bullet's row pool it
    // would only spread the rows the iterations read (docs/adapters.md, Bullet, "Springs without
    // rows"). `apply(jacobian, force)` applies the force [N | N·m] over the step to both bodies
    // and returns the row's effective mass 1/(J·M⁻¹·Jᵀ) (NaN if not known); the force is the dof's
    // carried force, and its effective mass the law's (solved_masses), as for a written row.
    template <class Apply>
    void apply_pushes(Apply&& apply) {
        if (push_count_ == 0) return;  // most joints: their rows need not be read
        const JointFrameState& s = measure();  // cached since the joint's plan: the bodies have not moved
        const Levers at_anchor = levers(s);
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            Row& row = rows_[i];
            if (row.kind != RowKind::Push) continue;
            row.solved_mass = apply(jacobian(s, at_anchor, i), row.lower);
            row.carried = row.lower;
            row.pushed = 0.0;  // a spring's law books no motion apart (elastic_plastic_law.hpp)
        }
    }
    // The force the k-th row written by the last getInfo2 carried when its step was solved (0 before
    // the first) [N | N·m], for BulletPlasticSolver's warm start; and the solver's report of it.
    double carried_force(std::size_t k) const { return k < written_ ? rows_[written_dof_[k]].carried : 0.0; }
    void carry_force(std::size_t k, double force) {
        if (k < written_) rows_[written_dof_[k]].carried = force;
    }
    // The motion the solver's split-impulse pushes made along the k-th written row in the last solve
    // [m | rad] (0 without them), and per dof: what the law books apart (plastic_joint_law.hpp).
    void carry_push(std::size_t k, double motion) {
        if (k < written_) rows_[written_dof_[k]].pushed = motion;
    }
    // The effective mass 1/(J·M⁻¹·Jᵀ) of the k-th written row as the solver formed it in the last
    // solve (BulletPlasticSolver: Bullet's jacDiagABInv; NaN where Bullet left it 0), and per
    // dof (NaN for a dof whose row has not been solved yet): the law's eq. 3.2 masses at the start
    // of the last step, which saves the joint computing them again (row_effective_mass.hpp).
    void note_row_mass(std::size_t k, double mass) {
        if (k < written_) rows_[written_dof_[k]].solved_mass = mass;
    }
    PerDof<double> solved_masses() const {
        PerDof<double> masses;
        for (std::size_t i = 0; i < rows_.size(); ++i) masses[i] = rows_[i].solved_mass;
        return masses;
    }
    PerDof<double> corrected_motion() const {
        PerDof<double> motion{};
        for (std::size_t i = 0; i < rows_.size(); ++i) motion[i] = rows_[i].pushed;
        return motion;
    }

    void getInfo1(btConstraintInfo1* info) override;
    void getInfo2(btConstraintInfo2* info) override;
    // BT_CONSTRAINT_STOP_ERP / BT_CONSTRAINT_STOP_CFM set the locked rows' error reduction (default:
    // the world's ERP; getParam then gives −1) and constraint force mixing (default 0); other
    // parameters are ignored.
    void setParam(int num, btScalar value, int axis = -1) override;
    btScalar getParam(int num, int axis = -1) const override;

private:
    enum class RowKind { None, Lock, Hold, Push };
    static bool emits_row(RowKind kind) { return kind == RowKind::Lock || kind == RowKind::Hold; }
    void set_kind(std::size_t i, RowKind kind);  // keeps row_count_ and push_count_
    struct Levers {
        btVector3 a, b;  // the anchor less each body's centre of mass [m]
    };
    Levers levers(const JointFrameState& s) const;
    static RowJacobian jacobian(const JointFrameState& s, const Levers& levers, std::size_t i);
    struct Row {
        RowKind kind = RowKind::None;
        double target = 0.0;  // Lock: position; Hold: rate
        double lower = 0.0, upper = 0.0;  // Hold and Push: force range on b [N | N·m]
        double correction = 0.0;          // the position-correction rate last written
        double carried = 0.0;             // the force it carried in the last solved step
        double pushed = 0.0;              // the motion the last solve's pushes made along it
        double solved_mass = NAN;         // its effective mass in the last solve [kg | kg·m²]
    };

    btTransform frame_in_a_, frame_in_b_;
    std::array<Row, 6> rows_{};
    int row_count_ = 0;   // of Lock and Hold rows: those getInfo2 writes
    int push_count_ = 0;  // of Push dofs
    std::array<std::size_t, 6> written_dof_{};  // the dof of each row the last getInfo2 wrote
    std::size_t written_ = 0;
    bool split_corrections_ = false;
    btScalar stop_erp_ = -1.0;  // < 0: the world's
    btScalar stop_cfm_ = 0.0;
    // The measurement and the body poses it was made at.
    JointFrameState state_{};
    btTransform measured_a_, measured_b_;
    bool measured_ = false;
};

}  // namespace plascap
