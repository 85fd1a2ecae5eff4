#pragma once
// ODE 0.16's joint object, declared as libode (Debian's libode8, 0.16.x) lays it out, so that
// plascap can add its own joint type (ode_plastic_rows.hpp). ODE's public API has no joint whose
// bounded rows act at an arbitrary anchor (its LMotor, slider, piston and PU motors act at the
// bodies' centres), and ODE installs no header for its joint classes; it does export them: the
// base constructor and destructor, `vtable for dxJoint` and `typeinfo for dxJoint`. A joint is a
// C++ object whose virtual functions ODE's steppers call: getInfo1 (how many rows), getInfo2 (the
// rows), getSureMaxInfo (at most how many), type and size. This is ODE's internal interface, not
// its API: adapters/CMakeLists.txt builds the adapter only against ODE 0.16, and
// tests/test_ode_joint_object.cpp checks this layout against the library itself (the size of
// ODE's own null joint, the places where ODE keeps a joint's world, bodies and feedback, and the
// order of the virtual functions).
//
// Layout (x86-64, double precision): the vtable pointer; dObject's world, next, tome, tag and
// userdata; dxJoint's flags, two nodes (joint, body, next), feedback and lambda[6]: 160 bytes.
#include <ode/ode.h>

#include <cstddef>
#include <cstdint>

// dBase: ODE allocates and frees its objects with dAlloc and dFree (ODE's memory.h).
struct dBase {
    void* operator new(std::size_t size) { return dAlloc(size); }
    void operator delete(void* p, std::size_t size) { dFree(p, size); }
};

// dxJoint's constructor (in libode) initialises these; plascap never constructs a dObject itself.
struct dObject : dBase {
    virtual ~dObject();  // exported by libode

    dxWorld* world;
    dObject* next;
    dObject** tome;
    int tag;
    void* userdata;
};

// A joint's link in its body's list of joints.
struct dxJointNode {
    dxJoint* joint;
    dxBody* body;
    dxJointNode* next;
};

struct dxJoint : dObject {
    struct Info1 {
        std::uint8_t m;    // rows this step
        std::uint8_t nub;  // of which the first nub are unbounded
    };
    struct SureMaxInfo {
        std::uint8_t max_m;  // the most rows getInfo1 can ever give
    };

    unsigned flags;
    dxJointNode node[2];
    dJointFeedback* feedback;
    dReal lambda[6];

    explicit dxJoint(dxWorld* w);  // exported: links the joint into w's list
    ~dxJoint() override;           // exported

    virtual void getInfo1(Info1* info) = 0;
    // Row i's Jacobian on the first body is J1 + i·rowskip (linear part at dDA_LX.., angular at
    // dDA_AX..), on the second J2 + i·rowskip (J2 is null without a second body); its right-hand
    // side and CFM are pairRhsCfm[i·pairskip + 0, 1], its force bounds pairLoHi[i·pairskip + 0, 1].
    // ODE zeroes J, the right-hand sides, sets CFM to the world's and the bounds to ∓dInfinity,
    // and findex to −1 before the call.
    virtual void getInfo2(dReal worldFPS, dReal worldERP, int rowskip, dReal* J1, dReal* J2, int pairskip,
                          dReal* pairRhsCfm, dReal* pairLoHi, int* findex) = 0;
    virtual void getSureMaxInfo(SureMaxInfo* info) = 0;
    virtual dJointType type() const = 0;
    virtual std::size_t size() const = 0;
    virtual void setRelativeValues();  // exported

    bool isEnabled() const;  // exported
};

namespace plascap::ode_joint_object {
// Where ODE's row arrays keep each value (ODE's joint.h: GI2_RHS, GI2_CFM, GI2_LO, GI2_HI).
constexpr int kRhs = 0, kCfm = 1, kLo = 0, kHi = 1;
constexpr std::size_t kSize = 160;  // sizeof(dxJoint) in libode 0.16, x86-64
}  // namespace plascap::ode_joint_object

static_assert(sizeof(dxJoint) == plascap::ode_joint_object::kSize, "dxJoint must be laid out as libode 0.16's");
