#include <gtest/gtest.h>

#include <cmath>

#include "plascap/input_error.hpp"
#include "plascap/materials/material.hpp"
#include "plascap/materials/shear_criterion.hpp"

using namespace plascap;

// Paper, text after eq. 2.14: Tresca τy = 0.5 fy, von Mises τy = fy/√3 (≈ 0.577 fy).
TEST(ShearCriterion, TrescaIsHalfTheYieldStress) {
    EXPECT_DOUBLE_EQ(shear_yield_stress(200e6, ShearCriterion::Tresca), 100e6);
}

TEST(ShearCriterion, VonMisesIsYieldStressOverRootThree) {
    EXPECT_NEAR(shear_yield_stress(355e6, ShearCriterion::VonMises), 204959345.56, 0.01);  // 355e6/1.7320508076
}

TEST(ShearCriterion, ParsesNamesAndRejectsOthers) {
    EXPECT_EQ(parse_shear_criterion("tresca"), ShearCriterion::Tresca);
    EXPECT_EQ(parse_shear_criterion("Von-Mises"), ShearCriterion::VonMises);
    EXPECT_EQ(parse_shear_criterion("von_mises"), ShearCriterion::VonMises);
    try {
        parse_shear_criterion("rankine");
        FAIL() << "accepted an unknown criterion";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown shear criterion 'rankine'"), std::string::npos) << e.what();
    }
}

TEST(Material, RejectsNegativeOrNonFiniteYieldStress) {
    for (double fy : {-200e6, std::nan(""), HUGE_VAL}) {
        try {
            validate_material(Material{"", fy}, "part 3, material");
            FAIL() << "accepted fy = " << fy;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("part 3, material: yield stress fy must be a finite number >= 0 in Pa"),
                      std::string::npos)
                << e.what();
        }
    }
    EXPECT_THROW(validate_material(Material{"", 0.0}, "x"), InputError);  // no strength at all
    EXPECT_NO_THROW(validate_material(Material{"", 1.0}, "x"));
    EXPECT_NO_THROW(validate_material(Material{"", 1e12}, "x"));
}

TEST(Material, RejectsYieldStressOutsideTheSupportedRange) {
    for (double fy : {5e-324, 0.5, 2e12}) {
        try {
            validate_material(Material{"", fy}, "part 0, material");
            FAIL() << "accepted fy = " << fy;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("Pa is outside the supported range 1 Pa to 1e12 Pa"), std::string::npos)
                << e.what();
        }
    }
}
