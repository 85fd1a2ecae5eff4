#include "plascap/sections/elastic_properties.hpp"

#include <algorithm>
#include <cmath>

namespace plascap {
namespace {

// ∫dA, ∫x dA, ∫z dA, ∫x² dA, ∫z² dA, ∫xz dA over a ring (signed by orientation) with its
// coordinates taken about `o` (Green's theorem; Steger 1996, eqs. for moments of order ≤ 2).
struct Moments {
    double a = 0.0, sx = 0.0, sz = 0.0, xx = 0.0, zz = 0.0, xz = 0.0;

    void add(const Moments& m, double weight) {
        a += weight * m.a, sx += weight * m.sx, sz += weight * m.sz;
        xx += weight * m.xx, zz += weight * m.zz, xz += weight * m.xz;
    }
};

Moments ring_second_moments(const Ring& ring, Point o) {
    Moments m;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const double x0 = ring[i].x - o.x, z0 = ring[i].z - o.z;
        const double x1 = ring[i + 1 == n ? 0 : i + 1].x - o.x, z1 = ring[i + 1 == n ? 0 : i + 1].z - o.z;
        const double cross = x0 * z1 - x1 * z0;
        m.a += cross / 2.0;
        m.sx += (x0 + x1) * cross / 6.0;
        m.sz += (z0 + z1) * cross / 6.0;
        m.xx += (x0 * x0 + x0 * x1 + x1 * x1) * cross / 12.0;
        m.zz += (z0 * z0 + z0 * z1 + z1 * z1) * cross / 12.0;
        m.xz += (x0 * z1 + 2.0 * x0 * z0 + 2.0 * x1 * z1 + x1 * z0) * cross / 24.0;
    }
    return m;
}

// A point area (a bar) as moments about o.
Moments point_moments(Point p, double area, Point o) {
    const double x = p.x - o.x, z = p.z - o.z;
    return {area, area * x, area * z, area * x * x, area * z * z, area * x * z};
}

// The section's moments about o, each part weighted by weight(material); bars add
// (weight(bar) − weight(part))·A at their centre when `with_bars`.
template <class Weight>
Moments section_moments(const ValidSection& section, Point o, Weight weight, bool with_bars) {
    Moments total;
    for (const Part& part : section.parts()) {
        const double w = weight(part.material);
        total.add(ring_second_moments(part.outer, o), w);
        for (const Ring& hole : part.holes) total.add(ring_second_moments(hole, o), w);
        if (with_bars)
            for (const Bar& bar : part.bars) total.add(point_moments(bar.at, bar.area, o), weight(bar.material) - w);
    }
    return total;
}

// Second moments about the weighted centroid: computed again about it (no parallel-axis cancellation).
template <class Weight>
Moments centroidal(const ValidSection& section, Weight weight, bool with_bars, Point& centroid) {
    const Moments first = section_moments(section, Point{0.0, 0.0}, weight, with_bars);
    centroid = {first.sx / first.a, first.sz / first.a};
    return section_moments(section, centroid, weight, with_bars);
}

bool every_material_gives_E(const ValidSection& section) {
    for (const Part& part : section.parts()) {
        if (!part.material.E) return false;
        for (const Bar& bar : part.bars)
            if (!bar.material.E) return false;
    }
    return true;
}

}  // namespace

ElasticProperties elastic_properties(const ValidSection& section) {
    ElasticProperties p;
    Point c;
    const Moments m = centroidal(section, [](const Material&) { return 1.0; }, false, c);
    p.area = m.a;
    p.centroid = section.to_section(c);
    p.Ixx = m.zz, p.Izz = m.xx, p.Ixz = m.xz;
    const double mean = 0.5 * (p.Ixx + p.Izz), half_difference = 0.5 * (p.Ixx - p.Izz);
    const double radius = std::hypot(half_difference, p.Ixz);  // Mohr's circle
    p.I1 = mean + radius, p.I2 = mean - radius;
    p.principal_angle = 0.5 * std::atan2(-2.0 * p.Ixz, p.Ixx - p.Izz);
    double reach_z = 0.0, reach_x = 0.0;  // extreme fibres from the centroid
    for (const Part& part : section.parts())
        for (Point q : part.outer) reach_z = std::max(reach_z, std::abs(q.z - c.z)), reach_x = std::max(reach_x, std::abs(q.x - c.x));
    p.Wx = p.Ixx / reach_z, p.Wz = p.Izz / reach_x;
    p.rx = std::sqrt(p.Ixx / p.area), p.rz = std::sqrt(p.Izz / p.area);
    if (every_material_gives_E(section)) {
        Point ce;
        const Moments e = centroidal(section, [](const Material& material) { return *material.E; }, true, ce);
        p.stiffness = SectionStiffness{section.to_section(ce), e.a, e.zz, e.xx, e.xz};
    }
    return p;
}

}  // namespace plascap
