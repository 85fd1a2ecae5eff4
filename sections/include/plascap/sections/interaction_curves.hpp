#pragma once
// Sampled cuts through the exact yield surface (yield_surface.hpp), for plots and reports:
// the N–Mx and N–Mz curves (Mz = 0, resp. Mx = 0) and the Mx–Mz curve at a given N. Each is a
// closed convex loop of surface points, in order of angle in the plane of the cut (the two
// components scaled by the surface's own sizes, so the samples spread evenly around it). The
// points are exact (each is a ray's exact hit); only the sampling is discrete.
#include <cstddef>
#include <vector>

#include "plascap/sections/yield_surface.hpp"

namespace plascap {

std::vector<SectionResultant> n_mx_curve(const YieldSurface& surface, std::size_t samples);
std::vector<SectionResultant> n_mz_curve(const YieldSurface& surface, std::size_t samples);
// Throws InputError unless N lies strictly between the full compression and full tension.
std::vector<SectionResultant> mx_mz_curve(const YieldSurface& surface, double N, std::size_t samples);

}  // namespace plascap
