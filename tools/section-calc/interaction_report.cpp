#include "interaction_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "plascap/input_error.hpp"
#include "plascap/sections/interaction_curves.hpp"

namespace plascap::tools {
namespace {

std::string g10(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
}

double* component(SectionLoads& load, const std::string& name) {
    if (name == "N") return &load.N;
    if (name == "Mx") return &load.Mx;
    if (name == "Mz") return &load.Mz;
    if (name == "Qx") return &load.Qx;
    if (name == "Qz") return &load.Qz;
    if (name == "My") return &load.T;
    return nullptr;
}

nlohmann::ordered_json loads_json(const SectionLoads& l) {
    return {{"N", l.N}, {"Qx", l.Qx}, {"Qz", l.Qz}, {"Mx", l.Mx}, {"Mz", l.Mz}, {"My", l.T}};
}

SectionLoads scaled(const SectionLoads& l, double f) { return {l.N * f, l.Qx * f, l.Qz * f, l.Mx * f, l.Mz * f, l.T * f}; }

}  // namespace

SectionLoads parse_load(const std::string& text) {
    SectionLoads load;
    std::vector<std::string> seen;
    std::stringstream items(text);
    std::string item;
    if (text.empty()) throw InputError("--load: empty; give e.g. N=1e5,Mx=2e4 (N, Mx, Mz, Qx, Qz, My in N and N*m)");
    while (std::getline(items, item, ',')) {
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw InputError("--load: \"" + item + "\" is not NAME=VALUE (names: N, Mx, Mz, Qx, Qz, My)");
        const std::string name = item.substr(0, eq), value = item.substr(eq + 1);
        double* slot = component(load, name);
        if (!slot) throw InputError("--load: unknown component \"" + name + "\" (names: N, Mx, Mz, Qx, Qz, My)");
        if (std::find(seen.begin(), seen.end(), name) != seen.end())
            throw InputError("--load: " + name + " is given twice");
        seen.push_back(name);
        std::size_t used = 0;
        double v = 0.0;
        try {
            v = std::stod(value, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != value.size() || !std::isfinite(v))
            throw InputError("--load: " + name + " = \"" + value + "\" is not a finite number");
        *slot = v;
    }
    return load;
}

LoadCheck check_load(const SectionYield& yield, const SectionLoads& load, TorsionCapacity torsion) {
    LoadCheck c;
    c.load = load;
    c.state = yield.evaluate(load);
    c.nm_utilisation = c.state.nm_utilisation;
    c.share = c.state.shear_torsion_share;
    c.torsion = torsion;
    return c;
}

InteractionCurves sample_interaction(const YieldSurface& surface, double N, std::size_t samples) {
    InteractionCurves c;
    c.n_mx = n_mx_curve(surface, samples);
    c.n_mz = n_mz_curve(surface, samples);
    c.mx_mz_at = N;
    c.mx_mz = mx_mz_curve(surface, N, samples);
    const auto axis = [&](SectionResultant d) { return 1.0 / surface.utilisation(d); };
    c.box_positive = {axis({1, 0, 0}), axis({0, 1, 0}), axis({0, 0, 1})};
    c.box_negative = {axis({-1, 0, 0}), axis({0, -1, 0}), axis({0, 0, -1})};
    return c;
}

std::string load_check_text(const LoadCheck& c, const SectionYield& y) {
    std::ostringstream out;
    const ShearTorsionCapacities& st = y.shear_torsion();
    out << "\nLoad check (exact N-Mx-Mz surface; shear and torsion: U = sqrt(u_NM^2 + eta^2), docs/yield-surface.md)\n";
    out << "  load         N = " << g10(c.load.N) << " N, Mx = " << g10(c.load.Mx) << " N*m, Mz = " << g10(c.load.Mz)
        << " N*m, Qx = " << g10(c.load.Qx) << " N, Qz = " << g10(c.load.Qz) << " N, My = " << g10(c.load.T) << " N*m\n";
    out << "  utilisation  " << g10(c.state.utilisation) << (c.state.utilisation <= 1.0 ? "  (carried)" : "  (exceeds the capacity)")
        << "\n  N-M part     u_NM = " << g10(c.nm_utilisation) << "; shear/torsion share eta = " << g10(c.share)
        << " (Qxp = Qzp = " << g10(st.Qx) << " N";
    if (c.load.T != 0.0) out << ", torsion capacity " << torsion_capacity_name(c.torsion) << " " << g10(st.T) << " N*m";
    out << ")\n";
    if (std::isfinite(c.state.utilisation) && c.state.utilisation > 0.0) {
        const SectionLoads p = scaled(c.load, 1.0 / c.state.utilisation);
        out << "  governing point (load / U): N = " << g10(p.N) << " N, Mx = " << g10(p.Mx) << " N*m, Mz = " << g10(p.Mz)
            << " N*m, Qx = " << g10(p.Qx) << " N, Qz = " << g10(p.Qz) << " N, My = " << g10(p.T) << " N*m\n";
    }
    return out.str();
}

void add_load_check_json(nlohmann::ordered_json& out, const LoadCheck& c, const SectionYield& y) {
    out["utilisation"] = std::isfinite(c.state.utilisation) ? nlohmann::ordered_json(c.state.utilisation) : nlohmann::ordered_json("inf");
    nlohmann::ordered_json check;
    check["load"] = loads_json(c.load);
    check["nm_utilisation"] = c.nm_utilisation;
    check["shear_torsion_share"] = c.share;
    if (std::isfinite(c.state.utilisation) && c.state.utilisation > 0.0) {
        check["surface_point"] = loads_json(scaled(c.load, 1.0 / c.state.utilisation));
        check["normal"] = loads_json(c.state.gradient);  // ∂U/∂load [1/N, 1/(N·m)]
    }
    if (c.load.T != 0.0) check["torsion"] = {{"capacity", torsion_capacity_name(c.torsion)}, {"value", y.shear_torsion().T}};
    check["shear_capacity"] = y.shear_torsion().Qx;
    out["load_check"] = check;
}

std::string interaction_text(const InteractionCurves& c) {
    std::ostringstream out;
    const auto extreme = [](const std::vector<SectionResultant>& pts, double SectionResultant::*m, bool largest) {
        double best = 0.0;
        for (const auto& p : pts) best = largest ? std::max(best, p.*m) : std::min(best, p.*m);
        return best;
    };
    out << "\nInteraction (" << c.n_mx.size() << " exact points per curve; --json for them, --svg to draw them)\n";
    out << "  N-Mx:  Mx from " << g10(extreme(c.n_mx, &SectionResultant::Mx, false)) << " to "
        << g10(extreme(c.n_mx, &SectionResultant::Mx, true)) << " N*m, N from " << g10(extreme(c.n_mx, &SectionResultant::N, false))
        << " to " << g10(extreme(c.n_mx, &SectionResultant::N, true)) << " N\n";
    out << "  N-Mz:  Mz from " << g10(extreme(c.n_mz, &SectionResultant::Mz, false)) << " to "
        << g10(extreme(c.n_mz, &SectionResultant::Mz, true)) << " N*m\n";
    out << "  Mx-Mz at N = " << g10(c.mx_mz_at) << " N: Mx from " << g10(extreme(c.mx_mz, &SectionResultant::Mx, false)) << " to "
        << g10(extreme(c.mx_mz, &SectionResultant::Mx, true)) << " N*m\n";
    return out.str();
}

void add_interaction_json(nlohmann::ordered_json& out, const InteractionCurves& c) {
    nlohmann::ordered_json j;
    j["samples"] = c.n_mx.size();
    for (const auto& p : c.n_mx) j["N_Mx"].push_back({p.N, p.Mx});
    for (const auto& p : c.n_mz) j["N_Mz"].push_back({p.N, p.Mz});
    j["Mx_Mz"]["N"] = c.mx_mz_at;
    for (const auto& p : c.mx_mz) j["Mx_Mz"]["points"].push_back({p.Mx, p.Mz});
    out["interaction"] = j;
}

namespace {

// One diagram: a closed curve in (a, b), both axes through 0, the load's point if any.
// The box of independent limits: a from −a_neg to a_pos, b from −b_neg to b_pos.
struct Box {
    double a_neg, a_pos, b_neg, b_pos;
};

void draw_diagram(std::ostream& svg, double x0, double y0, double size, const std::vector<std::pair<double, double>>& curve,
                  const Box& box, std::optional<std::pair<double, double>> load, const std::string& a_name,
                  const std::string& b_name, const std::string& title) {
    double a_max = std::max(box.a_neg, box.a_pos), b_max = std::max(box.b_neg, box.b_pos);
    for (const auto& [a, b] : curve) a_max = std::max(a_max, std::abs(a)), b_max = std::max(b_max, std::abs(b));
    if (load) a_max = std::max(a_max, std::abs(load->first)), b_max = std::max(b_max, std::abs(load->second));
    a_max = a_max > 0 ? 1.1 * a_max : 1.0, b_max = b_max > 0 ? 1.1 * b_max : 1.0;
    const double half = size / 2, cx = x0 + half, cy = y0 + half + 20;
    const auto X = [&](double b) { return cx + b / b_max * half; };  // moments (or Mx) horizontal
    const auto Y = [&](double a) { return cy - a / a_max * half; };  // N (or Mz) vertical
    char line[400];
    svg << "<text x=\"" << x0 << "\" y=\"" << y0 + 12 << "\" font-weight=\"bold\">" << title << "</text>\n";
    std::snprintf(line, sizeof line,
                  "<path d=\"M%g,%g H%g M%g,%g V%g\" stroke=\"#999\" stroke-width=\"1\"/>\n", x0, cy, x0 + size, cx, cy - half, cy + half);
    svg << line;
    svg << "<text x=\"" << x0 + size - 40 << "\" y=\"" << cy - 6 << "\">" << b_name << "</text>\n";
    svg << "<text x=\"" << cx + 6 << "\" y=\"" << cy - half + 12 << "\">" << a_name << "</text>\n";
    std::snprintf(line, sizeof line, "<text x=\"%g\" y=\"%g\" font-size=\"11\" fill=\"#555\">%s: ±%.4g, %s: ±%.4g</text>\n", x0,
                  cy + half + 16, b_name.c_str(), b_max, a_name.c_str(), a_max);
    svg << line;
    svg << "<path d=\"";
    for (std::size_t i = 0; i < curve.size(); ++i) {
        std::snprintf(line, sizeof line, "%s%.2f,%.2f", i == 0 ? "M" : " L", X(curve[i].second), Y(curve[i].first));
        svg << line;
    }
    svg << " Z\" fill=\"#dbe8f5\" fill-opacity=\"0.6\" stroke=\"#1f5fa8\" stroke-width=\"2\"/>\n";
    std::snprintf(line, sizeof line,
                  "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"none\" stroke=\"#e08000\" "
                  "stroke-width=\"1.5\" stroke-dasharray=\"6,4\"/>\n",
                  X(-box.b_neg), Y(box.a_pos), X(box.b_pos) - X(-box.b_neg), Y(-box.a_neg) - Y(box.a_pos));
    svg << line;
    if (load) {
        std::snprintf(line, sizeof line,
                      "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"5\" fill=\"#d62728\" stroke=\"#000\" stroke-width=\"1\"/>\n",
                      X(load->second), Y(load->first));
        svg << line;
    }
}

}  // namespace

SvgPanel interaction_panels(const InteractionCurves& c, const std::optional<SectionLoads>& load) {
    constexpr double kSize = 300, kGap = 40;
    std::ostringstream svg;
    std::vector<std::pair<double, double>> nmx, nmz, mm;
    for (const auto& p : c.n_mx) nmx.push_back({p.N, p.Mx});
    for (const auto& p : c.n_mz) nmz.push_back({p.N, p.Mz});
    for (const auto& p : c.mx_mz) mm.push_back({p.Mz, p.Mx});
    std::optional<std::pair<double, double>> l1, l2, l3;
    if (load) l1 = {{load->N, load->Mx}}, l2 = {{load->N, load->Mz}}, l3 = {{load->Mz, load->Mx}};
    const SectionResultant &p = c.box_positive, &n = c.box_negative;
    draw_diagram(svg, kGap, 10, kSize, nmx, {n.N, p.N, n.Mx, p.Mx}, l1, "N [N]", "Mx [N*m]", "N-Mx (Mz = 0)");
    draw_diagram(svg, 2 * kGap + kSize, 10, kSize, nmz, {n.N, p.N, n.Mz, p.Mz}, l2, "N [N]", "Mz [N*m]", "N-Mz (Mx = 0)");
    char title[80];
    std::snprintf(title, sizeof title, "Mx-Mz at N = %.4g N", c.mx_mz_at);
    draw_diagram(svg, 3 * kGap + 2 * kSize, 10, kSize, mm, {n.Mz, p.Mz, n.Mx, p.Mx}, l3, "Mz [N*m]", "Mx [N*m]", title);
    svg << "<text x=\"" << kGap << "\" y=\"" << kSize + 80 << "\" font-size=\"11\" fill=\"#555\">blue: exact fully plastic surface "
        << "(stress blocks over the polygons); orange dashed: the paper's independent limits (the box); red: the load's "
        << "components in each plane</text>\n";
    return {svg.str(), 3 * kSize + 4 * kGap, kSize + 95};
}

}  // namespace plascap::tools
