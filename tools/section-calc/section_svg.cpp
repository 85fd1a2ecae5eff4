#include "section_svg.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "plascap/input_error.hpp"
#include "plascap/sections/ring_integrals.hpp"
#include "plascap/sections/section_mesh.hpp"

namespace plascap::tools {
namespace {

constexpr double kDrawing = 800.0;          // px for the section's larger side
constexpr double kMargin = 70.0;            // px around it
constexpr std::size_t kMostTriangles = 20000;  // beyond this the mesh is only counted

std::string escaped(const std::string& text) {
    std::string out;
    for (char ch : text) {
        if (ch == '<') out += "&lt;";
        else if (ch == '>') out += "&gt;";
        else if (ch == '&') out += "&amp;";
        else if (ch == '"') out += "&quot;";
        else out += ch;
    }
    return out;
}

std::string length_text(double metres) {
    char text[48];
    if (metres >= 1.0) std::snprintf(text, sizeof text, "%g m", metres);
    else if (metres >= 1e-3) std::snprintf(text, sizeof text, "%g mm", metres * 1e3);
    else std::snprintf(text, sizeof text, "%g µm", metres * 1e6);
    return text;
}

// 1, 2 or 5 times a power of ten, at most `limit`.
double round_length(double limit) {
    const double decade = std::pow(10.0, std::floor(std::log10(limit)));
    for (double step : {5.0, 2.0, 1.0})
        if (step * decade <= limit) return step * decade;
    return decade;
}

// Maps section coordinates (m, z up) to SVG pixels (y down).
class Canvas {
public:
    explicit Canvas(const ValidSection& section) {
        for (const Part& part : section.parts())
            for (Point local : part.outer) {
                const Point p = section.to_section(local);
                x_min_ = std::min(x_min_, p.x);
                x_max_ = std::max(x_max_, p.x);
                z_min_ = std::min(z_min_, p.z);
                z_max_ = std::max(z_max_, p.z);
            }
        scale_ = kDrawing / std::max(x_max_ - x_min_, z_max_ - z_min_);
    }
    double x(double metres) const { return kMargin + (metres - x_min_) * scale_; }
    double y(double metres) const { return kMargin + (z_max_ - metres) * scale_; }
    double width() const { return std::max(820.0, 2 * kMargin + (x_max_ - x_min_) * scale_); }
    double height() const { return 2 * kMargin + (z_max_ - z_min_) * scale_ + 60.0; }
    double scale() const { return scale_; }
    double x_min() const { return x_min_; }
    double x_max() const { return x_max_; }
    double z_min() const { return z_min_; }
    double z_max() const { return z_max_; }

private:
    double x_min_ = std::numeric_limits<double>::infinity(), x_max_ = -x_min_;
    double z_min_ = x_min_, z_max_ = -x_min_;
    double scale_ = 1.0;
};

std::string ring_path(const Ring& ring, const ValidSection& section, const Canvas& canvas) {
    std::ostringstream d;
    d.precision(8);
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point p = section.to_section(ring[i]);
        d << (i == 0 ? "M" : "L") << canvas.x(p.x) << "," << canvas.y(p.z) << " ";
    }
    d << "Z ";
    return d.str();
}

// One fill colour per material name, in order of appearance, and a legend line for each.
class MaterialColours {
public:
    const char* colour(const Material& m) {
        const std::string key = m.name.empty() ? "unnamed material" : m.name;
        for (std::size_t i = 0; i < names_.size(); ++i)
            if (names_[i] == key) return kPalette[i % kPaletteSize];
        names_.push_back(key);
        return kPalette[(names_.size() - 1) % kPaletteSize];
    }
    const std::vector<std::string>& names() const { return names_; }
    static const char* at(std::size_t i) { return kPalette[i % kPaletteSize]; }

private:
    static constexpr std::size_t kPaletteSize = 6;
    static constexpr const char* kPalette[kPaletteSize] = {"#cfd8e3", "#e8d3a9", "#c9e3c5", "#e3c5d8", "#d6d0ea", "#f0e0b0"};
    std::vector<std::string> names_;
};

void draw_parts(std::ostream& svg, const ValidSection& section, const Canvas& canvas, MaterialColours& colours) {
    for (const Part& part : section.parts()) {
        std::string d = ring_path(part.outer, section, canvas);
        for (const Ring& hole : part.holes) d += ring_path(hole, section, canvas);
        svg << "<path d=\"" << d << "\" fill=\"" << colours.colour(part.material) << "\" fill-rule=\"evenodd\" stroke=\"none\"/>\n";
    }
}

// Bars at their true size (the circle of their area), at least 2 px across.
void draw_bars(std::ostream& svg, const ValidSection& section, const Canvas& canvas, MaterialColours& colours) {
    for (const Part& part : section.parts())
        for (const Bar& bar : part.bars) {
            const Point p = section.to_section(bar.at);
            const double r = std::max(2.0, std::sqrt(bar.area / 3.141592653589793) * canvas.scale());
            svg << "<circle cx=\"" << canvas.x(p.x) << "\" cy=\"" << canvas.y(p.z) << "\" r=\"" << r << "\" fill=\""
                << colours.colour(bar.material) << "\" stroke=\"#333\" stroke-width=\"1\"/>\n";
        }
}

void draw_legend(std::ostream& svg, const Canvas& canvas, const MaterialColours& colours) {
    double x = kMargin + 160.0;
    const double y = canvas.height() - 45.0;
    for (std::size_t i = 0; i < colours.names().size(); ++i) {
        svg << "<rect x=\"" << x << "\" y=\"" << y - 11 << "\" width=\"14\" height=\"14\" fill=\"" << MaterialColours::at(i)
            << "\" stroke=\"#333\"/>\n<text x=\"" << x + 20 << "\" y=\"" << y << "\">" << escaped(colours.names()[i]) << "</text>\n";
        x += 34.0 + 7.5 * static_cast<double>(colours.names()[i].size());
    }
}

void draw_outlines(std::ostream& svg, const ValidSection& section, const Canvas& canvas) {
    for (const Part& part : section.parts()) {
        std::string d = ring_path(part.outer, section, canvas);
        for (const Ring& hole : part.holes) d += ring_path(hole, section, canvas);
        svg << "<path d=\"" << d << "\" fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"/>\n";
    }
}

// The mesh as the cubature route builds it; returns its triangle count.
std::size_t draw_mesh(std::ostream& svg, const ValidSection& section, const Capacities& c, double max_area,
                      const Canvas& canvas) {
    MeshOptions options;
    options.max_area = max_area;
    for (const std::optional<double>& z : {c.z_pna, c.z_pna_neg})
        if (z) options.z_cuts.push_back(*z - section.local_origin().z);
    for (const std::optional<double>& x : {c.x_pna, c.x_pna_neg})
        if (x) options.x_cuts.push_back(*x - section.local_origin().x);
    if (c.reference) options.vertex = section.to_local(*c.reference);
    const SectionMesh mesh = mesh_section(section, options);
    if (mesh.triangles.size() > kMostTriangles) return mesh.triangles.size();
    svg << "<g fill=\"none\" stroke=\"#7a8899\" stroke-width=\"0.5\">\n";
    for (const auto& t : mesh.triangles) {
        svg << "<polygon points=\"";
        for (std::size_t k : t) {
            const Point p = section.to_section(mesh.vertices[k]);
            svg << canvas.x(p.x) << "," << canvas.y(p.z) << " ";
        }
        svg << "\"/>\n";
    }
    svg << "</g>\n";
    return mesh.triangles.size();
}

// Round-off residue (1e-19 m on a 0.3 m section) shown as the 0 it stands for.
double tidy(double value, const Canvas& canvas) {
    const double size = std::max(canvas.x_max() - canvas.x_min(), canvas.z_max() - canvas.z_min());
    return std::abs(value) < 1e-12 * size ? 0.0 : value;
}

// One neutral axis across the drawing: horizontal (z = level) for Mx, vertical (x = level) for Mz.
void draw_axis(std::ostream& svg, const Canvas& canvas, BendingAxis axis, double level, const char* label,
               const char* colour, const char* dashes, double label_offset) {
    char text[320];
    if (axis == BendingAxis::X) {
        const double y = canvas.y(level);
        std::snprintf(text, sizeof text,
                      "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"%s\" stroke-width=\"1.5\" stroke-dasharray=\"%s\"/>\n"
                      "<text x=\"%g\" y=\"%g\" fill=\"%s\">%s z = %.6g m</text>\n",
                      kMargin - 20, y, canvas.x(canvas.x_max()) + 20, y, colour, dashes, kMargin - 20, y - 5 + label_offset,
                      colour, label, tidy(level, canvas));
    } else {
        const double x = canvas.x(level);
        const bool right_half = x > 0.5 * (canvas.x(canvas.x_min()) + canvas.x(canvas.x_max()));  // label inwards
        std::snprintf(text, sizeof text,
                      "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"%s\" stroke-width=\"1.5\" stroke-dasharray=\"%s\"/>\n"
                      "<text x=\"%g\" y=\"%g\" fill=\"%s\" text-anchor=\"%s\">%s x = %.6g m</text>\n",
                      x, kMargin - 20, x, canvas.y(canvas.z_min()) + 20, colour, dashes, right_half ? x - 5 : x + 5,
                      canvas.y(canvas.z_min()) + 34 + label_offset, colour, right_half ? "end" : "start", label,
                      tidy(level, canvas));
    }
    svg << text;
}

void draw_axes(std::ostream& svg, const Capacities& c, const Canvas& canvas) {
    if (c.z_pna) draw_axis(svg, canvas, BendingAxis::X, *c.z_pna, "Mx axis", "#c0392b", "8,4", 0.0);
    if (c.z_pna_neg && c.z_pna_neg != c.z_pna)
        draw_axis(svg, canvas, BendingAxis::X, *c.z_pna_neg, "Mx_neg axis", "#c0392b", "2,3", 18.0);
    if (c.x_pna) draw_axis(svg, canvas, BendingAxis::Z, *c.x_pna, "Mz axis", "#2e6fb7", "8,4", 0.0);
    if (c.x_pna_neg && c.x_pna_neg != c.x_pna)
        draw_axis(svg, canvas, BendingAxis::Z, *c.x_pna_neg, "Mz_neg axis", "#2e6fb7", "2,3", 16.0);
}

void draw_points(std::ostream& svg, const Capacities& c, const Canvas& canvas) {
    char text[320];
    const double cx = canvas.x(c.centroid.x), cy = canvas.y(c.centroid.z);
    std::snprintf(text, sizeof text,
                  "<circle cx=\"%g\" cy=\"%g\" r=\"6\" fill=\"none\" stroke=\"#000\" stroke-width=\"1.5\"/>\n"
                  "<path d=\"M%g,%g h12 M%g,%g v12\" stroke=\"#000\" stroke-width=\"1.5\"/>\n"
                  "<text x=\"%g\" y=\"%g\">centroid</text>\n",
                  cx, cy, cx - 6, cy, cx, cy - 6, cx + 9, cy + 16);
    svg << text;
    if (c.reference) {
        const double jx = canvas.x(c.reference->x), jy = canvas.y(c.reference->z);
        std::snprintf(text, sizeof text,
                      "<path d=\"M%g,%g l5,5 l-5,5 l-5,-5 Z\" fill=\"#8e44ad\"/>\n"
                      "<text x=\"%g\" y=\"%g\" fill=\"#8e44ad\">joint point (My)</text>\n",
                      jx, jy - 5, jx + 9, jy - 6);
        svg << text;
    }
}

void draw_scale_and_title(std::ostream& svg, const Canvas& canvas, const std::string& title, std::size_t triangles) {
    const double length = round_length(0.25 * (canvas.x_max() - canvas.x_min()));
    const double y = canvas.height() - 45.0;
    char text[512];
    std::snprintf(text, sizeof text,
                  "<path d=\"M%g,%g v-6 h%g v6\" fill=\"none\" stroke=\"#000\" stroke-width=\"2\"/>\n"
                  "<text x=\"%g\" y=\"%g\">%s</text>\n",
                  kMargin, y, length * canvas.scale(), kMargin, y + 18, length_text(length).c_str());
    svg << text;
    const std::string mesh = triangles > kMostTriangles ? std::to_string(triangles) + " triangles (too many to draw)"
                                                        : std::to_string(triangles) + " triangles";
    svg << "<text x=\"" << kMargin << "\" y=\"24\" font-weight=\"bold\">" << escaped(title) << "</text>\n"
        << "<text x=\"" << kMargin << "\" y=\"42\" fill=\"#555\">mesh: " << mesh
        << "; red: Mx neutral axis, blue: Mz neutral axis (dotted: the _neg axes where they differ)</text>\n";
}

}  // namespace

