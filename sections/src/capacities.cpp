#include "plascap/sections/capacities.hpp"

#include "plascap/sections/plastic_bending.hpp"
#include "plascap/sections/ring_integrals.hpp"

namespace plascap {
namespace {

struct PartTotals {
    double force = 0.0;        // Σ fy·A  [N]
    double shear_force = 0.0;  // Σ τy·A  [N]
    RingMoments moments;       // ∫dA, ∫x dA, ∫z dA over the whole section (local coordinates)
};

PartTotals sum_parts(const ValidSection& section) {
    PartTotals totals;
    for (const Part& part : section.parts()) {
        const RingMoments m = part_moments(part);
        totals.force += part.material.fy * m.area;                                          // eq. 2.10
        totals.shear_force += shear_yield_stress(part.material.fy, section.shear()) * m.area;  // eq. 2.11
        totals.moments.area += m.area;
        totals.moments.Sx += m.Sx;
        totals.moments.Sz += m.Sz;
    }
    return totals;
}

// ∫ τy·|p − c| dA (eq. 2.14), c in local coordinates.
double torsion_capacity(const ValidSection& section, Point c) {
    double moment = 0.0;
    for (const Part& part : section.parts()) {
        double integral = distance_integral(part.outer, c);
        for (const Ring& hole : part.holes) integral += distance_integral(hole, c);
        moment += shear_yield_stress(part.material.fy, section.shear()) * integral;
    }
    return moment;
}

}  // namespace

std::optional<double> Capacities::get(Capacity c) const {
    switch (c) {
        case Capacity::N: return N;
        case Capacity::Qx: return Qx;
        case Capacity::Qz: return Qz;
        case Capacity::Mx: return Mx;
        case Capacity::Mz: return Mz;
        case Capacity::My: return My;
    }
    return std::nullopt;
}

Capacities compute_capacities(const ValidSection& section, CapacitySet wanted) {
    Capacities result;
    result.shear = section.shear();
    const PartTotals totals = sum_parts(section);
    const Point local_centroid{totals.moments.Sx / totals.moments.area, totals.moments.Sz / totals.moments.area};
    result.area = totals.moments.area;
    result.centroid = section.to_section(local_centroid);

    if (wanted.contains(Capacity::N)) result.N = totals.force;
    if (wanted.contains(Capacity::Qx)) result.Qx = totals.shear_force;
    if (wanted.contains(Capacity::Qz)) result.Qz = totals.shear_force;
    if (wanted.contains(Capacity::Mx)) {
        const PlasticBending bending = plastic_bending(section, BendingAxis::X);  // eq. 2.12
        result.Mx = bending.moment;
        result.z_pna = bending.axis + section.local_origin().z;
    }
    if (wanted.contains(Capacity::Mz)) {
        const PlasticBending bending = plastic_bending(section, BendingAxis::Z);  // eq. 2.13
        result.Mz = bending.moment;
        result.x_pna = bending.axis + section.local_origin().x;
    }
    if (wanted.contains(Capacity::My)) {
        const Point c = section.reference() ? section.to_local(*section.reference()) : local_centroid;
        result.My = torsion_capacity(section, c);
        result.reference = section.reference() ? *section.reference() : result.centroid;
    }
    return result;
}

}  // namespace plascap
