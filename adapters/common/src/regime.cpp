#include "plascap/adapters/regime.hpp"

namespace plascap {

const char* regime_name(Regime regime) {
    switch (regime) {
        case Regime::RigidPlastic: return "rigid-plastic";
        case Regime::ElasticPlastic: return "elastic-plastic";
        case Regime::StiffRigidPlastic: return "stiff: rigid-plastic";
    }
    return "?";
}

}  // namespace plascap
