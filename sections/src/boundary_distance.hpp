#pragma once
// The sand heap's height function over one part (plastic_torsion.cpp):
//   φ(p) = min over the part's rings k of (offset_k + d(p, ring k)),
// offset 0 for the outer ring and the hole's plateau for each hole. The rings' edges sit in a
// Boost.Geometry R-tree; the nearest-edge query visits edges by increasing distance and stops as
// soon as no farther edge can lower φ (every offset is >= 0), so an evaluation costs O(log n)
// for an n-edge part instead of O(n).
#include <memory>
#include <vector>

#include "plascap/sections/geometry.hpp"

namespace plascap::detail {

class BoundaryDistance {
public:
    // offsets[k] for hole k; the outer ring's offset is 0.
    BoundaryDistance(const Part& part, const std::vector<double>& hole_offsets);
    ~BoundaryDistance();
    BoundaryDistance(BoundaryDistance&&) noexcept;

    double operator()(Point p) const;

private:
    struct Index;
    std::unique_ptr<Index> index_;
};

}  // namespace plascap::detail
