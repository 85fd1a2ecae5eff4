#pragma once
// The yield condition of a section under all six joint loads: the exact N–Mx–Mz surface
// (yield_surface.hpp) reduced by shear and torsion (docs/yield-surface.md, "Shear and torsion").
//
// Shear and torsion use a share η of the shear strength everywhere:
//   η = √((Qx/Qxp)² + (Qz/Qzp)²) + |T|/Tt,
// Qxp = Qzp = Σ τy·A (eq. 2.11, which already assumes τ uniform), Tt the torsion capacity: the fully
// plastic torque T_p of the sand heap by default (a stress field of magnitude τy everywhere), or
// the paper's eq. 2.14. Scaling those fields by η leaves σ ≤ fy·√(1 − η²) by von Mises (or Tresca:
// σ² + 4τ² ≤ fy² with τy = fy/2 gives the same), so the N–M surface shrinks by √(1 − η²) — the
// uniform reduction of fy that EN 1993-1-1 §6.2.8(3) and §6.2.10 apply to the shear area — and
//   U = √(u_NM² + η²),  u_NM = the N–Mx–Mz utilisation.
// U is convex (a norm of two gauges) and 1 on the yield condition. For torsion it is a lower bound
// (the scaled sand heap is statically admissible), exact for a thin-walled tube under N and T
// (n² + t² = 1); the linear sum of shear and torsion is safe by convexity.
#include <array>
#include <optional>
#include <string>

#include "plascap/sections/yield_surface.hpp"

namespace plascap {

// The six loads a joint carries [N, N·m]: capacities.hpp's signs for N, Mx, Mz.
struct SectionLoads {
    double N = 0.0, Qx = 0.0, Qz = 0.0, Mx = 0.0, Mz = 0.0, T = 0.0;
};

enum class TorsionCapacity {
    FullyPlastic,  // T_p, the sand heap (plastic_torsion.hpp): the default
    Paper,         // ∫ τy·|p − c| dA (eq. 2.14): an upper bound far above T_p
};

struct ShearTorsionCapacities {
    double Qx = 0.0, Qz = 0.0, T = 0.0;  // [N, N, N·m], all > 0
};

struct SectionYieldState {
    double utilisation = 0.0;           // U; +inf for a load the section can never carry
    double nm_utilisation = 0.0;        // u_NM, the N–Mx–Mz part
    double shear_torsion_share = 0.0;   // η
    SectionLoads gradient;              // ∂U/∂load (the outward normal of the yield condition)
    std::optional<SectionResultant> nm_normal;  // the N–M surface's normal, for a warm start
};

class SectionYield {
public:
    // Throws InputError unless every capacity is positive and finite.
    SectionYield(YieldSurface surface, const ShearTorsionCapacities& capacities);

    SectionYieldState evaluate(const SectionLoads& load, const std::optional<SectionResultant>& warm = {}) const;
    double utilisation(const SectionLoads& load) const { return evaluate(load).utilisation; }

    const YieldSurface& surface() const { return surface_; }
    const ShearTorsionCapacities& shear_torsion() const { return capacities_; }

private:
    YieldSurface surface_;
    ShearTorsionCapacities capacities_;
};

// The yield condition of a section: its exact N–M surface, Qxp = Qzp = Σ τy·A (eq. 2.11) and the
// torsion capacity chosen (T_p by the sand heap, to its default tolerance, or eq. 2.14).
SectionYield section_yield(const ValidSection& section, TorsionCapacity torsion = TorsionCapacity::FullyPlastic);

const char* torsion_capacity_name(TorsionCapacity torsion);  // "fully-plastic", "paper"
// Throws InputError naming `where` for another name.
TorsionCapacity torsion_capacity_from_name(const std::string& name, const std::string& where);

// The shear-and-torsion share η of the header.
double shear_torsion_share(const SectionLoads& load, const ShearTorsionCapacities& capacities);

}  // namespace plascap
