#include "capacity_report.hpp"
#include "text_columns.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

namespace plascap::tools {
namespace {

struct Row {
    Capacity capacity;
    const char* meaning;
    const char* unit;
};

constexpr Row kRows[] = {
    {Capacity::N, "axial force along y (eq. 2.10)", "N"},
    {Capacity::Qx, "shear force along x (eq. 2.11)", "N"},
    {Capacity::Qz, "shear force along z (eq. 2.11)", "N"},
    {Capacity::Mx, "bending about x (eq. 2.12)", "N·m"},
    {Capacity::Mz, "bending about z (eq. 2.13)", "N·m"},
    {Capacity::My, "torsion about y (eq. 2.14)", "N·m"},
    {Capacity::N_neg, "axial force, compression (fc)", "N"},
    {Capacity::Mx_neg, "bending about x, tension above its axis", "N·m"},
    {Capacity::Mz_neg, "bending about z, tension at smaller x", "N·m"},
};

// The counterpart of a _neg capacity: with fc = fy the two are equal and the table shows one.
std::optional<Capacity> counterpart(Capacity c) {
    if (c == Capacity::N_neg) return Capacity::N;
    if (c == Capacity::Mx_neg) return Capacity::Mx;
    if (c == Capacity::Mz_neg) return Capacity::Mz;
    return std::nullopt;
}

std::string format(const char* pattern, double a) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, a);
    return buffer;
}

std::string format(const char* pattern, double a, double b) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, pattern, a, b);
    return buffer;
}

std::string shear_rule(ShearCriterion shear) {
    return shear == ShearCriterion::Tresca ? "Tresca, τy = fy/2" : "von Mises, τy = fy/√3";
}

std::string method_line(const ReportContext& context) {
    if (!context.cubature_options) return context.method + " (closed forms over the polygons)";
    const CubatureOptions& o = *context.cubature_options;
    std::string text = o.rule == CubatureRule::Adaptive ? format("cubature, adaptive to %.3g relative", o.tolerance)
                                                        : format("cubature, Gauss–Legendre %g × %g per triangle", o.order, o.order);
    if (o.max_area > 0.0) text += format(", triangles ≤ %.3g m²", o.max_area);
    return text;
}

std::string elastic_block(const ElasticProperties& e) {
    std::ostringstream out;
    out << "\nelastic     " << format("Ixx = %.10g m⁴, Izz = %.10g m⁴", e.Ixx, e.Izz) << format(", Ixz = %.10g m⁴", e.Ixz) << "\n"
        << "            " << format("I1 = %.10g m⁴, I2 = %.10g m⁴", e.I1, e.I2)
        << format(", I1's axis at %.6g° from x towards z", e.principal_angle * 180.0 / 3.141592653589793) << "\n"
        << "            " << format("Wx = %.10g m³, Wz = %.10g m³ (extreme fibre)", e.Wx, e.Wz) << "\n"
        << "            " << format("rx = %.10g m, rz = %.10g m", e.rx, e.rz) << "\n";
    if (e.stiffness)
        out << "stiffness   " << format("EA = %.10g N, EIxx = %.10g N·m²", e.stiffness->EA, e.stiffness->EIxx)
            << format(", EIzz = %.10g N·m², EIxz = %.10g N·m²", e.stiffness->EIzz, e.stiffness->EIxz) << "\n"
            << "            " << format("modulus weighted, about x = %.10g m, z = %.10g m", e.stiffness->centroid.x, e.stiffness->centroid.z) << "\n";
    else
        out << "stiffness   not available: a material gives no E\n";
    return out.str();
}

std::string torsion_block(const TorsionConstant& t, const PlasticTorsion& tp, std::optional<double> My) {
    std::ostringstream out;
    out << "torsion     " << format("J = %.10g m⁴ (± %.2g, Saint-Venant, FEM)", t.J, t.error);
    if (t.GJ) out << format(", GJ = %.10g N·m²", *t.GJ);
    out << "\n            " << format("T_p = %.10g N·m (± %.2g, fully plastic, sand heap)", tp.T, tp.error);
    if (My) out << format("; the paper's My/T_p = %.4f", *My / tp.T);
    out << "\n";
    return out.str();
}

