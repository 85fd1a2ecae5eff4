#include "bar_checks.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "planar_distance.hpp"
#include "plascap/input_error.hpp"
#include "plascap/sections/ring_integrals.hpp"
#include "topology_checks.hpp"

namespace plascap::detail {
namespace {

constexpr double kPi = 3.141592653589793;

std::string number(double value) {
    std::ostringstream out;
    out.precision(10);
    out << value;
    return out.str();
}

double radius_of(const Bar& bar) { return std::sqrt(bar.area / kPi); }  // a round bar of that area

void check_bar_inside(const Part& part, const Bar& bar, const std::string& where) {
    const std::string at = "(" + number(bar.at.x) + ", " + number(bar.at.z) + ") m";
    if (!strictly_inside(part.outer, bar.at)) throw InputError(where + ": its centre " + at + " lies outside its part");
    for (std::size_t h = 0; h < part.holes.size(); ++h)
        if (strictly_inside(part.holes[h], bar.at))
            throw InputError(where + ": its centre " + at + " lies in hole " + std::to_string(h) + " of its part");
    double clearance = distance_to_ring(bar.at, part.outer);
    for (const Ring& hole : part.holes) clearance = std::fmin(clearance, distance_to_ring(bar.at, hole));
    if (clearance < radius_of(bar))
        throw InputError(where + ": the bar (radius " + number(radius_of(bar)) + " m for its area) crosses its part's edge, " +
                         number(clearance) + " m from its centre " + at);
}

}  // namespace

void check_bars(const Part& part, std::size_t part_index) {
    // Rings are not oriented yet: the material's area is |outer| − Σ|hole|.
    double part_area = std::fabs(ring_moments(part.outer).area);
    for (const Ring& hole : part.holes) part_area -= std::fabs(ring_moments(hole).area);
    for (std::size_t b = 0; b < part.bars.size(); ++b) {
        const Bar& bar = part.bars[b];
        const std::string where = "part " + std::to_string(part_index) + ", bar " + std::to_string(b);
        if (!std::isfinite(bar.at.x) || !std::isfinite(bar.at.z))
            throw InputError(where + ": its position must be finite");
        if (!std::isfinite(bar.area) || bar.area <= 0.0 || bar.area > part_area)
            throw InputError(where + ": its area must be a positive finite number up to its part's area " + number(part_area) +
                             " m² (got " + number(bar.area) + ")");
        validate_material(bar.material, where + ", material");
        check_bar_inside(part, bar, where);
        for (std::size_t c = 0; c < b; ++c) {
            const Bar& other = part.bars[c];
            const double gap = std::hypot(bar.at.x - other.at.x, bar.at.z - other.at.z);
            if (gap < radius_of(bar) + radius_of(other))
                throw InputError(where + ": overlaps bar " + std::to_string(c) + " (centres " + number(gap) +
                                 " m apart, radii " + number(radius_of(bar)) + " and " + number(radius_of(other)) + " m)");
        }
    }
}

}  // namespace plascap::detail
