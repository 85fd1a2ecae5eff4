#include "plascap/sections/cubature.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bar_strength.hpp"
#include "mesh_neutral_axis.hpp"
#include "plascap/sections/plastic_bending.hpp"
#include "plascap/input_error.hpp"
#include "plascap/sections/section_mesh.hpp"
#include "triangle_cubature.hpp"

namespace plascap {
namespace {

using detail::Estimate;
using detail::Integrand;
using detail::Triangle;
using detail::TriangleRule;

class Unit final : public Integrand {  // ∫ dA: N and Q (eqs. 2.10, 2.11)
public:
    double operator()(Point) const override { return 1.0; }
    detail::PolynomialDegree degree_on(const Triangle&) const override { return {0, 0}; }
};

// s·|z − z_pna| or s·|x − x_pna| (eqs. 2.12, 2.13), s the strength on p's side of the axis.
class DistanceFromAxis final : public Integrand {
public:
    DistanceFromAxis(BendingAxis axis, double level, double below, double above)
        : axis_(axis), level_(level), below_(below), above_(above) {}
    double operator()(Point p) const override {
        const double d = level_of(p, axis_) - level_;
        return d < 0.0 ? -below_ * d : above_ * d;
    }
    // Linear where the triangle lies on one side of the axis: the map p(u, w) is bilinear.
    // A corner within round-off of the axis (its mesh edge is a constructed intersection) counts
    // as on it; the kink it misses spans a sliver of that width.
    detail::PolynomialDegree degree_on(const Triangle& t) const override {
        const double a = level_of(t.a, axis_) - level_, b = level_of(t.b, axis_) - level_, c = level_of(t.c, axis_) - level_;
        const double slack = 1e-12 * std::max({std::abs(a), std::abs(b), std::abs(c)});
        if ((a >= -slack && b >= -slack && c >= -slack) || (a <= slack && b <= slack && c <= slack)) return {1, 1};
        return {};
    }

private:
    BendingAxis axis_;
    double level_;
    double below_, above_;
};

class DistanceFromPoint final : public Integrand {  // |p − c| (eq. 2.14)
public:
    explicit DistanceFromPoint(Point c) : c_(c) {}
    double operator()(Point p) const override { return std::hypot(p.x - c_.x, p.z - c_.z); }
    // From the collapsed corner, |p(u, w) − a| = u·|(b − a) + w·(c − b)|: linear in u.
    detail::PolynomialDegree degree_on(const Triangle& t) const override {
        if (t.a.x == c_.x && t.a.z == c_.z) return {1, std::nullopt};
        return {};
    }

private:
    Point c_;
};

// Compensated (Neumaier) sum of the triangles' contributions: thousands of triangles would
// otherwise lose n·ε to the summation itself.
class Sum {
public:
    void add(double factor, const Estimate& e) {
        const double term = factor * e.value;
        const double t = value_ + term;
        compensation_ += std::abs(value_) >= std::abs(term) ? (value_ - t) + term : (term - t) + value_;
        value_ = t;
        error_ += factor * e.error;
    }
    double value() const { return value_ + compensation_; }
    // The triangles' estimates, plus the rounding of the compensated sum (2ε of the total).
    double error() const { return error_ + 2.0 * std::numeric_limits<double>::epsilon() * std::abs(value()); }

private:
    double value_ = 0.0, compensation_ = 0.0, error_ = 0.0;
};

struct AreaAndCentroid {
    double area = 0.0;
    Point centroid;  // local coordinates
};

// Σ A_i and Σ A_i·(a + b + c)/3 over the triangles: exact for polygons.
AreaAndCentroid area_and_centroid(const SectionMesh& mesh) {
    double area = 0.0, sx = 0.0, sz = 0.0;
    for (const auto& corner : mesh.triangles) {
        const Point a = mesh.vertices[corner[0]], b = mesh.vertices[corner[1]], c = mesh.vertices[corner[2]];
        const double triangle_area = 0.5 * ((b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z));
        area += triangle_area;
        sx += triangle_area * (a.x + b.x + c.x) / 3.0;
        sz += triangle_area * (a.z + b.z + c.z) / 3.0;
    }
    return {area, {sx / area, sz / area}};
}

// The triangle with the joint point, when it is a corner, as the collapsed corner a.
Triangle oriented_triangle(const SectionMesh& mesh, std::size_t i, Point joint) {
    const auto& corner = mesh.triangles[i];
    Point p[3] = {mesh.vertices[corner[0]], mesh.vertices[corner[1]], mesh.vertices[corner[2]]};
    for (int k = 0; k < 3; ++k)
        if (p[k].x == joint.x && p[k].z == joint.z) return {p[k], p[(k + 1) % 3], p[(k + 2) % 3]};
    return {p[0], p[1], p[2]};
}

double extent(const SectionMesh& mesh) {
    double x_min = 0.0, x_max = 0.0, z_min = 0.0, z_max = 0.0;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Point p = mesh.vertices[i];
        x_min = i == 0 ? p.x : std::min(x_min, p.x);
        x_max = i == 0 ? p.x : std::max(x_max, p.x);
        z_min = i == 0 ? p.z : std::min(z_min, p.z);
        z_max = i == 0 ? p.z : std::max(z_max, p.z);
    }
    return std::max(x_max - x_min, z_max - z_min);
}

// A cut that passes within round-off of the joint point (the centroid of a symmetric section) is
// moved onto it, so the mesh has one vertex there instead of a cluster of slivers. Mx and Mz are
// stationary in the axis position (dMx/dz_pna = 0 at the equal-force axis), so the kink the cut
// now misses by δ costs O(δ²).
void snap_cuts_to_joint(MeshOptions& mesh, Point joint, double extent) {
    const double near = 1e-12 * extent;
    for (double& z : mesh.z_cuts)
        if (std::abs(z - joint.z) <= near) z = joint.z;
    for (double& x : mesh.x_cuts)
        if (std::abs(x - joint.x) <= near) x = joint.x;
}

TriangleRule make_rule(const CubatureOptions& options) {
    return options.rule == CubatureRule::Adaptive ? TriangleRule::adaptive(options.tolerance)
                                                  : TriangleRule::fixed(options.order);
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// One bending capacity to integrate: its axis, the strength each part has below and above it,
// the axis level, and the running sum. A _neg capacity of a section with fc = fy everywhere is a
// copy of its counterpart.
struct Bending {
    Capacity capacity;
    BendingAxis axis;
    std::vector<detail::SideStrengths> strength;  // by part
    std::vector<detail::PointArea> bars;          // with their net strengths
    double level = 0.0;                           // local coordinates
    std::optional<std::size_t> copy_of;
    Sum sum;
};

detail::SideStrengths sides(double fy, double fc, BendingAxis axis, bool negative) {
    return tension_side(axis, negative) == TensionSide::Below ? detail::SideStrengths{fy, fc} : detail::SideStrengths{fc, fy};
}

std::vector<detail::SideStrengths> side_strengths(const ValidSection& section, BendingAxis axis, bool negative) {
    std::vector<detail::SideStrengths> strengths;
    for (const Part& part : section.parts())
        strengths.push_back(sides(part.material.fy, part.material.compression_strength(), axis, negative));
    return strengths;
}

std::vector<detail::PointArea> bar_areas(const ValidSection& section, BendingAxis axis, bool negative) {
    std::vector<detail::PointArea> bars;
    for (const Part& part : section.parts())
        for (const Bar& bar : part.bars) {
            const detail::BarStrength net = detail::bar_strength(bar, part.material, section.shear());
            bars.push_back({bar.at, bar.area, sides(net.tension, net.compression, axis, negative)});
        }
    return bars;
}

// The bars' exact point terms of one bending capacity: s·A·|level − t|.
double bar_moment(const std::vector<detail::PointArea>& bars, BendingAxis axis, double t) {
    double moment = 0.0;
    for (const detail::PointArea& bar : bars) {
        const double d = level_of(bar.at, axis) - t;
        moment += (d < 0.0 ? -bar.strength.below * d : bar.strength.above * d) * bar.area;
    }
    return moment;
}

std::vector<Bending> wanted_bendings(const ValidSection& section, CapacitySet wanted) {
    bool symmetric = true;
    for (const Part& part : section.parts()) symmetric = symmetric && part.material.compression_strength() == part.material.fy;
    struct Kind {
        Capacity capacity, twin;
        BendingAxis axis;
        bool negative;
    };
    const Kind kinds[] = {{Capacity::Mx, Capacity::Mx_neg, BendingAxis::X, false},
                          {Capacity::Mz, Capacity::Mz_neg, BendingAxis::Z, false},
                          {Capacity::Mx_neg, Capacity::Mx, BendingAxis::X, true},
                          {Capacity::Mz_neg, Capacity::Mz, BendingAxis::Z, true}};
    std::vector<Bending> bendings;
    for (const Kind& k : kinds) {
        if (!wanted.contains(k.capacity)) continue;
        Bending b{k.capacity, k.axis, side_strengths(section, k.axis, k.negative),
                  bar_areas(section, k.axis, k.negative), 0.0, std::nullopt, Sum()};
        for (std::size_t i = 0; i < bendings.size(); ++i)
            if (symmetric && bendings[i].capacity == k.twin) b.copy_of = i;
        bendings.push_back(std::move(b));
    }
    return bendings;
}

std::optional<double>& capacities_slot(Capacities& c, Capacity k) {
    switch (k) {
        case Capacity::Mx: return c.Mx;
        case Capacity::Mz: return c.Mz;
        case Capacity::Mx_neg: return c.Mx_neg;
        default: return c.Mz_neg;
    }
}

std::optional<double>& level_slot(Capacities& c, Capacity k) {
    switch (k) {
        case Capacity::Mx: return c.z_pna;
        case Capacity::Mz: return c.x_pna;
        case Capacity::Mx_neg: return c.z_pna_neg;
        default: return c.x_pna_neg;
    }
}

}  // namespace

void validate_cubature_options(const CubatureOptions& options) {
    // GSL's qag cannot reach a relative tolerance below 50·ε ≈ 1.1e-14.
    if (!(options.tolerance >= 1e-13 && options.tolerance <= 0.1))
        throw InputError("cubature: the tolerance must be between 1e-13 and 0.1 (got " + number(options.tolerance) + ")");
    if (options.order < 1 || options.order > 100)
        throw InputError("cubature: the order must be a whole number from 1 to 100 (got " + std::to_string(options.order) + ")");
    if (!std::isfinite(options.max_area) || options.max_area < 0.0)
        throw InputError("cubature: the largest triangle area must be a finite number ≥ 0 m² (got " +
                         number(options.max_area) + ")");
}

CubatureResult cubature_capacities(const ValidSection& section, CapacitySet wanted, const CubatureOptions& options) {
    validate_cubature_options(options);
    const auto start = std::chrono::steady_clock::now();
    CubatureResult result;
    Capacities& capacities = result.capacities;
    capacities.shear = section.shear();

    // A first triangulation gives the area, the centroid and the neutral axes; the second
    // conforms to the kinks they define.
    const SectionMesh plain = mesh_section(section);
    const AreaAndCentroid geometry = area_and_centroid(plain);
    capacities.area = geometry.area;
    capacities.centroid = section.to_section(geometry.centroid);

    MeshOptions mesh_options;
    mesh_options.max_area = options.max_area;
    // The fixed rule's estimate compares two Gauss orders; that says something only where every
    // triangle resolves the integrand, which long slivers (a 1:1000 strip's triangulation) do not.
    mesh_options.refine_shape = options.rule == CubatureRule::Fixed;
    std::vector<Bending> bendings = wanted_bendings(section, wanted);
    for (Bending& b : bendings) {
        b.level = detail::mesh_neutral_axis(plain, b.strength, b.bars, b.axis);
        b.sum.add(1.0, {bar_moment(b.bars, b.axis, b.level), 0.0});
        if (options.conforming) (b.axis == BendingAxis::X ? mesh_options.z_cuts : mesh_options.x_cuts).push_back(b.level);
    }
    const Point joint = section.reference() ? section.to_local(*section.reference()) : geometry.centroid;
    if (wanted.contains(Capacity::My)) {
        capacities.reference = section.to_section(joint);
        if (options.conforming) {
            mesh_options.vertex = joint;
            snap_cuts_to_joint(mesh_options, joint, extent(plain));
        }
    }
    const bool remesh = !mesh_options.z_cuts.empty() || !mesh_options.x_cuts.empty() || mesh_options.vertex ||
                        mesh_options.max_area > 0.0 || mesh_options.refine_shape;
    const SectionMesh mesh = remesh ? mesh_section(section, mesh_options) : plain;

    const TriangleRule rule = make_rule(options);
    const Unit unit;
    const DistanceFromPoint from_joint(joint);
    const bool want_area = wanted.contains(Capacity::N) || wanted.contains(Capacity::N_neg) ||
                           wanted.contains(Capacity::Qx) || wanted.contains(Capacity::Qz);
    Sum force, compression, shear, my;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const Triangle triangle = oriented_triangle(mesh, i, joint);
        const Material& material = section.parts()[mesh.part_of[i]].material;
        const double tau = shear_yield_stress(material.fy, section.shear());
        if (want_area) {
            const Estimate area = rule.integrate(triangle, unit);
            force.add(material.fy, area);                            // eq. 2.10
            compression.add(material.compression_strength(), area);  // eq. 2.10 with fc
            shear.add(tau, area);                                     // eq. 2.11
        }
        for (Bending& b : bendings) {  // eqs. 2.12, 2.13, each side with its own strength
            if (b.copy_of) continue;
            const detail::SideStrengths strength = b.strength[mesh.part_of[i]];
            b.sum.add(1.0, rule.integrate(triangle, DistanceFromAxis(b.axis, b.level, strength.below, strength.above)));
        }
        if (wanted.contains(Capacity::My)) my.add(tau, rule.integrate(triangle, from_joint));  // eq. 2.14
    }
    for (const Part& part : section.parts())  // bars: exact point terms, displacing the part's material
        for (const Bar& bar : part.bars) {
            const detail::BarStrength net = detail::bar_strength(bar, part.material, section.shear());
            force.add(net.tension, {bar.area, 0.0});
            compression.add(net.compression, {bar.area, 0.0});
            shear.add(net.shear, {bar.area, 0.0});
            my.add(net.shear, {bar.area * from_joint(bar.at), 0.0});
        }

    const auto store = [&](Capacity c, std::optional<double>& slot, const Sum& sum) {
        if (!wanted.contains(c)) return;
        slot = sum.value();
        result.error[static_cast<std::size_t>(c)] = sum.error();
    };
    store(Capacity::N, capacities.N, force);
    store(Capacity::N_neg, capacities.N_neg, compression);
    store(Capacity::Qx, capacities.Qx, shear);
    store(Capacity::Qz, capacities.Qz, shear);
    store(Capacity::My, capacities.My, my);
    for (const Bending& b : bendings) {
        const Bending& source = b.copy_of ? bendings[*b.copy_of] : b;
        store(b.capacity, capacities_slot(capacities, b.capacity), source.sum);
        level_slot(capacities, b.capacity) =
            b.level + (b.axis == BendingAxis::X ? section.local_origin().z : section.local_origin().x);
    }
    result.triangles = mesh.triangles.size();
    result.refinement_stopped = mesh.refinement_stopped;
    result.evaluations = rule.evaluations();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace plascap