std::string joint_block(const JointStiffness& k, double length) {
    std::ostringstream out;
    out << "joint       " << format("a segment of L = %g m: EA/L = %.6g N/m", length, k.axial)
        << format(", EIxx/L = %.6g, EIzz/L = %.6g N·m/rad", k.bending_x, k.bending_z) << "\n"
        << "            " << format("12EI/L³ = %.6g (along x), %.6g N/m (along z)", k.shear_x, k.shear_z);
    if (k.torsion) out << format(", GJ/L = %.6g N·m/rad", *k.torsion);
    out << "\n";
    return out.str();
}

void add_elastic(nlohmann::ordered_json& out, const ElasticProperties& e) {
    out["Ixx"] = e.Ixx, out["Izz"] = e.Izz, out["Ixz"] = e.Ixz;
    out["I1"] = e.I1, out["I2"] = e.I2, out["principal_angle"] = e.principal_angle;
    out["Wx"] = e.Wx, out["Wz"] = e.Wz, out["rx"] = e.rx, out["rz"] = e.rz;
    if (!e.stiffness) return;
    out["EA"] = e.stiffness->EA, out["EIxx"] = e.stiffness->EIxx, out["EIzz"] = e.stiffness->EIzz, out["EIxz"] = e.stiffness->EIxz;
    out["stiffness_centroid"] = {e.stiffness->centroid.x, e.stiffness->centroid.z};
}

}  // namespace

std::string capacity_table(const Capacities& c, const ReportContext& context) {
    std::ostringstream out;
    std::size_t holes = 0;
    for (const Part& part : context.section->parts()) holes += part.holes.size();
    out << "section     " << context.source << "\n"
        << "            " << context.section->parts().size() << " part(s), " << holes << " hole(s), "
        << context.section->vertex_count() << " vertices\n"
        << "method      " << method_line(context) << "\n"
        << "shear       " << shear_rule(c.shear) << "\n"
        << "area        " << format("%.10g m²", c.area) << "\n"
        << "centroid    " << format("x = %.10g m, z = %.10g m", c.centroid.x, c.centroid.z) << "\n";
    if (c.z_pna) out << "Mx axis     " << format("z = %.10g m (plastic neutral axis, equal force)", *c.z_pna) << "\n";
    if (c.x_pna) out << "Mz axis     " << format("x = %.10g m (plastic neutral axis, equal force)", *c.x_pna) << "\n";
    if (c.z_pna_neg && c.z_pna_neg != c.z_pna)
        out << "Mx_neg axis " << format("z = %.10g m (equal force, tension above)", *c.z_pna_neg) << "\n";
    if (c.x_pna_neg && c.x_pna_neg != c.x_pna)
        out << "Mz_neg axis " << format("x = %.10g m (equal force, tension at smaller x)", *c.x_pna_neg) << "\n";
    if (c.reference) out << "joint point " << format("x = %.10g m, z = %.10g m (My)", c.reference->x, c.reference->z) << "\n";
    if (context.cubature)
        out << "mesh        " << context.cubature->triangles << " triangles, " << context.cubature->evaluations
            << " integrand evaluations, " << format("%.3g ms", context.cubature->seconds * 1e3) << "\n";
    if (context.cubature && context.cubature->refinement_stopped)
        out << "            refinement stopped at its vertex budget (a feature or angle too small to resolve):\n"
            << "            some triangles miss the shape/size bounds, and the fixed rule's estimates may be low\n";
    out << "\n  capacity  value              " << (context.cubature ? "± estimated error  " : "") << "unit  meaning\n";
    for (const Row& row : kRows) {
        const std::optional<double> value = c.get(row.capacity);
        if (!value) continue;
        const std::optional<Capacity> twin = counterpart(row.capacity);
        if (twin && c.get(*twin) == value) continue;  // fc = fy: the same number again
        char line[200];
        const std::string error = context.cubature ? format("± %-16.2e ", *context.cubature->estimated_error(row.capacity)) : "";
        std::snprintf(line, sizeof line, "  %-8s  %-17.10g  %s%s  %s\n", to_string(row.capacity).c_str(), *value,
                      error.c_str(), padded(row.unit, 4).c_str(), row.meaning);
        out << line;
    }
    if (context.elastic) out << elastic_block(*context.elastic);
    if (context.torsion && context.plastic_torsion) out << torsion_block(*context.torsion, *context.plastic_torsion, c.My);
    if (context.joint) out << joint_block(*context.joint, context.length);
    return out.str();
}

