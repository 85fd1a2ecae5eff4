#pragma once
// Euclidean distances in the section plane (shared by the bar checks, the mesh cuts and the sand
// heap of plastic torsion).
#include <algorithm>
#include <cmath>
#include <limits>

#include "plascap/sections/geometry.hpp"

namespace plascap::detail {

inline double distance_to_segment(Point p, Point a, Point b) {
    const double dx = b.x - a.x, dz = b.z - a.z;
    const double length2 = dx * dx + dz * dz;
    const double t = length2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.z - a.z) * dz) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.z - a.z - t * dz);
}

// To the nearest edge of a closed ring.
inline double distance_to_ring(Point p, const Ring& ring) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) d = std::min(d, distance_to_segment(p, ring[i], ring[i + 1 == n ? 0 : i + 1]));
    return d;
}

}  // namespace plascap::detail
