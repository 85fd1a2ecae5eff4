#include "plascap/adapters/bullet_plastic_solver.hpp"

#include <algorithm>
#include <cmath>
#include <typeinfo>

#include "plascap/adapters/bullet_plastic_constraint.hpp"

namespace plascap {
namespace {

// The class is final, so its exact type identifies it (cheaper than a dynamic_cast).
BulletPlasticConstraint* plascap_constraint(btTypedConstraint* constraint) {
    if (constraint->getConstraintType() != MAX_CONSTRAINT_TYPE || typeid(*constraint) != typeid(BulletPlasticConstraint))
        return nullptr;
    return static_cast<BulletPlasticConstraint*>(constraint);
}

// The push iterations stop once no row's push changes its rate by more than this [m/s | rad/s]:
// a micrometre per second; what is left is corrected the next step.
constexpr btScalar kPushConverged = 1e-6;

// One projected Gauss–Seidel step of a row's push (as Bullet's resolveSplitPenetrationImpulse does
// for a contact), within what the row's bounds leave beside the force it carries (its warm start:
// the pushes run before the velocity iterations), so that a row at its capacity cannot push on top;
// returns |the push impulse's change| (times J·M⁻¹·Jᵀ, the change of the row's push rate).
btScalar resolve_push(btSolverBody& a, btSolverBody& b, btSolverConstraint& row) {
    btScalar delta = row.m_rhsPenetration;
    delta -= (row.m_contactNormal1.dot(a.internalGetPushVelocity()) + row.m_relpos1CrossNormal.dot(a.internalGetTurnVelocity()) +
              row.m_contactNormal2.dot(b.internalGetPushVelocity()) + row.m_relpos2CrossNormal.dot(b.internalGetTurnVelocity())) *
             row.m_jacDiagABInv;
    const btScalar lower = std::min<btScalar>(0, row.m_lowerLimit - row.m_appliedImpulse);
    const btScalar upper = std::max<btScalar>(0, row.m_upperLimit - row.m_appliedImpulse);
    const btScalar sum = std::clamp<btScalar>(row.m_appliedPushImpulse + delta, lower, upper);
    delta = sum - row.m_appliedPushImpulse;
    row.m_appliedPushImpulse = sum;
    a.internalApplyPushImpulse(row.m_contactNormal1 * a.internalGetInvMass(), row.m_angularComponentA, delta);
    b.internalApplyPushImpulse(row.m_contactNormal2 * b.internalGetInvMass(), row.m_angularComponentB, delta);
    return std::abs(delta);
}

// Applies `impulse` along the row to both bodies and books it as the row's, as
// resolveSingleConstraintRowGeneric applies an impulse.
void apply_row_impulse(btSolverConstraint& row, btSolverBody& a, btSolverBody& b, btScalar impulse) {
    row.m_appliedImpulse = impulse;
    a.internalApplyImpulse(row.m_contactNormal1 * a.internalGetInvMass(), row.m_angularComponentA, impulse);
    b.internalApplyImpulse(row.m_contactNormal2 * b.internalGetInvMass(), row.m_angularComponentB, impulse);
}

// One body's share of a row's J·M⁻¹·Jᵀ, added to `sum` as Bullet's convertJoint sums it for its
// jacDiagABInv; returns M⁻¹ on the row's angular part, as its m_angularComponentA/B.
btVector3 add_share(btScalar& sum, const btRigidBody& body, const btVector3& linear, const btVector3& angular) {
    const btVector3 turn = body.getInvInertiaTensorWorld() * angular;
    sum += linear.dot(linear) * body.getInvMass() + angular.dot(turn);
    return turn * body.getAngularFactor();
}

// A spring's force f over the step h, applied to both bodies as an impulse f·h along the row's
// Jacobian (as resolveSingleConstraintRowGeneric applies a row's impulse), and added to the joint's
// feedback as Bullet adds a row's (solveGroupCacheFriendlyFinish). Returns the row's effective mass
// 1/(J·M⁻¹·Jᵀ), NaN where J·M⁻¹·Jᵀ is below Bullet's epsilon.
double apply_push(btTypedConstraint& c, btSolverBody& a, btSolverBody& b, const BulletPlasticConstraint::RowJacobian& j,
                  double force, btScalar h) {
    btScalar sum = 0.0;
    const btVector3 turn_a = add_share(sum, c.getRigidBodyA(), -j.linear, j.angular_a);
    const btVector3 turn_b = add_share(sum, c.getRigidBodyB(), j.linear, j.angular_b);
    const btScalar impulse = force * h;
    a.internalApplyImpulse(-j.linear * a.internalGetInvMass(), turn_a, impulse);
    b.internalApplyImpulse(j.linear * b.internalGetInvMass(), turn_b, impulse);
    if (btJointFeedback* fb = c.getJointFeedback()) {
        fb->m_appliedForceBodyA += -j.linear * c.getRigidBodyA().getLinearFactor() * force;
        fb->m_appliedTorqueBodyA += j.angular_a * c.getRigidBodyA().getAngularFactor() * force;
        fb->m_appliedForceBodyB += j.linear * c.getRigidBodyB().getLinearFactor() * force;
        fb->m_appliedTorqueBodyB += j.angular_b * c.getRigidBodyB().getAngularFactor() * force;
    }
    return sum > SIMD_EPSILON ? 1.0 / sum : NAN;
}

}  // namespace

template <class Act>
void BulletPlasticSolver::for_each_row(Act&& act) {
    for (const PlascapRows& joint : joints_) {
        for (int k = 0; k < joint.count; ++k)
            act(*joint.constraint, static_cast<std::size_t>(k), m_tmpSolverNonContactConstraintPool[joint.first + k]);
    }
}

void BulletPlasticSolver::convertJoints(btTypedConstraint** constraints, int count, const btContactSolverInfo& info) {
    joints_.clear();
    for (int i = 0; i < count; ++i) {
        // A disabled constraint has no rows (Bullet asks it for none), and its springs no force.
        BulletPlasticConstraint* c = plascap_constraint(constraints[i]);
        if (c != nullptr && c->isEnabled()) {
            c->split_corrections(info.m_splitImpulse != 0);  // before Bullet's getInfo2 writes the rows
            joints_.push_back({c, i, 0, 0});
        }
    }
    btSequentialImpulseConstraintSolver::convertJoints(constraints, count, info);
    // Each constraint's rows follow those of every constraint before it in the list.
    int at = 0;
    auto next = joints_.begin();
    for (int i = 0; i < count && next != joints_.end(); ++i) {
        const int rows = m_tmpConstraintSizesPool[i].m_numConstraintRows;
        if (i == next->index) {
            next->first = at, next->count = rows;
            ++next;
        }
        at += rows;
    }
    largest_correction_ = 0.0;
    // One pass over the joints: each one's springs, then its rows, while its state is in the cache.
    for (const PlascapRows& joint : joints_) {
        apply_pushes(*joint.constraint, info);
        for (int k = 0; k < joint.count; ++k)
            set_up_row(*joint.constraint, static_cast<std::size_t>(k), m_tmpSolverNonContactConstraintPool[joint.first + k], info);
    }
}

void BulletPlasticSolver::apply_pushes(BulletPlasticConstraint& c, const btContactSolverInfo& info) {
    btSolverBody* a = nullptr;  // looked up once a joint, at its first spring
    btSolverBody* b = nullptr;
    c.apply_pushes([&](const BulletPlasticConstraint::RowJacobian& j, double force) {
        if (a == nullptr) {
            a = &m_tmpSolverBodyPool[getOrInitSolverBody(c.getRigidBodyA(), info.m_timeStep)];
            b = &m_tmpSolverBodyPool[getOrInitSolverBody(c.getRigidBodyB(), info.m_timeStep)];
        }
        return apply_push(c, *a, *b, j, force, info.m_timeStep);
    });
}

void BulletPlasticSolver::set_up_row(BulletPlasticConstraint& c, std::size_t k, btSolverConstraint& row, const btContactSolverInfo& info) {
    // Bullet's jacDiagABInv is the row's effective mass 1/(J·M⁻¹·Jᵀ) (0 when J·M⁻¹·Jᵀ is below
    // its epsilon: not known then).
    c.note_row_mass(k, row.m_jacDiagABInv > 0.0 ? row.m_jacDiagABInv : NAN);
    if (info.m_splitImpulse) {
        const double rate = c.correction_rate(k);
        row.m_rhsPenetration = rate * row.m_jacDiagABInv;
        largest_correction_ = std::max(largest_correction_, std::abs(rate));
    }
    // The warm start, as resolveSingleConstraintRowGeneric applies an impulse.
    const btScalar impulse = std::clamp<btScalar>(c.carried_force(k) * info.m_timeStep, row.m_lowerLimit, row.m_upperLimit);
    if (impulse == 0.0) return;
    apply_row_impulse(row, m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], impulse);
}

