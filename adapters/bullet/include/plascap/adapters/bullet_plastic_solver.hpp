#pragma once
// Bullet's sequential-impulse solver, made for plascap's rows: it warm-starts them, corrects
// their drift by split impulses, and applies a spring's force (Push) once, without a row.
//   Warm start: Bullet warm-starts contacts from the last step's impulses but starts every joint row
//   from zero (btSequentialImpulseConstraintSolver::convertJoint), so a chain of joints under a
//   sustained load re-solves its whole load each step and sags by what the iterations leave
//   unconverged. Here each row of a BulletPlasticConstraint starts from the force it carried the
//   step before, clamped to its bounds this step and applied to the bodies as Bullet applies a
//   contact's warm start.
//   Split impulses: a row's position correction (its Baumgarte rate) is not part of its velocity
//   target but solved apart, as Bullet does for contacts' penetration (m_splitImpulse): pushes that
//   move the bodies this step and leave no velocity behind. Warm-starting rows whose impulses carry
//   their corrections feeds those corrections back step after step — on the example beam at 100
//   iterations a growing oscillation that folded it (docs/adapters.md, "Bullet's solver") — and the
//   correction's velocity would remain as kinetic energy.
//   Springs: a Push dof's force is fixed before the solve (the law's explicit spring), so it is
//   applied to the bodies in the set-up, without a row (BulletPlasticConstraint::apply_pushes), as
//   ODE's adapter puts the same force on its bodies.
// The pushes are integrated by Bullet only with m_splitImpulse on (its default); their rotations are
// scaled by m_splitImpulseTurnErp (default 0.1, BulletWorld sets 1). Use this solver as the world's
// constraint solver (BulletWorld does); with any other solver plascap's joints work, cold-started,
// with Baumgarte in their rows.
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace plascap {

class BulletPlasticConstraint;

class BulletPlasticSolver : public btSequentialImpulseConstraintSolver {
public:
    // The work the split-impulse pushes (plascap's rows' and contacts') have done on the bodies
    // against the forces applied to them (gravity and loads), summed over every solve [J]: the
    // energy the position corrections put in — positive when they lift a load back to where its
    // joints hold it. An energy ledger books it apart from the joints' work.
    double correction_work() const { return correction_work_; }

protected:
    void convertJoints(btTypedConstraint** constraints, int count, const btContactSolverInfo& info) override;
    void solveGroupCacheFriendlySplitImpulseIterations(btCollisionObject** bodies, int body_count,
                                                       btPersistentManifold** manifolds, int manifold_count,
                                                       btTypedConstraint** constraints, int constraint_count,
                                                       const btContactSolverInfo& info, btIDebugDraw* drawer) override;
    btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int count, const btContactSolverInfo& info) override;

private:
    // A BulletPlasticConstraint of this solve and where its rows lie in
    // m_tmpSolverNonContactConstraintPool (Bullet lays each constraint's rows out in turn, in the
    // order its getInfo2 wrote them). One record per joint, not per row: the passes over the rows
    // read them where the solve keeps them (issue 16: a per-row list, rebuilt each step and read
    // twice, cost the warm-started solve most of its extra cache misses).
    struct PlascapRows {
        BulletPlasticConstraint* constraint;
        int index;  // in this solve's list of constraints
        int first;  // its first row in the pool
        int count;
    };
    std::vector<PlascapRows> joints_;  // this solve's
    // The set-up of one joint: its springs' forces applied to its bodies, and its k-th row's
    // effective mass noted, its correction rate set as a push target, its warm start applied.
    void apply_pushes(BulletPlasticConstraint& c, const btContactSolverInfo& info);
    void set_up_row(BulletPlasticConstraint& c, std::size_t k, btSolverConstraint& row, const btContactSolverInfo& info);
    // Calls `act(constraint, k, row)` for each row of this solve's plascap constraints.
    template <class Act>
    void for_each_row(Act&& act);
    // The push iterations per solve: half the velocity solve's (the corrections need not converge
    // in one step; what is left is corrected in the next).
    static int push_iterations(const btContactSolverInfo& info) { return std::max(1, info.m_numIterations / 2); }
    double largest_correction_ = 0.0;                // of the pushed rows' rates [m/s | rad/s]
    bool pushed_ = false;  // this solve ran pushes (plascap's rows' or contacts'): bodies may have moved
    double correction_work_ = 0.0;
};

}  // namespace plascap
