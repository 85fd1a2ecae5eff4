// Callers ask for a subset and get exactly that, with the same numbers as the full set.
#include <gtest/gtest.h>

#include "plascap/input_error.hpp"
#include "plascap/sections/shapes.hpp"
#include "test_support.hpp"

using namespace plascap;

TEST(CapacitySubset, OnlyTheRequestedCapacitiesArePresent) {
    const Section s = rectangle_section(0.1, 0.3, 355e6);
    const Capacities all = test::capacities_of(s);
    const Capacities some = test::capacities_of(s, CapacitySet().insert(Capacity::N).insert(Capacity::Mx));
    ASSERT_TRUE(some.N && some.Mx);
    EXPECT_FALSE(some.Qx || some.Qz || some.Mz || some.My);
    EXPECT_FALSE(some.x_pna || some.reference);  // Mz's axis and My's joint point were never computed
    EXPECT_EQ(*some.N, *all.N);
    EXPECT_EQ(*some.Mx, *all.Mx);
    EXPECT_EQ(*some.z_pna, *all.z_pna);
}

TEST(CapacitySubset, ParsesCommaSeparatedNames) {
    const CapacitySet set = CapacitySet::parse("N, My");
    EXPECT_TRUE(set.contains(Capacity::N));
    EXPECT_TRUE(set.contains(Capacity::My));
    EXPECT_FALSE(set.contains(Capacity::Mx));
    try {
        CapacitySet::parse("N,Mq");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "unknown capacity 'Mq' (choose from N, Qx, Qz, Mx, Mz, My, N_neg, Mx_neg, Mz_neg)");
    }
}
