// section-calc: the plastic capacities of a cross section (docs/section-format.md, README).
// Exit codes: 0 success, 2 bad input (one message on stderr), 1 internal failure.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "capacity_report.hpp"
#include "interaction_report.hpp"
#include "material_listing.hpp"
#include "section_page.hpp"
#include "section_svg.hpp"
#include "shape_listing.hpp"
#include "plascap/input_error.hpp"
#include "tool_main.hpp"
#include "plascap/materials/catalogue.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/cubature.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/joint_stiffness.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/torsion_constant.hpp"
#include "plascap/sections/section_json.hpp"
#include "plascap/sections/shape_designation.hpp"
#include "plascap/sections/shape_table.hpp"
#include "plascap/sections/shapes.hpp"
#include <unistd.h>

namespace {

struct Options {
    std::string file;
    std::vector<double> rect;
    std::string shape;
    std::optional<double> arc_tolerance;
    std::optional<std::string> list_shapes;  // "" for every family
    std::string table;
    bool csv = false;
    bool skip_torsion = false;
    std::optional<double> fy;
    std::optional<std::string> shear;
    std::vector<double> reference;
    std::string only;
    std::string method = "exact";
    std::optional<double> tolerance;
    std::optional<int> order;
    std::optional<double> max_area;
    std::string svg;
    std::string html;
    std::string material;
    std::vector<std::string> material_files;
    bool list_materials = false;
    bool elastic = false;
    std::optional<double> length;
    bool json = false;
    std::string load;
    bool interaction = false;
    std::size_t samples = 72;
    std::string torsion = "fully-plastic";
};

void add_options(CLI::App& app, Options& o) {
    app.add_option("FILE", o.file, "Section file (JSON, format in docs/section-format.md); - reads standard input");
    app.add_option("--rect", o.rect, "Shortcut: a centred rectangle, B along x and H along z [m]")->expected(2);
    app.add_option("--shape", o.shape, "Instead of FILE: a standard shape by name, e.g. \"IPE 300\", \"HE 200 B\", "
                                       "\"CHS 168.3x8\", or parametric, e.g. \"I 300x150x7.1x10.7 r15\" (docs/shapes.md); "
                                       "depth h along z, width b along x, so Mx is the strong-axis (EN y-y) moment");
    app.add_option("--arc-tolerance", o.arc_tolerance, "With --shape or --table: largest area the chords of all arcs "
                                                       "together may miss, relative to the section's area, 1e-12 to 1e-2 "
                                                       "(default 1e-6)");
    app.add_option("--list-shapes", o.list_shapes, "Print the shape catalogue, or one FAMILY of it (with --json: "
                                                   "geometry, published values and sources)")
        ->expected(0, 1)
        ->default_str("");
    app.add_option("--table", o.table, "One row per catalogue shape of FAMILY (or several, comma-separated, or all): "
                                       "A, Ixx, Izz, Wel, Wpl, J, T_p "
                                       "and every capacity, on all cores; material from --material or --fy "
                                       "(default S355)");
    app.add_flag("--csv", o.csv, "With --table: comma-separated values instead of the table");
    app.add_flag("--skip-torsion", o.skip_torsion, "With --table: leave out J and T_p (the costly columns)");
    app.add_option("--fy", o.fy, "Yield stress [Pa] of the --rect or --shape section (or of the --table shapes)");
    app.add_option("--material", o.material, "Catalogue material for every part (or the --rect section), e.g. S355; "
                                             "overrides the file");
    app.add_option("--materials", o.material_files, "Add a materials file (format: docs/materials.md) to the catalogue; "
                                                    "may be given more than once, later files replace same-named entries");
    app.add_flag("--list-materials", o.list_materials, "Print the materials catalogue (with --json: every value and its source)");
    app.add_option("--shear", o.shear, "Shear criterion: tresca (τy = fy/2) or von-mises (τy = fy/√3); overrides the file");
    app.add_option("--reference", o.reference, "Joint point X Z [m] for My; overrides the file (default: centroid)")
        ->expected(2);
    app.add_option("--only", o.only, "Compute only these capacities, e.g. N,My (from N, Qx, Qz, Mx, Mz, My)");
    app.add_option("--method", o.method,
                   "Integration route: exact (closed forms over the polygons) or cubature (CGAL mesh + GSL cubature, "
                   "with error estimates)")
        ->capture_default_str();
    app.add_option("--tol", o.tolerance, "cubature: adaptive rule to this relative tolerance per triangle, 1e-13 to 0.1 "
                                         "(default 1e-10)");
    app.add_option("--order", o.order, "cubature: fixed Gauss–Legendre rule with this many points per direction, 1 to 100, "
                                       "instead of the adaptive rule");
    app.add_option("--max-area", o.max_area, "cubature: largest triangle area [m²] (default: no bound, the "
                                             "constrained triangulation as it is)");
    app.add_option("--svg", o.svg, "Also draw the section, its mesh, neutral axes, centroid and joint point to this SVG file");
    app.add_option("--html", o.html, "Also write a self-contained page: the drawing, the capacity table and (exact route) the "
                                     "N-Mx, N-Mz and Mx-Mz interaction diagrams of the exact surface (docs/replay.md)");
    app.add_flag("--elastic", o.elastic, "Add the elastic properties: Ixx, Izz, Ixz, principal axes, moduli, radii of gyration, "
                                         "and EA, EI (modulus weighted) when every material gives E");
    app.add_option("--length", o.length, "With --elastic: the joint stiffness of a segment of this length [m]: EA/L, EI/L, "
                                         "12EI/L³, GJ/L");
    app.add_option("--load", o.load, "Check a load on the exact yield surface: N=..,Mx=..,Mz=..[,Qx=..,Qz=..,My=..] in N and "
                                     "N*m (omitted components are 0; N tension positive, Mx and Mz in the senses of the "
                                     "capacities, about the joint point); prints the utilisation and the governing point "
                                     "(docs/yield-surface.md)");
    app.add_flag("--interaction", o.interaction, "Sample the N-Mx, N-Mz and Mx-Mz (at the load's N, else 0) curves of the "
                                                 "exact surface: into the JSON, and as diagrams into the --svg file");
    app.add_option("--samples", o.samples, "With --interaction or --html: points per curve, 8 to 100000")->capture_default_str();
    app.add_option("--torsion", o.torsion, "With --load: the torsion capacity for My: fully-plastic (T_p, the sand heap) or "
                                           "paper (eq. 2.14)")
        ->capture_default_str();
    app.add_flag("--json", o.json, "Print one JSON object instead of the table");
    app.set_version_flag("--version", "section-calc (plascap) " PLASCAP_VERSION);
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

void require_positive(double value, const std::string& what) {
    if (!std::isfinite(value) || value <= 0.0)
        throw plascap::InputError(what + " must be a positive finite number (got " + number(value) + ")");
}

// The built-in catalogue plus the --materials files.
plascap::MaterialCatalogue load_catalogue(const Options& o) {
    plascap::MaterialCatalogue catalogue = plascap::MaterialCatalogue::built_in();
    for (const std::string& file : o.material_files) catalogue.add(plascap::MaterialCatalogue::read_file(file));
    return catalogue;
}

plascap::ShapeOptions shape_options(const Options& o) {
    plascap::ShapeOptions options;
    if (o.arc_tolerance) options.area_tolerance = *o.arc_tolerance;
    plascap::validate_shape_options(options);
    return options;
}

plascap::Section load_section(const Options& o, const plascap::MaterialCatalogue& catalogue, std::string& source) {
    const int sources = !o.file.empty() + !o.rect.empty() + !o.shape.empty();
    if (sources > 1) throw plascap::InputError("give one of FILE, --rect B H and --shape NAME, not several");
    if (sources == 0)
        throw plascap::InputError("no section: give FILE, --rect B H --fy FY or --shape NAME --material M (see --help)");
    if (o.arc_tolerance && o.shape.empty()) throw plascap::InputError("--arc-tolerance goes with --shape or --table");
    if (!o.shape.empty()) {
        if (!o.fy && o.material.empty())
            throw plascap::InputError("--shape needs --material NAME (e.g. S355) or --fy FY, the yield stress in Pa");
        if (o.fy && !o.material.empty()) throw plascap::InputError("give --fy or --material, not both");
        if (o.fy) require_positive(*o.fy, "--fy");
        source = "--shape " + o.shape;
        return plascap::shape_section(o.shape, plascap::Material{"", o.fy.value_or(1.0)}, shape_options(o));  // --material replaces it
    }
    if (!o.rect.empty()) {
        if (!o.fy && o.material.empty())
            throw plascap::InputError("--rect needs --fy FY, the yield stress in Pa, or --material NAME");
        if (o.fy && !o.material.empty()) throw plascap::InputError("give --fy or --material, not both");
        require_positive(o.rect[0], "--rect: width B [m]");
        require_positive(o.rect[1], "--rect: height H [m]");
        source = "--rect " + number(o.rect[0]) + " x " + number(o.rect[1]) + " m";
        return plascap::rectangle_section(o.rect[0], o.rect[1], o.fy.value_or(1.0));  // --material replaces it
    }
    if (o.fy) throw plascap::InputError("--fy goes with --rect or --shape; a section file gives its own materials (or use --material)");
    source = o.file == "-" ? "standard input" : o.file;
    if (o.file != "-") return plascap::read_section_file(o.file, catalogue);
    std::ostringstream text;
    text << std::cin.rdbuf();
    try {
        return plascap::parse_section_json(text.str(), catalogue);
    } catch (const plascap::InputError& e) {
        throw plascap::InputError(source + ": " + e.what());
    }
}

// validate_section, with the file named in front of its message.
plascap::ValidSection validated(const plascap::Section& section, const std::string& file) {
    try {
        return plascap::validate_section(section);
    } catch (const plascap::InputError& e) {
        if (file.empty()) throw;
        throw plascap::InputError(file + ": " + e.what());
    }
}

// The cubature options from the command line; refuses them with --method exact.
plascap::CubatureOptions cubature_options(const Options& o) {
    if (o.method != "cubature") {
        if (o.tolerance || o.order || o.max_area)
            throw plascap::InputError("--tol, --order and --max-area go with --method cubature");
        return {};
    }
    if (o.tolerance && o.order)
        throw plascap::InputError("give --tol (adaptive rule) or --order (fixed rule), not both");
    plascap::CubatureOptions options;
    if (o.tolerance) options.tolerance = *o.tolerance;
    if (o.order) {
        options.rule = plascap::CubatureRule::Fixed;
        options.order = *o.order;
    }
    if (o.max_area) options.max_area = *o.max_area;
    plascap::validate_cubature_options(options);
    return options;
}

// The progress of a long table on standard error: a line rewritten in place on a terminal, else a
// line every 2 s.
class Progress {
public:
    void operator()(std::size_t done, std::size_t total) {
        const auto now = std::chrono::steady_clock::now();
        if (done < total && now - last_ < std::chrono::seconds(terminal_ ? 0 : 2)) return;
        last_ = now;
        std::fprintf(stderr, terminal_ ? "\rsection-calc: %zu of %zu shapes" : "section-calc: %zu of %zu shapes\n", done, total);
        if (terminal_ && done == total) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    bool terminal_ = isatty(2) != 0;
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

int run_table(const Options& o, const plascap::MaterialCatalogue& catalogue, const plascap::ShapeCatalogue& shapes) {
    if (!o.file.empty() || !o.rect.empty() || !o.shape.empty())
        throw plascap::InputError("--table computes catalogue shapes: give no FILE, --rect or --shape with it");
    if (o.method != "exact" || !o.only.empty() || o.elastic || !o.svg.empty() || !o.html.empty() || o.shear || !o.reference.empty())
        throw plascap::InputError("--table goes with --material or --fy, --arc-tolerance, --csv or --json and --skip-torsion only");
    if (o.csv && o.json) throw plascap::InputError("give --csv or --json, not both");
    if (o.fy && !o.material.empty()) throw plascap::InputError("give --fy or --material, not both");
    plascap::Material material = o.material.empty() ? catalogue.get("S355", "--table default material") : catalogue.get(o.material, "--material");
    if (o.fy) {
        require_positive(*o.fy, "--fy");
        material = plascap::Material{"", *o.fy};
    }
    plascap::ShapeTableOptions options;
    options.shape = shape_options(o);
    options.torsion = !o.skip_torsion;
    Progress progress;
    options.progress = [&progress](std::size_t done, std::size_t total) { progress(done, total); };
    const std::vector<const plascap::CatalogueShape*> rows = plascap::tools::shapes_of(shapes, o.table);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<plascap::ShapeTableRow> table = plascap::shape_table(rows, material, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto format = o.csv ? plascap::tools::TableFormat::Csv : o.json ? plascap::tools::TableFormat::Json : plascap::tools::TableFormat::Text;
    std::cout << plascap::tools::shape_table_text(table, material, format, seconds);
    return 0;
}

// What --load and --interaction ask for.
struct YieldReport {
    std::optional<plascap::SectionLoads> load;
    std::optional<plascap::SectionYield> condition;
    std::optional<plascap::tools::LoadCheck> check;
    std::optional<plascap::tools::InteractionCurves> curves;
};

YieldReport yield_report(const Options& o, const plascap::ValidSection& valid) {
    YieldReport r;
    const plascap::TorsionCapacity torsion = plascap::torsion_capacity_from_name(o.torsion, "--torsion");
    if (o.load.empty() && o.torsion != "fully-plastic") throw plascap::InputError("--torsion goes with --load");
    if (!o.interaction && o.html.empty() && o.samples != 72) throw plascap::InputError("--samples goes with --interaction or --html");
    if (o.load.empty() && !o.interaction) return r;
    if (o.method != "exact") throw plascap::InputError("--load and --interaction use the exact surface: leave out --method cubature");
    if (!o.load.empty()) {
        r.load = plascap::tools::parse_load(o.load);
        // T_p costs a mesh integration: only when the load twists.
        const plascap::TorsionCapacity used = r.load->T != 0.0 ? torsion : plascap::TorsionCapacity::Paper;
        r.condition = plascap::section_yield(valid, used);
        r.check = plascap::tools::check_load(*r.condition, *r.load, used);
    }
    if (o.interaction) {
        const plascap::YieldSurface surface(valid);
        r.curves = plascap::tools::sample_interaction(surface, r.load ? r.load->N : 0.0, o.samples);
    }
    return r;
}

// The --json object: the capacities and what was asked besides (the load's check, the curves).
nlohmann::ordered_json report_json(const plascap::Capacities& capacities, const plascap::tools::ReportContext& context,
                                   const YieldReport& yield, const plascap::tools::InteractionCurves* curves) {
    nlohmann::ordered_json out = plascap::tools::capacity_json_value(capacities, context);
    if (yield.check) plascap::tools::add_load_check_json(out, *yield.check, *yield.condition);
    if (curves) plascap::tools::add_interaction_json(out, *curves);
    return out;
}

// --html: the page shows the interaction diagrams whenever the exact surface is at hand.
void write_html(const Options& o, const plascap::ValidSection& valid, const plascap::Capacities& capacities,
                const plascap::tools::ReportContext& context, const YieldReport& yield, double max_area) {
    std::optional<plascap::tools::InteractionCurves> curves = yield.curves;
    std::string note;
    if (!curves && o.method == "exact") {
        curves = plascap::tools::sample_interaction(plascap::YieldSurface(valid), yield.load ? yield.load->N : 0.0, o.samples);
    } else if (!curves) {
        note = "The interaction diagrams come from the exact surface: run without --method cubature to see them.";
    }
    plascap::tools::write_section_page(o.html, context.source, report_json(capacities, context, yield, curves ? &*curves : nullptr),
                                       plascap::tools::section_svg(valid, capacities, max_area, context.source), note);
}

int run(const Options& o) {
    if (o.method != "exact" && o.method != "cubature")
        throw plascap::InputError("--method " + o.method + ": unknown method (available: exact, cubature)");
    const plascap::CubatureOptions cubature = cubature_options(o);
    const plascap::CapacitySet wanted =
        o.only.empty() ? plascap::CapacitySet::all() : plascap::CapacitySet::parse(o.only);
    const plascap::MaterialCatalogue catalogue = load_catalogue(o);
    if (o.list_materials) {
        std::cout << (o.json ? plascap::tools::material_json(catalogue) : plascap::tools::material_table(catalogue));
        return 0;
    }
    if (o.csv && o.table.empty()) throw plascap::InputError("--csv goes with --table");
    if (o.skip_torsion && o.table.empty()) throw plascap::InputError("--skip-torsion goes with --table");
    const plascap::ShapeCatalogue& shapes = plascap::ShapeCatalogue::built_in();
    if (o.list_shapes) {
        std::cout << (o.json ? plascap::tools::shape_list_json(shapes, *o.list_shapes)
                             : plascap::tools::shape_list(shapes, *o.list_shapes));
        return 0;
    }
    if (!o.table.empty()) return run_table(o, catalogue, shapes);
    std::string source;
    plascap::Section section = load_section(o, catalogue, source);
    if (!o.material.empty()) {
        const plascap::Material& material = catalogue.get(o.material, "--material");
        for (plascap::Part& part : section.parts) part.material = material;
    }
    if (o.shear) section.shear = plascap::parse_shear_criterion(*o.shear);
    if (!o.reference.empty()) section.reference = plascap::Point{o.reference[0], o.reference[1]};

    const plascap::ValidSection valid = validated(section, o.file.empty() ? (o.shape.empty() ? "" : source) : source);
    plascap::tools::ReportContext context{source, o.method, &valid};
    std::optional<plascap::CubatureResult> cubature_result;
    if (o.method == "cubature") {
        cubature_result = plascap::cubature_capacities(valid, wanted, cubature);
        context.cubature_options = &cubature;
        context.cubature = &*cubature_result;
    }
    const plascap::Capacities capacities =
        cubature_result ? cubature_result->capacities : plascap::compute_capacities(valid, wanted);
    std::optional<plascap::ElasticProperties> elastic;
    std::optional<plascap::TorsionConstant> torsion;
    std::optional<plascap::PlasticTorsion> plastic_torsion;
    std::optional<plascap::JointStiffness> joint;
    if (o.length && !o.elastic) throw plascap::InputError("--length goes with --elastic");
    if (o.elastic) {
        elastic = plascap::elastic_properties(valid);
        torsion = plascap::saint_venant_torsion(valid);
        plastic_torsion = plascap::plastic_torsion(valid);
        context.elastic = &*elastic;
        context.torsion = &*torsion;
        context.plastic_torsion = &*plastic_torsion;
        if (o.length) {
            if (!elastic->stiffness) throw plascap::InputError("--length: the joint stiffness needs E for every material");
            joint = plascap::joint_stiffness(*elastic->stiffness, torsion->GJ, *o.length);
            context.joint = &*joint;
            context.length = *o.length;
        }
    }
    const YieldReport yield = yield_report(o, valid);
    std::optional<plascap::tools::SvgPanel> panels;
    if (yield.curves) panels = plascap::tools::interaction_panels(*yield.curves, yield.load);
    if (!o.svg.empty())
        plascap::tools::write_section_svg(o.svg, valid, capacities, cubature.max_area, source, panels ? &*panels : nullptr);
    if (!o.html.empty()) write_html(o, valid, capacities, context, yield, cubature.max_area);
    if (o.json) {
        std::cout << report_json(capacities, context, yield, yield.curves ? &*yield.curves : nullptr).dump(2) << "\n";
        return 0;
    }
    std::cout << plascap::tools::capacity_table(capacities, context);
    if (yield.check) std::cout << plascap::tools::load_check_text(*yield.check, *yield.condition);
    if (yield.curves) std::cout << plascap::tools::interaction_text(*yield.curves);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"section-calc: plastic capacities N, Qx, Qz, Mx, Mz, My of a polygon cross section or a standard "
                 "shape. The section lies in the x-z plane, the beam axis is y; shapes have their depth h along z and "
                 "their width b along x, so Mx is the strong-axis (EN y-y) and Mz the weak-axis (EN z-z) moment."};
    Options options;
    add_options(app, options);
    return plascap::tool_main("section-calc", app, argc, argv, [&] { return run(options); });
}
