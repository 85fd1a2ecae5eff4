#pragma once
// A section that passed validation. Only validate_section() makes one, so every integral
// routine may rely on its invariants:
//   - every ring has >= 3 vertices, no closing duplicate, finite coordinates, non-vanishing area;
//   - rings are simple, outer rings counter-clockwise and holes clockwise (in x-z);
//   - holes lie strictly inside their outer ring and apart from each other; parts do not overlap;
//   - coordinates are stored relative to local_origin() (the bounding-box centre), which keeps
//     the integrals accurate for sections far from the origin.
#include <cstddef>
#include <optional>
#include <vector>

#include "plascap/sections/geometry.hpp"
#include "plascap/sections/ring_integrals.hpp"

namespace plascap {

class ValidSection {
public:
    const std::vector<Part>& parts() const { return parts_; }  // in local coordinates
    // Area and first moments of each part (local coordinates; outer ring less its holes, bars not
    // counted), computed once here for every integral that needs them.
    const std::vector<RingMoments>& part_moments() const { return part_moments_; }
    // The box around each part's outer ring (local coordinates), for the bending axes' search range.
    const std::vector<RingExtent>& part_extents() const { return part_extents_; }
    Point local_origin() const { return origin_; }              // section coordinates of local (0, 0)
    ShearCriterion shear() const { return shear_; }
    const std::optional<Point>& reference() const { return reference_; }  // section coordinates
    std::size_t vertex_count() const;

    Point to_local(Point p) const { return {p.x - origin_.x, p.z - origin_.z}; }
    Point to_section(Point p) const { return {p.x + origin_.x, p.z + origin_.z}; }

private:
    friend ValidSection validate_section(const Section& section);
    ValidSection() = default;

    std::vector<Part> parts_;
    std::vector<RingMoments> part_moments_;
    std::vector<RingExtent> part_extents_;
    Point origin_;
    ShearCriterion shear_ = ShearCriterion::Tresca;
    std::optional<Point> reference_;
};

// Checks every rule above and throws InputError with one message naming the problem and where
// it is ("part 0, hole 1, vertex 3: ..."). Uses CGAL's exact predicates for the topology.
ValidSection validate_section(const Section& section);

}  // namespace plascap
