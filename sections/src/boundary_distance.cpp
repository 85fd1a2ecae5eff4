#include "boundary_distance.hpp"

// Boost 1.74's R-tree includes one of Boost's own deprecated headers, which would print a note in
// every build; the code here uses none of them.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <limits>

#include "planar_distance.hpp"

namespace plascap::detail {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

using BoostPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BoostSegment = bg::model::segment<BoostPoint>;
struct Edge {
    BoostSegment segment;
    Point a, b;
    double offset;
};
struct EdgeIndexable {
    using result_type = const BoostSegment&;
    const BoostSegment& operator()(const Edge& e) const { return e.segment; }
};

}  // namespace

struct BoundaryDistance::Index {
    bgi::rtree<Edge, bgi::rstar<16>, EdgeIndexable> tree;
};

BoundaryDistance::BoundaryDistance(const Part& part, const std::vector<double>& hole_offsets) : index_(new Index) {
    std::vector<Edge> edges;
    const auto add = [&edges](const Ring& ring, double offset) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
            const Point a = ring[i], b = ring[i + 1 == n ? 0 : i + 1];
            edges.push_back({BoostSegment(BoostPoint(a.x, a.z), BoostPoint(b.x, b.z)), a, b, offset});
        }
    };
    add(part.outer, 0.0);
    for (std::size_t k = 0; k < part.holes.size(); ++k) add(part.holes[k], hole_offsets[k]);
    index_->tree = decltype(index_->tree)(edges);  // bulk loading (packing)
}

BoundaryDistance::~BoundaryDistance() = default;
BoundaryDistance::BoundaryDistance(BoundaryDistance&&) noexcept = default;

double BoundaryDistance::operator()(Point p) const {
    // The nearest edge bounds φ from above; only edges closer than that bound can lower it, and
    // they all meet the square of half-side φ around p.
    const BoostPoint q(p.x, p.z);
    double phi = std::numeric_limits<double>::infinity();
    for (auto it = index_->tree.qbegin(bgi::nearest(q, 1)); it != index_->tree.qend(); ++it)
        phi = it->offset + distance_to_segment(p, it->a, it->b);
    const bg::model::box<BoostPoint> near(BoostPoint(p.x - phi, p.z - phi), BoostPoint(p.x + phi, p.z + phi));
    for (auto it = index_->tree.qbegin(bgi::intersects(near)); it != index_->tree.qend(); ++it)
        phi = std::min(phi, it->offset + distance_to_segment(p, it->a, it->b));
    return phi;
}

}  // namespace plascap::detail
