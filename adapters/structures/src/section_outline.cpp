#include "section_outline.hpp"

#include <algorithm>
#include <boost/geometry/algorithms/simplify.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/ring.hpp>
#include <boost/geometry/strategies/strategies.hpp>
#include <cmath>

namespace plascap::detail {

std::pair<double, double> section_extent(const ValidSection& section) {
    double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
    for (const Part& part : section.parts())
        for (const Point& p : part.outer) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
    return {x1 - x0, z1 - z0};
}

// Douglas–Peucker (Boost.Geometry): a rolled shape's root arcs come as hundreds of chords, which a
// replay of a thousand segments cannot draw.
SectionOutline section_outline(const ValidSection& section, const ElasticProperties& elastic) {
    namespace bg = boost::geometry;
    using Xz = bg::model::d2::point_xy<double>;
    using DrawnRing = bg::model::ring<Xz, false, false>;  // counter-clockwise, open, as ValidSection keeps them
    const Point line = section.reference() ? *section.reference() : elastic.centroid;
    const auto [width, depth] = section_extent(section);
    const double tolerance = 0.01 * std::max(width, depth);
    const auto drawn = [&](const Ring& ring) {
        DrawnRing full, simple;
        for (const Point& local : ring) {
            const Point p = section.to_section(local);
            full.push_back(Xz(p.x - line.x, p.z - line.z));
        }
        bg::simplify(full, simple, tolerance);
        if (simple.size() < 3) simple = full;
        Outline o;
        for (const Xz& p : simple) o.push_back({p.x(), p.y()});
        return o;
    };
    SectionOutline outline;
    for (const Part& part : section.parts()) {
        OutlinePart drawn_part{drawn(part.outer), {}};
        for (const Ring& hole : part.holes) drawn_part.holes.push_back(drawn(hole));
        outline.push_back(std::move(drawn_part));
    }
    return outline;
}

}  // namespace plascap::detail
