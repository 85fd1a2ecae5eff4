#include "section_svg.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "plascap/input_error.hpp"
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
    double width() const { return 2 * kMargin + (x_max_ - x_min_) * scale_; }
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

void draw_parts(std::ostream& svg, const ValidSection& section, const Canvas& canvas) {
    for (const Part& part : section.parts()) {
        std::string d = ring_path(part.outer, section, canvas);
        for (const Ring& hole : part.holes) d += ring_path(hole, section, canvas);
        svg << "<path d=\"" << d << "\" fill=\"#cfd8e3\" fill-rule=\"evenodd\" stroke=\"none\"/>\n";
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

void draw_axes(std::ostream& svg, const Capacities& c, const Canvas& canvas) {
    char text[256];
    if (c.z_pna) {
        const double y = canvas.y(*c.z_pna);
        std::snprintf(text, sizeof text,
                      "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#c0392b\" stroke-width=\"1.5\" "
                      "stroke-dasharray=\"8,4\"/>\n<text x=\"%g\" y=\"%g\" fill=\"#c0392b\">Mx axis z = %.6g m</text>\n",
                      kMargin - 20, y, canvas.x(canvas.x_max()) + 20, y, kMargin - 20, y - 5, tidy(*c.z_pna, canvas));
        svg << text;
    }
    if (c.x_pna) {
        const double x = canvas.x(*c.x_pna);
        std::snprintf(text, sizeof text,
                      "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#2e6fb7\" stroke-width=\"1.5\" "
                      "stroke-dasharray=\"8,4\"/>\n<text x=\"%g\" y=\"%g\" fill=\"#2e6fb7\">Mz axis x = %.6g m</text>\n",
                      x, kMargin - 20, x, canvas.y(canvas.z_min()) + 20, x + 5, canvas.y(canvas.z_min()) + 34, tidy(*c.x_pna, canvas));
        svg << text;
    }
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
        << "; red: Mx neutral axis, blue: Mz neutral axis</text>\n";
}

}  // namespace

void write_section_svg(const std::string& path, const ValidSection& section, const Capacities& capacities,
                       double max_area, const std::string& title) {
    const Canvas canvas(section);
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << canvas.width() << "\" height=\"" << canvas.height()
        << "\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
    draw_parts(svg, section, canvas);
    const std::size_t triangles = draw_mesh(svg, section, capacities, max_area, canvas);
    draw_outlines(svg, section, canvas);
    draw_axes(svg, capacities, canvas);
    draw_points(svg, capacities, canvas);
    draw_scale_and_title(svg, canvas, title, triangles);
    svg << "</svg>\n";
    std::ofstream file(path);
    if (file) file << svg.str();
    if (!file) throw InputError("--svg " + path + ": cannot write the file (" + std::strerror(errno) + ")");
}

}  // namespace plascap::tools
