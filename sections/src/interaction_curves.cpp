#include "plascap/sections/interaction_curves.hpp"

#include <cmath>
#include <optional>
#include <string>

#include "plascap/input_error.hpp"

namespace plascap {
namespace {

const double kTwoPi = 2.0 * std::acos(-1.0);

void check_samples(std::size_t samples) {
    if (samples < 8 || samples > 100000)
        throw InputError("interaction curves: samples must be between 8 and 100000 (got " + std::to_string(samples) + ")");
}

// Rays from the origin in the plane of N and one moment (which = 1 for Mx, 2 for Mz).
std::vector<SectionResultant> meridian(const YieldSurface& surface, int which, std::size_t samples) {
    check_samples(samples);
    const SectionResultant s = surface.scale();
    std::vector<SectionResultant> curve;
    std::optional<SectionResultant> warm;
    for (std::size_t i = 0; i < samples; ++i) {
        const double a = kTwoPi * static_cast<double>(i) / static_cast<double>(samples);
        SectionResultant direction{s.N * std::cos(a), 0.0, 0.0};
        (which == 1 ? direction.Mx : direction.Mz) = (which == 1 ? s.Mx : s.Mz) * std::sin(a);
        const SurfaceHit hit = surface.along(direction, warm);
        curve.push_back(hit.point);
        warm = hit.normal;
    }
    return curve;
}

}  // namespace

std::vector<SectionResultant> n_mx_curve(const YieldSurface& surface, std::size_t samples) {
    return meridian(surface, 1, samples);
}

std::vector<SectionResultant> n_mz_curve(const YieldSurface& surface, std::size_t samples) {
    return meridian(surface, 2, samples);
}

std::vector<SectionResultant> mx_mz_curve(const YieldSurface& surface, double N, std::size_t samples) {
    check_samples(samples);
    const double tension = surface.full_tension().N, compression = surface.full_compression().N;
    if (!(N < tension && N > compression))
        throw InputError("interaction curves: N = " + std::to_string(N) + " N must lie strictly between the full compression " +
                         std::to_string(compression) + " N and the full tension " + std::to_string(tension) + " N");
    const SectionResultant s = surface.scale();
    // Rays in the plane N = const from its point on the N axis (inside for any N strictly between
    // the ends when the section is homogeneous; from() says so when it is not).
    std::vector<SectionResultant> curve;
    std::optional<SectionResultant> warm;
    const SectionResultant origin{N, 0.0, 0.0};
    for (std::size_t i = 0; i < samples; ++i) {
        const double a = kTwoPi * static_cast<double>(i) / static_cast<double>(samples);
        const SurfaceHit hit = surface.from(origin, {0.0, s.Mx * std::cos(a), s.Mz * std::sin(a)}, warm);
        curve.push_back(hit.point);
        warm = hit.normal;
    }
    return curve;
}

}  // namespace plascap
