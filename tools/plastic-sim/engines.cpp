#include "plascap/input_error.hpp"
#include "scene_engine.hpp"

namespace plascap {

#ifdef PLASCAP_HAVE_BULLET
enum class BulletConstraint { Plascap, Spring2, Spring };
std::unique_ptr<SceneEngine> make_bullet_scene(const Scene& scene, BulletConstraint constraint);
#endif

#ifdef PLASCAP_HAVE_ODE
std::unique_ptr<SceneEngine> make_ode_scene(const Scene& scene, bool quick);
#endif

std::vector<std::string> available_engines() {
    std::vector<std::string> names;
#ifdef PLASCAP_HAVE_BULLET
    names.push_back("bullet");              // plascap::BulletPlasticConstraint
    names.push_back("bullet-spring2");      // btGeneric6DofSpring2Constraint, driven from outside
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
    if (name == "bullet") return make_bullet_scene(scene, BulletConstraint::Plascap);
    if (name == "bullet-spring2") return make_bullet_scene(scene, BulletConstraint::Spring2);
    if (name == "bullet-6dof-spring") return make_bullet_scene(scene, BulletConstraint::Spring);
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
