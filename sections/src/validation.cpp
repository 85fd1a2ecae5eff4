#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "plascap/input_error.hpp"
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/valid_section.hpp"
#include "bar_checks.hpp"
#include "topology_checks.hpp"

namespace plascap {
namespace {

// Supported sizes (documented in docs/section-format.md): coordinates within ±1e6 m, rings at least
// 1e-9 m across, and area at least 1e-12 of the square of the ring's extent (anything thinner is
// collinear up to the round-off of its own coordinates).
constexpr double kMaxCoordinate = 1e6;
constexpr double kMinExtent = 1e-9;
constexpr double kMinAreaRatio = 1e-12;
// Parts overlapping by at most this fraction of the smaller one share an edge up to round-off.
constexpr double kRoundOffOverlap = 1e-9;
// Above this many vertices a self-intersection is reported without naming the edges (O(n²) search).
constexpr std::size_t kMaxVerticesToLocate = 5000;

std::string number(double value) {
    std::ostringstream out;
    out.precision(17);
    out << value;
    return out.str();
}

struct RingId {
    std::size_t part;
    int hole;  // -1: the outer ring

    std::string name() const {
        return "part " + std::to_string(part) + ", " + (hole < 0 ? std::string("outer ring") : "hole " + std::to_string(hole));
    }
    std::string vertex(std::size_t i) const { return name() + ", vertex " + std::to_string(i); }
};

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

bool same_point(Point a, Point b) { return a.x == b.x && a.z == b.z; }

// Shoelace area about the ring's first vertex: no cancellation when the ring is far from the origin.
double signed_area(const Ring& ring) {
    Ring local = ring;
    for (Point& p : local) p = {p.x - ring[0].x, p.z - ring[0].z};
    return ring_moments(local).area;
}

using Box = RingExtent;

bool overlaps(const Box& a, const Box& b) {
    return a.min_x < b.max_x && b.min_x < a.max_x && a.min_z < b.max_z && b.min_z < a.max_z;
}

// Drops the closing vertex, then checks what a ring must be on its own: enough vertices,
// finite and in-range coordinates, no repeated neighbours, non-vanishing area, simple.
Ring checked_ring(Ring ring, const RingId& id) {
    if (ring.size() > 1 && same_point(ring.front(), ring.back())) ring.pop_back();
    for (std::size_t i = 0; i < ring.size(); ++i) {
        for (const auto& [axis, value] : {std::pair<const char*, double>{"x", ring[i].x}, {"z", ring[i].z}}) {
            if (!std::isfinite(value))
                fail(id.vertex(i), std::string("coordinate ") + axis + " is not a finite number (" + number(value) + ")");
            if (std::fabs(value) > kMaxCoordinate)
                fail(id.vertex(i), std::string("coordinate ") + axis + " = " + number(value) +
                                       " m is outside the supported range ±1e6 m");
        }
    }
    if (ring.size() < 3)
        fail(id.name(), "has " + std::to_string(ring.size()) + " distinct vertices; a ring needs at least 3");
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::size_t next = (i + 1) % ring.size();
        if (same_point(ring[i], ring[next]))
            fail(id.vertex(next), "repeats vertex " + std::to_string(i));
    }
    const Box box = ring_extent(ring);
    const double extent = std::max(box.max_x - box.min_x, box.max_z - box.min_z);
    if (extent < kMinExtent)
        fail(id.name(), "is only " + number(extent) + " m across; the smallest supported ring is 1e-9 m across");
    if (!detail::ring_is_simple(ring)) {
        if (detail::all_collinear(ring)) fail(id.name(), "has zero area: its vertices are collinear");
        const auto edges = detail::find_intersecting_edges(ring, kMaxVerticesToLocate);
        if (!edges) fail(id.name(), "is self-intersecting");
        const std::size_t n = ring.size();
        fail(id.vertex(edges->first), "is self-intersecting: edge " + std::to_string(edges->first) + "-" +
                                          std::to_string((edges->first + 1) % n) + " meets edge " +
                                          std::to_string(edges->second) + "-" +
                                          std::to_string((edges->second + 1) % n));
    }
    const double area = signed_area(ring);
    if (!(std::fabs(area) > kMinAreaRatio * extent * extent))
        fail(id.name(), "has vanishing area (" + number(std::fabs(area)) + " m² for a ring " + number(extent) +
                            " m across): its vertices are nearly collinear");
    return ring;
}

void orient(Ring& ring, bool counter_clockwise) {
    if ((signed_area(ring) > 0.0) != counter_clockwise) std::reverse(ring.begin(), ring.end());
}

// Ring `ring` (named by `id`) touches `other`: say so, naming the two edges where the search is
// affordable, then the rule.
[[noreturn]] void fail_touching(const Ring& ring, const RingId& id, const Ring& other, const std::string& other_name,
                                const std::string& what, const std::string& rule) {
    const auto edges = detail::find_touching_edges(ring, other, kMaxVerticesToLocate);
    if (!edges) fail(id.name(), what + rule);
    fail(id.vertex(edges->first), what + " (its edge " + std::to_string(edges->first) + "-" +
                                      std::to_string((edges->first + 1) % ring.size()) + " meets edge " +
                                      std::to_string(edges->second) + "-" +
                                      std::to_string((edges->second + 1) % other.size()) + " of " + other_name + ")" +
                                      rule);
}

// Holes strictly inside the outer ring and apart from each other.
void check_holes(const Part& part, std::size_t p) {
    if (part.holes.empty()) return;
    std::vector<const Ring*> rings{&part.outer};
    for (const Ring& hole : part.holes) rings.push_back(&hole);
    const bool touching = detail::any_rings_touch(rings);
    for (std::size_t h = 0; h < part.holes.size(); ++h) {
        const RingId id{p, static_cast<int>(h)};
        if (touching && detail::rings_touch(part.outer, part.holes[h]))
            fail_touching(part.holes[h], id, part.outer, "the outer ring", "touches or crosses its outer ring",
                          "; holes must lie strictly inside it");
        if (!detail::strictly_inside(part.outer, part.holes[h][0]))
            fail(id.vertex(0), "lies outside its outer ring; holes must lie strictly inside it");
        for (std::size_t g = 0; g < h; ++g) {
            const std::string overlap = "overlaps or touches hole " + std::to_string(g) + " of the same part";
            if (touching && detail::rings_touch(part.holes[g], part.holes[h]))
                fail_touching(part.holes[h], id, part.holes[g], "hole " + std::to_string(g), overlap, "");
            if (detail::strictly_inside(part.holes[g], part.holes[h][0])) fail(id.vertex(0), overlap);
            if (detail::strictly_inside(part.holes[h], part.holes[g][0])) fail(id.name(), overlap + " (which lies inside it)");
        }
    }
}

// Pairs whose bounding boxes overlap, found by a sweep over x (sort and scan), then CGAL's exact
// overlap on those pairs only: thousands of parts stay cheap. An overlap of at most
// kRoundOffOverlap of the smaller part is the round-off of an edge the parts share (a grid built as
// j*0.01 and j*0.01 + 0.01 overlaps by 1e-17 m): accepted; it changes no capacity by more than that.
void check_parts_apart(const std::vector<Part>& parts) {
    std::vector<Box> boxes;
    for (const Part& part : parts) boxes.push_back(ring_extent(part.outer));
    std::vector<std::size_t> by_x(parts.size());
    for (std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
    std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return boxes[a].min_x < boxes[b].min_x; });
    for (std::size_t k = 0; k < by_x.size(); ++k) {
        for (std::size_t l = k + 1; l < by_x.size() && boxes[by_x[l]].min_x < boxes[by_x[k]].max_x; ++l) {
            const std::size_t i = std::max(by_x[k], by_x[l]), j = std::min(by_x[k], by_x[l]);
            if (!overlaps(boxes[i], boxes[j])) continue;
            const double overlap = detail::overlap_area(parts[i], parts[j]);
            const double smaller = std::min(part_moments(parts[i]).area, part_moments(parts[j]).area);
            if (overlap > kRoundOffOverlap * smaller)
                fail("part " + std::to_string(i), "overlaps part " + std::to_string(j) + " by " + number(overlap) +
                                                      " m² (parts may share edges, not area)");
        }
    }
}

