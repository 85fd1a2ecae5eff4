#include "plascap/adapters/flow_criterion.hpp"

namespace plascap {

bool FlowCriterion::flowed(double share, double stopping_share) {
    mean_share_ += kMeanShareWeight * (share - mean_share_);  // exponential moving mean
    last_share_ = share;
    const bool continues = flowing_ * share > 0.0;  // the step before flowed, on this side
    const bool sustained = std::abs(mean_share_) >= kConfirmedShare && mean_share_ * share > 0.0;
    const bool beyond_noise = stopping_share >= kBeyondNoise;
    flowing_ = at_bound() && (continues || sustained || beyond_noise) ? share : 0.0;
    return flowing_ != 0.0;
}

}  // namespace plascap
