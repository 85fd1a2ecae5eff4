// cubature-report: sweeps the cubature route's tolerance, order and mesh size on six sections and
// writes, per capacity, the relative error against the exact route, the estimated error, the run
// time and the triangle count — with the mesh conforming to the kinks and without.
//   cubature-report --csv docs/cubature-report.csv --markdown docs/cubature-report.md [--plot-data F]
// scripts/cubature-report.sh runs it and draws the plot with gnuplot.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "plascap/input_error.hpp"
#include "plascap/sections/cubature.hpp"
#include "plascap/sections/shapes.hpp"

namespace {

using namespace plascap;

struct Case {
    std::string name;
    ValidSection section;
};

Part part(Ring outer, double fy, std::vector<Ring> holes = {}) { return Part{std::move(outer), std::move(holes), Material{"", fy}}; }

Section one_part(Part p) {
    Section s;
    s.parts.push_back(std::move(p));
    return s;
}

Ring box(double x0, double z0, double x1, double z1) { return {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}; }

std::vector<Case> report_cases() {
    constexpr double mm = 1e-3;
    const Ring tee = {{-5 * mm, 0}, {5 * mm, 0}, {5 * mm, 200 * mm}, {50 * mm, 200 * mm},
                      {50 * mm, 210 * mm}, {-50 * mm, 210 * mm}, {-50 * mm, 200 * mm}, {-5 * mm, 200 * mm}};
    // 310UB-type I: flanges 166 x 11.8, web 6.7, depth 304 (mm).
    const double b = 166 * mm, d = 304 * mm, tf = 11.8 * mm, tw = 6.7 * mm;
    const Ring i_section = {{-b / 2, -d / 2}, {b / 2, -d / 2}, {b / 2, -d / 2 + tf}, {tw / 2, -d / 2 + tf},
                            {tw / 2, d / 2 - tf}, {b / 2, d / 2 - tf}, {b / 2, d / 2}, {-b / 2, d / 2},
                            {-b / 2, d / 2 - tf}, {-tw / 2, d / 2 - tf}, {-tw / 2, -d / 2 + tf}, {-b / 2, -d / 2 + tf}};
    return {
        {"paper square 10 mm", validate_section(rectangle_section(0.01, 0.01, 200e6))},
        {"T 100x210 mm", validate_section(one_part(part(tee, 235e6)))},
        {"I 310UB-type", validate_section(one_part(part(i_section, 300e6)))},
        {"256-gon R 50 mm", validate_section(one_part(part(regular_polygon_ring(256, 0.05, 0.3), 235e6)))},
        {"strip 1:1000", validate_section(rectangle_section(1.0, 0.001, 235e6))},
        {"hollow rectangle", validate_section(one_part(part(box(-0.1, -0.05, 0.1, 0.05), 355e6, {box(-0.09, -0.04, 0.09, 0.04)})))},
    };
}

// Fastest of repeated runs (at least 3, and at least 20 ms in all): the cost without the noise.
double best_seconds(const std::function<void()>& run) {
    double best = 1e300, total = 0.0;
    for (int i = 0; i < 3 || (total < 0.02 && i < 10000); ++i) {
        const auto start = std::chrono::steady_clock::now();
        run();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::min(best, seconds);
        total += seconds;
    }
    return best;
}

struct Setting {
    std::string route;  // exact, adaptive, fixed
    CubatureOptions options;
    std::string mesh;   // "conforming", "ignores kinks", "" for exact
};

std::vector<Setting> settings(double area) {
    std::vector<Setting> out{{"exact", {}, ""}};
    for (bool conforming : {true, false}) {
        const std::string mesh = conforming ? "conforming" : "ignores kinks";
        for (double tolerance : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
            CubatureOptions o;
            o.tolerance = tolerance;
            o.conforming = conforming;
            out.push_back({"adaptive", o, mesh});
        }
        for (int order : {1, 2, 4, 8})
            for (double divisions : {0.0, 10.0, 100.0, 1000.0}) {
                CubatureOptions o;
                o.rule = CubatureRule::Fixed;
                o.order = order;
                o.max_area = divisions > 0.0 ? area / divisions : 0.0;
                o.conforming = conforming;
                out.push_back({"fixed", o, mesh});
            }
    }
    return out;
}

struct Row {
    std::string case_name, route, mesh;
    CubatureOptions options;
    std::size_t triangles = 0;
    double seconds = 0.0;
    std::vector<std::pair<Capacity, std::pair<double, double>>> errors;  // capacity → (relative error, estimated)
};

const std::vector<Capacity> kReported = {Capacity::N, Capacity::Qx, Capacity::Mx, Capacity::Mz, Capacity::My};

Row measure(const Case& c, const Setting& s, const Capacities& exact) {
    Row row{c.name, s.route, s.mesh, s.options, 0, 0.0, {}};
    if (s.route == "exact") {
        row.seconds = best_seconds([&] { compute_capacities(c.section); });
        for (Capacity k : kReported) row.errors.push_back({k, {0.0, 0.0}});
        return row;
    }
    const CubatureResult result = cubature_capacities(c.section, CapacitySet::all(), s.options);
    row.seconds = best_seconds([&] { cubature_capacities(c.section, CapacitySet::all(), s.options); });
    row.triangles = result.triangles;
    for (Capacity k : kReported) {
        const double reference = *exact.get(k);
        row.errors.push_back({k, {std::abs(*result.capacities.get(k) - reference) / reference,
                                  *result.estimated_error(k) / reference}});
    }
    return row;
}

std::string setting_text(const Row& r) {
    char text[96];
    if (r.route == "exact") return "closed forms";
    if (r.route == "adaptive") std::snprintf(text, sizeof text, "tol %.0e", r.options.tolerance);
    else if (r.options.max_area > 0.0) std::snprintf(text, sizeof text, "order %d, area ≤ %.2g m²", r.options.order, r.options.max_area);
    else std::snprintf(text, sizeof text, "order %d, no size bound", r.options.order);
    return text;
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
    std::ofstream out(path);
    out << "case,route,mesh,tolerance,order,max_area,capacity,relative_error,estimated_relative_error,seconds,triangles\n";
    for (const Row& r : rows)
        for (const auto& [k, e] : r.errors) {
            char line[512];
            std::snprintf(line, sizeof line, "\"%s\",%s,%s,%.3g,%d,%.6g,%s,%.6e,%.6e,%.6e,%zu\n", r.case_name.c_str(),
                          r.route.c_str(), r.mesh.c_str(), r.route == "adaptive" ? r.options.tolerance : 0.0,
                          r.route == "fixed" ? r.options.order : 0, r.options.max_area, to_string(k).c_str(), e.first,
                          e.second, r.seconds, r.triangles);
            out << line;
        }
    if (!out) throw InputError(path + ": cannot write the file");
}

std::string sci(double value) {
    if (value == 0.0) return "0";
    char text[32];
    std::snprintf(text, sizeof text, "%.1e", value);
    return text;
}

void write_markdown(const std::string& path, const std::vector<Row>& rows) {
    std::ofstream out(path);
    out << "<!-- Generated by scripts/cubature-report.sh (tools/cubature-report); do not edit by hand. -->\n"
        << "# Cubature route: error against run time\n\n"
        << "Relative error against the exact route, per capacity; `est` is the route's own estimate (relative). "
        << "`honest` says whether every estimate of the row is at least its actual error (a 1e-14 allowance covers "
           "the exact route's own round-off). Time: fastest of repeated runs, meshing included, one core. "
        << "Plot: [cubature-report.svg](cubature-report.svg); every number: [cubature-report.csv](cubature-report.csv).\n";
    std::string current;
    for (const Row& r : rows) {
        if (r.case_name != current) {
            current = r.case_name;
            out << "\n## " << current << "\n\n"
                << "| route | mesh | setting | triangles | time [µs] | N err | Mx err | Mz err | My err | My est | honest |\n"
                << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
        }
        double n = 0, mx = 0, mz = 0, my = 0, my_est = 0;
        bool honest = true;
        for (const auto& [k, e] : r.errors) {
            if (k == Capacity::N) n = e.first;
            if (k == Capacity::Mx) mx = e.first;
            if (k == Capacity::Mz) mz = e.first;
            if (k == Capacity::My) my = e.first, my_est = e.second;
            if (r.route != "exact" && e.first > e.second + 1e-14) honest = false;
        }
        char time[32];
        std::snprintf(time, sizeof time, "%.1f", r.seconds * 1e6);
        out << "| " << r.route << " | " << (r.mesh.empty() ? "—" : r.mesh) << " | " << setting_text(r) << " | "
            << (r.route == "exact" ? "—" : std::to_string(r.triangles)) << " | " << time << " | " << sci(n) << " | "
            << sci(mx) << " | " << sci(mz) << " | " << sci(my) << " | " << (r.route == "exact" ? "—" : sci(my_est))
            << " | " << (r.route == "exact" ? "—" : honest ? "yes" : "**no**") << " |\n";
        if (r.route == "exact" && r.case_name == "paper square 10 mm")
            out << "| Octave dblquad (the seed's baseline) | — | — | — | — | — | — | — | 7.1e-05 | — | — |\n";
    }
    if (!out) throw InputError(path + ": cannot write the file");
}

// For gnuplot: per case, five blocks (exact; adaptive and fixed, each conforming and ignoring the
// kinks) of "time [µs], worst relative error, worst estimate", blocks apart by two blank lines.
// A zero error is drawn at 1e-17, the floor of the plot.
void write_plot_data(const std::string& path, const std::vector<Row>& rows) {
    std::ofstream out(path);
    const std::pair<const char*, const char*> series[] = {
        {"exact", ""}, {"adaptive", "conforming"}, {"adaptive", "ignores kinks"}, {"fixed", "conforming"}, {"fixed", "ignores kinks"}};
    std::vector<std::string> cases;
    for (const Row& r : rows)
        if (std::find(cases.begin(), cases.end(), r.case_name) == cases.end()) cases.push_back(r.case_name);
    for (const std::string& name : cases)
        for (const auto& [route, mesh] : series) {
            out << "# " << name << ": " << route << " " << mesh << "\n";
            for (const Row& r : rows) {
                if (r.case_name != name || r.route != route || r.mesh != mesh) continue;
                double worst = 0.0, estimate = 0.0;
                for (const auto& [k, e] : r.errors) worst = std::max(worst, e.first), estimate = std::max(estimate, e.second);
                out << r.seconds * 1e6 << " " << std::max(worst, 1e-17) << " " << std::max(estimate, 1e-17) << "\n";
            }
            out << "\n\n";
        }
    if (!out) throw InputError(path + ": cannot write the file");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"cubature-report: error against run time of the cubature route, against the exact route"};
    std::string csv = "cubature-report.csv", markdown = "cubature-report.md", plot_data;
    app.add_option("--csv", csv, "Write every measurement here")->capture_default_str();
    app.add_option("--markdown", markdown, "Write the summary tables here")->capture_default_str();
    app.add_option("--plot-data", plot_data, "Also write the worst error per run for gnuplot here");
    CLI11_PARSE(app, argc, argv);
    try {
        std::vector<Row> rows;
        const std::vector<Case> cases = report_cases();
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const Case& c = cases[i];
            std::cerr << "cubature-report: [" << i + 1 << "/" << cases.size() << "] " << c.name << "\n";
            const Capacities exact = compute_capacities(c.section);
            for (const Setting& s : settings(exact.area)) rows.push_back(measure(c, s, exact));
        }
        write_csv(csv, rows);
        write_markdown(markdown, rows);
        if (!plot_data.empty()) write_plot_data(plot_data, rows);
        std::cerr << "cubature-report: wrote " << csv << " and " << markdown << "\n";
        return 0;
    } catch (const InputError& e) {
        std::cerr << "cubature-report: error: " << e.what() << "\n";
        return 2;
    }
}
