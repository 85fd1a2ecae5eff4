#pragma once
// Test names for suites run on every engine: "bullet-6dof-spring" becomes "bullet_6dof_spring".
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace plascap::test {

inline std::string engine_test_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

}  // namespace plascap::test