void BulletPlasticSolver::solveGroupCacheFriendlySplitImpulseIterations(
    btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds, int manifold_count,
    btTypedConstraint** constraints, int constraint_count, const btContactSolverInfo& info, btIDebugDraw* drawer) {
    btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySplitImpulseIterations(
        bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, drawer);
    // Bullet pushes only contacts here; with none, and no correction of ours, no body moves.
    pushed_ = info.m_splitImpulse && (manifold_count > 0 || largest_correction_ >= kPushConverged);
    if (!info.m_splitImpulse || largest_correction_ < kPushConverged) return;  // nothing to correct
    // push_iterations(info), or fewer once converged (a structure at rest needs none: its
    // corrections are nil).
    for (int iteration = 0; iteration < push_iterations(info); ++iteration) {
        btScalar largest = 0.0;  // of the impulse changes over the effective masses: rate changes
        for_each_row([&](BulletPlasticConstraint&, std::size_t, btSolverConstraint& row) {
            const btScalar change = resolve_push(m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
            if (row.m_jacDiagABInv > 0.0) largest = std::max(largest, change / row.m_jacDiagABInv);
        });
        if (largest < kPushConverged) break;
    }
}

btScalar BulletPlasticSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int count,
                                                             const btContactSolverInfo& info) {
    const btScalar per_second = 1.0 / info.m_timeStep;  // impulse over the step → force
    const bool pushed = pushed_ && info.m_splitImpulse;
    pushed_ = false;
    for_each_row([&](BulletPlasticConstraint& c, std::size_t k, btSolverConstraint& row) {
        c.carry_force(k, row.m_appliedImpulse * per_second);
        if (!pushed) {
            c.carry_push(k, 0.0);  // no push ran: no body moved but by its velocity
            return;
        }
        // The pushes move each body by v_push·h and turn it by ω_turn·turnErp·h (as Bullet
        // integrates them): the row's Jacobian on that is the motion they made along it.
        const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
        const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
        const btScalar rate = row.m_contactNormal1.dot(a.m_pushVelocity) + row.m_contactNormal2.dot(b.m_pushVelocity) +
                              (row.m_relpos1CrossNormal.dot(a.m_turnVelocity) + row.m_relpos2CrossNormal.dot(b.m_turnVelocity)) *
                                  info.m_splitImpulseTurnErp;
        c.carry_push(k, rate * info.m_timeStep);
    });
    if (info.m_splitImpulse) {
        // A push moves a body by δ = v_push·h (and turns it by ω_turn·turnErp·h, as Bullet integrates
        // it) without a velocity: the forces on it do F·δ of work that no row did.
        for (int i = 0; i < m_tmpSolverBodyPool.size(); ++i) {
            const btSolverBody& body = m_tmpSolverBodyPool[i];
            if (body.m_originalBody == nullptr) continue;
            const btVector3 shift = body.m_pushVelocity * info.m_timeStep;
            const btVector3 turn = body.m_turnVelocity * (info.m_splitImpulseTurnErp * info.m_timeStep);
            correction_work_ -= body.m_originalBody->getTotalForce().dot(shift) + body.m_originalBody->getTotalTorque().dot(turn);
        }
    }
    return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, count, info);
}

}  // namespace plascap
