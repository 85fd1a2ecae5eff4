#include "plascap/adapters/section_joint_settings.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "plascap/adapters/section_yield_condition.hpp"
#include "plascap/input_error.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/joint_stiffness.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/torsion_constant.hpp"

namespace plascap {
namespace {

double required(const std::optional<double>& capacity, const char* name) {
    if (!capacity || !(*capacity > 0.0)) {
        throw InputError(std::string("the section has no positive ") + name + " capacity");
    }
    return *capacity;
}

bool any_plastic(const PerDof<DofMode>& modes) {
    return std::any_of(modes.begin(), modes.end(), [](DofMode m) { return m == DofMode::Plastic; });
}

// The smallest limit any of the section's materials gives, if one does.
template <class Limit>
std::optional<double> smallest(const ValidSection& section, Limit limit) {
    std::optional<double> least;
    const auto consider = [&](const Material& m) {
        if (const std::optional<double> v = limit(m)) least = least ? std::min(*least, *v) : *v;
    };
    for (const Part& part : section.parts()) {
        consider(part.material);
        for (const Bar& bar : part.bars) consider(bar.material);
    }
    return least;
}

}  // namespace

DofLaw dof_law_from_section(Dof dof, const Capacities& c) {
    DofLaw law;
    switch (dof) {
        case Dof::Qx: law.capacity_positive = law.capacity_negative = required(c.Qx, "Qx"); break;
        case Dof::Qz: law.capacity_positive = law.capacity_negative = required(c.Qz, "Qz"); break;
        case Dof::My: law.capacity_positive = law.capacity_negative = required(c.My, "My"); break;
        case Dof::N:
            law.capacity_positive = required(c.N, "N");
            law.capacity_negative = required(c.N_neg, "N_neg");
            break;
        case Dof::Mx:
            law.capacity_positive = required(c.Mx, "Mx");
            law.capacity_negative = required(c.Mx_neg, "Mx_neg");
            break;
        case Dof::Mz:
            law.capacity_positive = required(c.Mz, "Mz");
            law.capacity_negative = required(c.Mz_neg, "Mz_neg");
            break;
    }
    return law;  // rigid-plastic: a stiffness, where wanted, comes from the beam segment
}

PerDof<std::optional<double>> segment_stiffness(const ValidSection& section, double length) {
    if (!(length > 0.0) || !std::isfinite(length))
        throw InputError("the segment length must be positive and finite (got " + std::to_string(length) + ")");
    const ElasticProperties elastic = elastic_properties(section);
    if (!elastic.stiffness) throw InputError("the stiffness needs E for every material of the section");
    const TorsionConstant torsion = saint_venant_torsion(section);
    const JointStiffness s = joint_stiffness(*elastic.stiffness, torsion.GJ, length);
    return {s.shear_x, s.axial, s.shear_z, s.bending_x, s.torsion, s.bending_z};
}

PlasticJointSettings section_joint_settings(const ValidSection& section, const SectionJointOptions& o) {
    PlasticJointSettings settings;
    settings.modes = o.modes;
    Capacities c = compute_capacities(section);
    const bool torsion_used = o.modes[index(Dof::My)] == DofMode::Plastic || o.coupled;
    if (o.torsion == TorsionCapacity::FullyPlastic && torsion_used) c.My = plastic_torsion(section).T;
    if (o.coupled && any_plastic(o.modes)) {
        settings.yield_condition = section_yield_condition(SectionYield(YieldSurface(section), {*c.Qx, *c.Qz, *c.My}));
        // The dofs' own capacities are where the surface meets their axes.
        const PerDof<double> up = settings.yield_condition->axis_capacity(true);
        const PerDof<double> down = settings.yield_condition->axis_capacity(false);
        c.N = up[index(Dof::N)], c.N_neg = down[index(Dof::N)];
        c.Mx = up[index(Dof::Mx)], c.Mx_neg = down[index(Dof::Mx)];
        c.Mz = up[index(Dof::Mz)], c.Mz_neg = down[index(Dof::Mz)];
    }
    std::optional<PerDof<std::optional<double>>> stiffness;
    if (o.segment_length) stiffness = segment_stiffness(section, *o.segment_length);
    for (Dof dof : kAllDofs) {
        if (o.modes[index(dof)] != DofMode::Plastic) continue;
        DofLaw law;
        try {
            law = dof_law_from_section(dof, c);
        } catch (const InputError& e) {
            throw InputError(std::string("dof ") + dof_name(dof) + ": " + e.what());
        }
        if (stiffness) law.stiffness = (*stiffness)[index(dof)];
        settings.laws[index(dof)] = law;
    }
    if (o.segment_length) {
        if (const auto strain = smallest(section, [](const Material& m) { return m.ultimate_strain; }))
            settings.max_plastic_displacement = *strain * *o.segment_length;  // ε_u·L
    }
    if (const auto rotation = smallest(section, [](const Material& m) { return m.max_plastic_rotation; }))
        settings.max_plastic_rotation = *rotation;
    return settings;
}

}  // namespace plascap