// The criterion all parts' materials name (S355: von Mises, EN 1993-1-1 6.2.6), else Tresca.
ShearCriterion materials_shear_criterion(const Section& section) {
    std::optional<ShearCriterion> common;
    for (const Part& part : section.parts) {
        if (!part.material.shear || (common && *common != *part.material.shear)) return ShearCriterion::Tresca;
        common = part.material.shear;
    }
    return common.value_or(ShearCriterion::Tresca);
}

}  // namespace

std::size_t ValidSection::vertex_count() const {
    std::size_t n = 0;
    for (const Part& part : parts_) {
        n += part.outer.size();
        for (const Ring& hole : part.holes) n += hole.size();
    }
    return n;
}

ValidSection validate_section(const Section& section) {
    if (section.parts.empty()) throw InputError("section: has no parts; give at least one part with an outer ring");
    ValidSection valid;
    valid.shear_ = section.shear ? *section.shear : materials_shear_criterion(section);
    for (std::size_t p = 0; p < section.parts.size(); ++p) {
        const Part& given = section.parts[p];
        validate_material(given.material, "part " + std::to_string(p) + ", material");
        Part part{checked_ring(given.outer, {p, -1}), {}, given.material, given.bars};
        for (std::size_t h = 0; h < given.holes.size(); ++h)
            part.holes.push_back(checked_ring(given.holes[h], {p, static_cast<int>(h)}));
        check_holes(part, p);  // before orienting, so that messages count vertices as given
        detail::check_bars(part, p);
        orient(part.outer, true);
        for (Ring& hole : part.holes) orient(hole, false);
        valid.parts_.push_back(std::move(part));
    }
    check_parts_apart(valid.parts_);

    if (section.reference) {
        const Point r = *section.reference;
        if (!std::isfinite(r.x) || !std::isfinite(r.z) || std::fabs(r.x) > kMaxCoordinate ||
            std::fabs(r.z) > kMaxCoordinate)
            throw InputError("reference: the joint point (" + number(r.x) + ", " + number(r.z) +
                             ") must be finite and within ±1e6 m");
        valid.reference_ = r;
    }

    // Local origin: the centre of the bounding box of all parts.
    std::vector<Box> boxes;
    for (const Part& part : valid.parts_) boxes.push_back(ring_extent(part.outer));
    Box all = boxes[0];
    for (const Box& b : boxes)
        all = {std::min(all.min_x, b.min_x), std::max(all.max_x, b.max_x), std::min(all.min_z, b.min_z),
               std::max(all.max_z, b.max_z)};
    valid.origin_ = {0.5 * (all.min_x + all.max_x), 0.5 * (all.min_z + all.max_z)};
    // Shifted as the vertices are: x − origin is monotonic in x, so the box stays exactly the ring's.
    for (const Box& b : boxes)
        valid.part_extents_.push_back({b.min_x - valid.origin_.x, b.max_x - valid.origin_.x,
                                       b.min_z - valid.origin_.z, b.max_z - valid.origin_.z});
    for (Part& part : valid.parts_) {
        for (Point& q : part.outer) q = valid.to_local(q);
        for (Ring& hole : part.holes)
            for (Point& q : hole) q = valid.to_local(q);
        for (Bar& bar : part.bars) bar.at = valid.to_local(bar.at);
        valid.part_moments_.push_back(part_moments(part));  // every capacity needs them: once here
    }
    return valid;
}

}  // namespace plascap
