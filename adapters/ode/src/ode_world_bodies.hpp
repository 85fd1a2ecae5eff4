#pragma once
// Every body of an ODE world. ODE 0.16's API lists a body's joints but not a world's bodies; the
// world keeps them in a list of its dObjects (ODE's objects.h: next, and tome, the place that
// points to the object — for the newest body, the world's own head of the list). A body made and
// destroyed at once shows where that head is (ode_joint_object.hpp has dObject's layout, which
// tests/test_ode_joint_object.cpp checks against libode).
#include <ode/ode.h>

#include <vector>

#include "ode_joint_object.hpp"

namespace plascap {

class OdeWorldBodies {
public:
    explicit OdeWorldBodies(dWorldID world);
    // The world's bodies now, newest first (ODE's order).
    const std::vector<dBodyID>& list();

private:
    dObject** head_;  // the world's head of its list of bodies
    std::vector<dBodyID> bodies_;
};

}  // namespace plascap
