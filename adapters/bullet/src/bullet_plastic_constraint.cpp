#include "plascap/adapters/bullet_plastic_constraint.hpp"

#include <cmath>

#include "plascap/adapters/bullet_vec3.hpp"
#include "plascap/adapters/swing_twist.hpp"

namespace plascap {
namespace {

constexpr double kTurn = 2.0 * 3.14159265358979323846;  // [rad]

void store(btScalar* at, const btVector3& v) {
    at[0] = v.x(), at[1] = v.y(), at[2] = v.z();
}

}  // namespace

BulletPlasticConstraint::BulletPlasticConstraint(btRigidBody* a, btRigidBody& b, const btTransform& frame_in_world)
    : btTypedConstraint(MAX_CONSTRAINT_TYPE, a ? *a : getFixedBody(), b),
      frame_in_a_(m_rbA.getCenterOfMassTransform().inverse() * frame_in_world),
      frame_in_b_(b.getCenterOfMassTransform().inverse() * frame_in_world) {}

void BulletPlasticConstraint::set_kind(std::size_t i, RowKind kind) {
    if (rows_[i].kind == kind) return;  // a plastic dof's every step: nothing to count
    row_count_ += int(emits_row(kind)) - int(emits_row(rows_[i].kind));
    push_count_ += int(kind == RowKind::Push) - int(rows_[i].kind == RowKind::Push);
    rows_[i].kind = kind;
}

void BulletPlasticConstraint::free_row(std::size_t i) {
    set_kind(i, RowKind::None);
    rows_[i] = {};
}

void BulletPlasticConstraint::lock_row(std::size_t i, double at) {
    set_kind(i, RowKind::Lock);
    rows_[i].target = at;
}

void BulletPlasticConstraint::command_row(std::size_t i, const RowCommand& c) {
    Row& row = rows_[i];  // keeps the force it carried, for the warm start
    if (c.kind == RowCommand::Kind::Hold) {
        set_kind(i, RowKind::Hold);
        row.target = c.velocity, row.lower = c.lower, row.upper = c.upper;
    } else {
        set_kind(i, RowKind::Push);
        row.target = 0.0, row.lower = c.force, row.upper = c.force;
    }
}

BulletPlasticConstraint::Levers BulletPlasticConstraint::levers(const JointFrameState& s) const {
    const btVector3 anchor = to_bt(s.axes.anchor);
    return {anchor - m_rbA.getCenterOfMassPosition(), anchor - m_rbB.getCenterOfMassPosition()};
}

BulletPlasticConstraint::RowJacobian BulletPlasticConstraint::jacobian(const JointFrameState& s, const Levers& levers, std::size_t i) {
    // J·v = the dof's rate: +axis on b, −axis on a; a translation row acts at b's anchor.
    if (i < 3) {
        const btVector3 axis = to_bt(s.axes.translation[i]);
        return {axis, -levers.a.cross(axis), levers.b.cross(axis)};
    }
    const btVector3 axis = to_bt(s.axes.rotation[i - 3]);
    return {btVector3(0, 0, 0), -axis, axis};
}

const JointFrameState& BulletPlasticConstraint::measure() {
    const btTransform& a = m_rbA.getCenterOfMassTransform();
    const btTransform& b = m_rbB.getCenterOfMassTransform();
    if (measured_ && a == measured_a_ && b == measured_b_) return state_;
    measured_a_ = a, measured_b_ = b, measured_ = true;
    state_ = measure_joint_swing_twist(to_pose(a * frame_in_a_), to_pose(b * frame_in_b_));
    return state_;
}

void BulletPlasticConstraint::getInfo1(btConstraintInfo1* info) {
    info->m_numConstraintRows = row_count_;
    info->nub = 0;
}

void BulletPlasticConstraint::getInfo2(btConstraintInfo2* info) {
    const JointFrameState& s = measure();
    const Levers at_anchor = levers(s);
    const btScalar erp = stop_erp_ >= 0.0 ? stop_erp_ : info->erp;
    const btScalar step = 1.0 / info->fps;  // bounds are impulses over the step: one division, not two a row
    int r = 0;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
        Row& row = rows_[i];
        if (!emits_row(row.kind)) continue;
        const int at = r * info->rowskip;  // the Jacobians' and the row scalars' stride
        const RowJacobian j = jacobian(s, at_anchor, i);
        if (i < 3) {  // Bullet's rows start zeroed: a rotation row has no linear part
            store(info->m_J1linearAxis + at, -j.linear);
            store(info->m_J2linearAxis + at, j.linear);
        }
        store(info->m_J1angularAxis + at, j.angular_a);
        store(info->m_J2angularAxis + at, j.angular_b);
        // Lock and Hold rows hold a rate of 0 but for their position correction (a Hold row's rate
        // from the law is all correction); a Hold row is bounded by its force range, as impulses
        // over the step.
        if (row.kind == RowKind::Lock) {
            const double error = row.target - s.positions[i];
            row.correction = erp * info->fps * (i >= 3 ? std::remainder(error, kTurn) : error);  // angles: the short way
            info->cfm[at] = stop_cfm_;
        } else {
            row.correction = row.target;
            info->m_lowerLimit[at] = row.lower * step;
            info->m_upperLimit[at] = row.upper * step;
        }
        info->m_constraintError[at] = split_corrections_ ? 0.0 : row.correction;
        written_dof_[static_cast<std::size_t>(r)] = i;
        ++r;
    }
    written_ = static_cast<std::size_t>(r);
}

void BulletPlasticConstraint::setParam(int num, btScalar value, int) {
    if (num == BT_CONSTRAINT_STOP_ERP || num == BT_CONSTRAINT_ERP) stop_erp_ = value;
    if (num == BT_CONSTRAINT_STOP_CFM || num == BT_CONSTRAINT_CFM) stop_cfm_ = value;
}

btScalar BulletPlasticConstraint::getParam(int num, int) const {
    if (num == BT_CONSTRAINT_STOP_ERP || num == BT_CONSTRAINT_ERP) return stop_erp_;
    if (num == BT_CONSTRAINT_STOP_CFM || num == BT_CONSTRAINT_CFM) return stop_cfm_;
    return 0.0;
}

}  // namespace plascap