std::string section_svg(const ValidSection& section, const Capacities& capacities, double max_area, const std::string& title,
                        const SvgPanel* below) {
    const Canvas canvas(section);
    std::ostringstream svg;
    const double width = below ? std::max(canvas.width(), below->width) : canvas.width();
    const double height = canvas.height() + (below ? below->height : 0.0);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
    MaterialColours colours;
    draw_parts(svg, section, canvas, colours);
    const std::size_t triangles = draw_mesh(svg, section, capacities, max_area, canvas);
    draw_outlines(svg, section, canvas);
    draw_bars(svg, section, canvas, colours);
    draw_legend(svg, canvas, colours);
    draw_axes(svg, capacities, canvas);
    draw_points(svg, capacities, canvas);
    draw_scale_and_title(svg, canvas, title, triangles);
    if (below) svg << "<g transform=\"translate(0," << canvas.height() << ")\">\n" << below->body << "</g>\n";
    svg << "</svg>\n";
    return svg.str();
}

void write_section_svg(const std::string& path, const ValidSection& section, const Capacities& capacities,
                       double max_area, const std::string& title, const SvgPanel* below) {
    const std::string svg = section_svg(section, capacities, max_area, title, below);
    std::ofstream file(path);
    if (file) file << svg;
    if (!file) throw InputError("--svg " + path + ": cannot write the file (" + std::strerror(errno) + ")");
}

}  // namespace plascap::tools
