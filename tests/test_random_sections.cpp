// Property tests over random star-shaped polygons, single and in groups, some snapped to a grid so
// that many vertices share a level (horizontal edges, axes through vertices): the neutral axis
// must balance the yield force to round-off, be the minimiser of ∫fy·|level − t| dA, and the
// capacities must be finite and positive.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "plascap/sections/plastic_bending.hpp"
#include "test_support.hpp"

using namespace plascap;
using plascap::test::random_star;

namespace {

// ∫ s·|level − t| dA from the clipped first moments, s = fy on the tension side and fc on the other.
double absolute_moment(const ValidSection& s, BendingAxis axis, TensionSide tension, double t) {
    double m = 0.0;
    for (const Part& part : s.parts()) {
        const double fy = part.material.fy, fc = part.material.compression_strength();
        const double below = tension == TensionSide::Below ? fy : fc, above = tension == TensionSide::Below ? fc : fy;
        m += above * half_plane_moments(part.outer, axis, t, Side::Above).first_moment -
             below * half_plane_moments(part.outer, axis, t, Side::Below).first_moment;
    }
    return m;
}

}  // namespace

TEST(RandomSections, NeutralAxisBalancesAndMinimises) {
    std::mt19937 rng(20261124);
    std::uniform_real_distribution<double> fy(100e6, 500e6);
    int accepted = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const bool snap = trial % 2 == 1;
        const int parts = 1 + trial % 3;
        Section s;
        for (int p = 0; p < parts; ++p) {
            s.parts.push_back(test::part(random_star(rng, {3.0 * p, 1.5 * (p % 2)}, 1.0, snap), fy(rng)));
            if (trial % 4 >= 2) s.parts.back().material.fc = fy(rng);  // different in compression
        }
        std::optional<ValidSection> valid;
        try {
            valid.emplace(validate_section(s));
        } catch (const std::exception&) {
            continue;  // snapping can make a ring degenerate; those are the validator's business
        }
        ++accepted;
        const Capacities c = compute_capacities(*valid);
        for (Capacity k : kAllCapacities) {
            ASSERT_TRUE(std::isfinite(*c.get(k)) && *c.get(k) > 0.0) << trial << " " << to_string(k);
        }
        for (BendingAxis axis : {BendingAxis::X, BendingAxis::Z})
            for (TensionSide tension : {TensionSide::Below, TensionSide::Above}) {
                const PlasticBending bending = plastic_bending(*valid, axis, tension);
                const double t = bending.axis;
                const double below = yield_force(*valid, axis, tension, t, Side::Below);
                const double above = yield_force(*valid, axis, tension, t, Side::Above);
                ASSERT_LE(std::fabs(below - above), 1e-12 * (below + above)) << "trial " << trial;
                const double at_axis = absolute_moment(*valid, axis, tension, t);
                ASSERT_LE(std::fabs(bending.moment - at_axis), 1e-12 * at_axis) << "trial " << trial;
                for (double shift : {-1e-3, 1e-3, -0.1, 0.1})
                    ASSERT_GE(absolute_moment(*valid, axis, tension, t + shift) * (1.0 + 1e-13), at_axis)
                        << "trial " << trial;
            }
    }
    EXPECT_GT(accepted, 300);
}