std::string capacity_json(const Capacities& c, const ReportContext& context) { return capacity_json_value(c, context).dump(2) + "\n"; }

nlohmann::ordered_json capacity_json_value(const Capacities& c, const ReportContext& context) {
    nlohmann::ordered_json out;
    for (Capacity capacity : kAllCapacities)
        if (const std::optional<double> value = c.get(capacity)) out[to_string(capacity)] = *value;
    out["area"] = c.area;
    out["centroid"] = {c.centroid.x, c.centroid.z};
    if (c.z_pna) out["z_pna"] = *c.z_pna;
    if (c.x_pna) out["x_pna"] = *c.x_pna;
    if (c.z_pna_neg) out["z_pna_neg"] = *c.z_pna_neg;
    if (c.x_pna_neg) out["x_pna_neg"] = *c.x_pna_neg;
    if (c.reference) out["reference"] = {c.reference->x, c.reference->z};
    if (context.elastic) add_elastic(out, *context.elastic);
    if (context.torsion) {
        out["J"] = context.torsion->J, out["J_error"] = context.torsion->error;
        if (context.torsion->GJ) out["GJ"] = *context.torsion->GJ;
    }
    if (context.plastic_torsion) {
        out["My_plastic_torsion"] = context.plastic_torsion->T;
        out["My_plastic_torsion_error"] = context.plastic_torsion->error;
    }
    if (context.joint) {
        out["joint"] = {{"length", context.length}, {"axial", context.joint->axial}, {"shear_x", context.joint->shear_x},
                        {"shear_z", context.joint->shear_z}, {"bending_x", context.joint->bending_x},
                        {"bending_z", context.joint->bending_z}};
        if (context.joint->torsion) out["joint"]["torsion"] = *context.joint->torsion;
    }
    out["shear"] = to_string(c.shear);
    out["method"] = context.method;
    if (context.cubature) {
        const CubatureOptions& o = *context.cubature_options;
        nlohmann::ordered_json errors;
        for (Capacity capacity : kAllCapacities)
            if (const std::optional<double> e = context.cubature->estimated_error(capacity)) errors[to_string(capacity)] = *e;
        out["errors"] = errors;  // estimated absolute error of each capacity, same units
        out["triangles"] = context.cubature->triangles;
        out["evaluations"] = context.cubature->evaluations;
        out["seconds"] = context.cubature->seconds;
        out["refinement_stopped"] = context.cubature->refinement_stopped;
        out["cubature"] = {{"rule", o.rule == CubatureRule::Adaptive ? "adaptive" : "fixed"}};
        if (o.rule == CubatureRule::Adaptive) out["cubature"]["tolerance"] = o.tolerance;
        else out["cubature"]["order"] = o.order;
        out["cubature"]["max_area"] = o.max_area;
    }
    out["parts"] = context.section->parts().size();
    out["vertices"] = context.section->vertex_count();
    out["units"] = {{"force", "N"}, {"moment", "N*m"}, {"length", "m"}, {"area", "m^2"}};
    return out;
}

}  // namespace plascap::tools
