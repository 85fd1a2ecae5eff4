#include "ode_plastic_rows.hpp"

namespace plascap {
namespace {

Vec3 centre_of(dBodyID body) {
    const dReal* x = dBodyGetPosition(body);
    return {x[0], x[1], x[2]};
}

void store(dReal* at, const Vec3& v) {
    at[0] = v[0], at[1] = v[1], at[2] = v[2];
}

}  // namespace

OdePlasticRows* OdePlasticRows::create(dWorldID world, dBodyID b, dBodyID a) {
    auto* joint = new OdePlasticRows(world);  // dBase's operator new: ODE's allocator, as dJointDestroy frees
    dJointAttach(joint, b, a);                // b first: ODE's J1, f1 and t1 are b's
    return joint;
}

void OdePlasticRows::set_rows(const JointFrameState& state, const PerDof<std::optional<OdeRowTarget>>& targets) {
    dxBody* b = node[0].body;  // ODE's first body
    dxBody* a = node[1].body;  // 0: the world
    const Vec3 lever_b = difference(state.axes.anchor, centre_of(b));
    const Vec3 lever_a = a ? difference(state.axes.anchor, centre_of(a)) : Vec3{};
    count_ = 0;
    all_unbounded_ = true;
    for (std::size_t i = 0; i < targets.size(); ++i) {
        if (!targets[i]) continue;
        Row& row = rows_[count_++];
        // +J on b, −J on a (plascap's Bullet constraint writes the same rows).
        if (i < 3) {
            const Vec3& axis = state.axes.translation[i];
            store(row.on_b, axis);
            store(row.on_b + 3, cross(lever_b, axis));
            store(row.on_a, {-axis[0], -axis[1], -axis[2]});
            const Vec3 moment_a = cross(lever_a, axis);
            store(row.on_a + 3, {-moment_a[0], -moment_a[1], -moment_a[2]});
        } else {
            const Vec3& gradient = state.axes.rotation[i - 3];
            store(row.on_b, {});
            store(row.on_b + 3, gradient);
            store(row.on_a, {});
            store(row.on_a + 3, {-gradient[0], -gradient[1], -gradient[2]});
        }
        row.rate = targets[i]->rate;
        row.lower = targets[i]->lower;
        row.upper = targets[i]->upper;
        all_unbounded_ = all_unbounded_ && row.lower == -dInfinity && row.upper == dInfinity;
    }
}

void OdePlasticRows::getInfo1(Info1* info) {
    info->m = count_;
    info->nub = all_unbounded_ ? count_ : 0;  // ODE solves a joint of only unbounded rows apart
}

void OdePlasticRows::getSureMaxInfo(SureMaxInfo* info) { info->max_m = 6; }

void OdePlasticRows::getInfo2(dReal, dReal, int rowskip, dReal* J1, dReal* J2, int pairskip, dReal* pairRhsCfm,
                              dReal* pairLoHi, int*) {
    using namespace ode_joint_object;
    for (int r = 0; r < count_; ++r) {
        const Row& row = rows_[static_cast<std::size_t>(r)];
        for (int k = 0; k < 3; ++k) {
            J1[r * rowskip + dDA_LX + k] = row.on_b[k];
            J1[r * rowskip + dDA_AX + k] = row.on_b[3 + k];
        }
        if (J2) {
            for (int k = 0; k < 3; ++k) {
                J2[r * rowskip + dDA_LX + k] = row.on_a[k];
                J2[r * rowskip + dDA_AX + k] = row.on_a[3 + k];
            }
        }
        pairRhsCfm[r * pairskip + kRhs] = row.rate;
        pairLoHi[r * pairskip + kLo] = row.lower;
        pairLoHi[r * pairskip + kHi] = row.upper;
    }
}

}  // namespace plascap
