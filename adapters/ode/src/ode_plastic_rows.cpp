#include "ode_plastic_rows.hpp"

#include "plascap/adapters/prefetch.hpp"

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

void OdePlasticRows::set_geometry(const JointFrameState& state) {
    dxBody* b = node[0].body;  // ODE's first body
    dxBody* a = node[1].body;  // 0: the world
    axes_ = state.axes;
    lever_b_ = difference(state.axes.anchor, centre_of(b));
    lever_a_ = a ? difference(state.axes.anchor, centre_of(a)) : Vec3{};
}

void OdePlasticRows::count_rows() {
    count_ = 0;
    all_unbounded_ = true;
    for (std::size_t i = 0; i < kDofCount; ++i) {
        if (!has_row(i)) continue;
        ++count_;
        all_unbounded_ = all_unbounded_ && targets_[i].lower == -dInfinity && targets_[i].upper == dInfinity;
    }
}

void OdePlasticRows::getInfo1(Info1* info) {
    info->m = count_;
    info->nub = all_unbounded_ ? count_ : 0;  // ODE solves a joint of only unbounded rows apart
}

void OdePlasticRows::getSureMaxInfo(SureMaxInfo* info) { info->max_m = 6; }

void OdePlasticRows::load_next_joint() const {
    // `next` may be any of ODE's joints, and smaller than this one: lines past its end are loaded
    // for nothing, and a prefetch never faults.
    if (next) prefetch_bytes<sizeof(OdePlasticRows), PrefetchFor::Reading>(next);
}

void OdePlasticRows::getInfo2(dReal, dReal, int rowskip, dReal* J1, dReal* J2, int pairskip, dReal* pairRhsCfm,
                              dReal* pairLoHi, int*) {
    using namespace ode_joint_object;
    load_next_joint();
    int r = 0;
    for (std::size_t i = 0; i < targets_.size(); ++i) {
        if (!has_row(i)) continue;
        dReal* on_b = J1 + r * rowskip;
        dReal* on_a = J2 ? J2 + r * rowskip : nullptr;  // ODE zeroed both
        // +J on b, −J on a (plascap's Bullet constraint writes the same rows).
        if (i < 3) {
            const Vec3& axis = axes_.translation[i];
            const Vec3 moment_b = cross(lever_b_, axis);
            store(on_b + dDA_LX, axis);
            store(on_b + dDA_AX, moment_b);
            if (on_a) {
                const Vec3 moment_a = cross(lever_a_, axis);
                store(on_a + dDA_LX, {-axis[0], -axis[1], -axis[2]});
                store(on_a + dDA_AX, {-moment_a[0], -moment_a[1], -moment_a[2]});
            }
        } else {
            const Vec3& gradient = axes_.rotation[i - 3];
            store(on_b + dDA_AX, gradient);
            if (on_a) store(on_a + dDA_AX, {-gradient[0], -gradient[1], -gradient[2]});
        }
        pairRhsCfm[r * pairskip + kRhs] = targets_[i].rate;
        pairLoHi[r * pairskip + kLo] = targets_[i].lower;
        pairLoHi[r * pairskip + kHi] = targets_[i].upper;
        ++r;
    }
}

}  // namespace plascap
