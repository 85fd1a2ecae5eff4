#include "plascap/sections/capacities.hpp"

#include <cmath>

#include "bar_strength.hpp"

#include "plascap/sections/plastic_bending.hpp"
#include "plascap/sections/ring_integrals.hpp"

namespace plascap {
namespace {

struct PartTotals {
    double force = 0.0;        // Σ fy·A  [N]
    double compression = 0.0;  // Σ fc·A  [N]
    double shear_force = 0.0;  // Σ τy·A  [N]
    RingMoments moments;       // ∫dA, ∫x dA, ∫z dA over the whole section (local coordinates)
};

PartTotals sum_parts(const ValidSection& section) {
    PartTotals totals;
    for (std::size_t p = 0; p < section.parts().size(); ++p) {
        const Part& part = section.parts()[p];
        const RingMoments& m = section.part_moments()[p];
        totals.force += part.material.fy * m.area;                                          // eq. 2.10
        totals.compression += part.material.compression_strength() * m.area;               // eq. 2.10 with fc
        totals.shear_force += shear_yield_stress(part.material.fy, section.shear()) * m.area;  // eq. 2.11
        totals.moments.area += m.area;
        totals.moments.Sx += m.Sx;
        totals.moments.Sz += m.Sz;
        for (const Bar& bar : part.bars) {  // bars displace the part's material
            const detail::BarStrength s = detail::bar_strength(bar, part.material, section.shear());
            totals.force += s.tension * bar.area;
            totals.compression += s.compression * bar.area;
            totals.shear_force += s.shear * bar.area;
        }
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
        for (const Bar& bar : part.bars)
            moment += detail::bar_strength(bar, part.material, section.shear()).shear * bar.area *
                      std::hypot(bar.at.x - c.x, bar.at.z - c.z);
    }
    return moment;
}

// True when every part has fc = fy: then each _neg capacity equals its counterpart.
bool same_strength_both_ways(const ValidSection& section) {
    for (const Part& part : section.parts()) {
        if (part.material.compression_strength() != part.material.fy) return false;
        for (const Bar& bar : part.bars)
            if (bar.material.compression_strength() != bar.material.fy) return false;
    }
    return true;
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
        case Capacity::N_neg: return N_neg;
        case Capacity::Mx_neg: return Mx_neg;
        case Capacity::Mz_neg: return Mz_neg;
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
    if (wanted.contains(Capacity::N_neg)) result.N_neg = totals.compression;
    if (wanted.contains(Capacity::Qx)) result.Qx = totals.shear_force;
    if (wanted.contains(Capacity::Qz)) result.Qz = totals.shear_force;
    const bool symmetric = same_strength_both_ways(section);
    const auto bending = [&](BendingAxis axis, bool negative, std::optional<double>& moment, std::optional<double>& level) {
        const PlasticBending b = plastic_bending(section, axis, tension_side(axis, negative));  // eqs. 2.12, 2.13
        moment = b.moment;
        level = b.axis + (axis == BendingAxis::X ? section.local_origin().z : section.local_origin().x);
    };
    const auto both_signs = [&](BendingAxis axis, Capacity positive, Capacity negative, std::optional<double>& m,
                                std::optional<double>& level, std::optional<double>& m_neg, std::optional<double>& level_neg) {
        const bool want = wanted.contains(positive), want_neg = wanted.contains(negative);
        if (want || (want_neg && symmetric)) bending(axis, false, m, level);
        if (want_neg && symmetric) m_neg = m, level_neg = level;
        else if (want_neg) bending(axis, true, m_neg, level_neg);
        if (!want) m.reset(), level.reset();
    };
    both_signs(BendingAxis::X, Capacity::Mx, Capacity::Mx_neg, result.Mx, result.z_pna, result.Mx_neg, result.z_pna_neg);
    both_signs(BendingAxis::Z, Capacity::Mz, Capacity::Mz_neg, result.Mz, result.x_pna, result.Mz_neg, result.x_pna_neg);
    if (wanted.contains(Capacity::My)) {
        const Point c = section.reference() ? section.to_local(*section.reference()) : local_centroid;
        result.My = torsion_capacity(section, c);
        result.reference = section.reference() ? *section.reference() : result.centroid;
    }
    return result;
}

}  // namespace plascap
