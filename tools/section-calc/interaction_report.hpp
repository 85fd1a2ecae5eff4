#pragma once
// section-calc --load and --interaction: the utilisation of a load on the section's exact yield
// condition, and the sampled N–Mx, N–Mz and Mx–Mz curves, as text, JSON and SVG panels.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "plascap/sections/section_yield.hpp"
#include "section_svg.hpp"

namespace plascap::tools {

// "N=1e5,Mx=2e4": components N, Mx, Mz, Qx, Qz, My [N, N·m]; omitted ones are 0. Throws InputError
// naming the component at fault.
SectionLoads parse_load(const std::string& text);

struct LoadCheck {
    SectionLoads load;
    SectionYieldState state;
    double nm_utilisation = 0.0;  // u_NM
    double share = 0.0;           // η
    TorsionCapacity torsion = TorsionCapacity::FullyPlastic;
};
LoadCheck check_load(const SectionYield& yield, const SectionLoads& load, TorsionCapacity torsion);

struct InteractionCurves {
    std::vector<SectionResultant> n_mx, n_mz, mx_mz;
    double mx_mz_at = 0.0;  // N of the Mx–Mz cut [N]
    // The paper's independent limits: where the surface meets each axis, both ways.
    SectionResultant box_positive, box_negative;  // (N, Mx, Mz) and (N_neg, Mx_neg, Mz_neg), magnitudes
};
InteractionCurves sample_interaction(const YieldSurface& surface, double N, std::size_t samples);

std::string load_check_text(const LoadCheck& check, const SectionYield& yield);
void add_load_check_json(nlohmann::ordered_json& out, const LoadCheck& check, const SectionYield& yield);
std::string interaction_text(const InteractionCurves& curves);
void add_interaction_json(nlohmann::ordered_json& out, const InteractionCurves& curves);

// The three diagrams side by side, with the load's point.
SvgPanel interaction_panels(const InteractionCurves& curves, const std::optional<SectionLoads>& load);

}  // namespace plascap::tools
