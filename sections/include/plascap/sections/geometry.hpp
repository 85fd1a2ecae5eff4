#pragma once
// Cross-section geometry as users give it. Coordinates are [x, z] in metres; the section lies
// in the x-z plane and the joint (beam) axis is y (paper Fig. 2.2; docs/section-format.md).
#include <optional>
#include <vector>

#include "plascap/materials/material.hpp"
#include "plascap/materials/shear_criterion.hpp"

namespace plascap {

struct Point {
    double x = 0.0;  // [m]
    double z = 0.0;  // [m]
};

// A closed polygon, either orientation; a closing vertex equal to the first is allowed.
using Ring = std::vector<Point>;

// A reinforcement bar as a point area (reinforced concrete): its area is taken out of the part's
// material and carried by its own.
struct Bar {
    Point at;           // centre [m]
    double area = 0.0;  // cross-section area [m²]
    Material material;
};

// One connected piece of material: an outer ring with holes strictly inside it, and bars.
struct Part {
    Ring outer;
    std::vector<Ring> holes;
    Material material;
    std::vector<Bar> bars = {};
};

struct Section {
    std::vector<Part> parts;                  // interiors must not overlap (a shared edge is fine)
    // τy = fy/2 or fy/√3 (eq. 2.11). Unset: the criterion every part's material names, when they
    // all name the same one, else Tresca (the paper's).
    std::optional<ShearCriterion> shear;
    std::optional<Point> reference;           // joint point for My; default: area centroid
};

}  // namespace plascap
