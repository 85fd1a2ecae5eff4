#include "ode_world_bodies.hpp"

namespace plascap {

OdeWorldBodies::OdeWorldBodies(dWorldID world) {
    // ODE links a new object in at the head of its world's list: its tome is the head.
    const dBodyID probe = dBodyCreate(world);
    head_ = reinterpret_cast<dObject*>(probe)->tome;
    dBodyDestroy(probe);
}

const std::vector<dBodyID>& OdeWorldBodies::list() {
    bodies_.clear();
    for (dObject* body = *head_; body; body = body->next) bodies_.push_back(reinterpret_cast<dBodyID>(body));
    return bodies_;
}

}  // namespace plascap
