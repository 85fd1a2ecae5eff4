#include "plascap/input_error.hpp"
#include "scene_engine.hpp"

namespace plascap {

#ifdef PLASCAP_HAVE_BULLET
std::unique_ptr<SceneEngine> make_bullet_scene(const Scene& scene, bool first_spring_constraint);
#endif

#ifdef PLASCAP_HAVE_ODE
std::unique_ptr<SceneEngine> make_ode_scene(const Scene& scene, bool quick);
#endif

std::vector<std::string> available_engines() {
    std::vector<std::string> names;
#ifdef PLASCAP_HAVE_BULLET
    names.push_back("bullet");              // btGeneric6DofSpring2Constraint
    names.push_back("bullet-6dof-spring");  // btGeneric6DofSpringConstraint, the paper's first
#endif
#ifdef PLASCAP_HAVE_ODE
    names.push_back("ode");       // dWorldQuickStep
    names.push_back("ode-step");  // dWorldStep
#endif
    return names;
}

std::unique_ptr<SceneEngine> make_engine(const std::string& name, const Scene& scene) {
#ifdef PLASCAP_HAVE_BULLET
    if (name == "bullet") return make_bullet_scene(scene, false);
    if (name == "bullet-6dof-spring") return make_bullet_scene(scene, true);
#endif
#ifdef PLASCAP_HAVE_ODE
    if (name == "ode") return make_ode_scene(scene, true);
    if (name == "ode-step") return make_ode_scene(scene, false);
#endif
    std::string list;
    for (const std::string& n : available_engines()) list += (list.empty() ? "" : ", ") + n;
    if (name.rfind("bullet", 0) == 0 || name.rfind("ode", 0) == 0) {
        throw InputError("--engine " + name + ": this build has no " + name + " adapter (it has: " + list + ")");
    }
    throw InputError("--engine " + name + ": unknown engine (this build has: " + list + ")");
}

}  // namespace plascap
