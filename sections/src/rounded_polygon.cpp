#include "plascap/sections/rounded_polygon.hpp"

#include <cmath>
#include <sstream>

#include "plascap/input_error.hpp"

namespace plascap {
namespace {

constexpr std::size_t kMaxChordsPerArc = 100000;

struct Vec {
    double x, z;
};

Vec operator-(Point a, Point b) { return {a.x - b.x, a.z - b.z}; }
double length(Vec v) { return std::hypot(v.x, v.z); }
double cross(Vec a, Vec b) { return a.x * b.z - a.z * b.x; }
double dot(Vec a, Vec b) { return a.x * b.x + a.z * b.z; }

// The corner's geometry: unit edge directions, turning angle φ ∈ (0, π) and its sense.
struct Turn {
    Vec in, out;       // unit directions of the incoming and outgoing edges
    double angle;      // φ [rad]
    bool left;         // counter-clockwise turn
    double tangent;    // r·tan(φ/2), distance from the corner to each tangent point [m]
};

Turn turn_at(const RoundedRing& ring, std::size_t i) {
    const std::size_t n = ring.size();
    const Point prev = ring[(i + n - 1) % n].at, here = ring[i].at, next = ring[(i + 1) % n].at;
    Vec in = here - prev, out = next - here;
    const double lin = length(in), lout = length(out);
    in = {in.x / lin, in.z / lin};
    out = {out.x / lout, out.z / lout};
    Turn t{in, out, std::atan2(std::fabs(cross(in, out)), dot(in, out)), cross(in, out) > 0.0, 0.0};
    t.tangent = ring[i].radius * std::tan(0.5 * t.angle);
    return t;
}

// Points that differ by round-off only (a tangent point computed from either of its two arcs).
bool same_place(Point a, Point b) { return std::fabs(a.x - b.x) + std::fabs(a.z - b.z) <= 1e-12; }

std::string number(double value) {
    std::ostringstream out;
    out.precision(6);
    out << value;
    return out.str();
}

std::string corner_name(const RoundedRing& ring, std::size_t i) {
    const std::string name = ring[i].name.empty() ? "corner radius" : ring[i].name;
    return name + " " + number(ring[i].radius * 1e3) + " mm";
}

std::size_t chords_for(double radius, double angle, double budget) {
    std::size_t n = 1;
    while (chord_area_error(radius, angle, n) > budget) {
        if (n >= kMaxChordsPerArc)
            throw InputError("an arc of radius " + number(radius) + " m needs more than " +
                             std::to_string(kMaxChordsPerArc) + " chords for the requested area tolerance");
        n = n < 8 ? n + 1 : n + n / 8;
    }
    while (n > 1 && chord_area_error(radius, angle, n - 1) <= budget) --n;  // the fewest
    return n;
}

void check_fit(const RoundedRing& ring, const std::vector<Turn>& turns) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (ring[i].radius > 0.0 && turns[i].angle < 1e-12)
            throw InputError(corner_name(ring, i) + ": a rounded corner must turn (the edges are collinear)");
        const std::size_t j = (i + 1) % n;
        const double edge = length(ring[j].at - ring[i].at);
        if (turns[i].tangent + turns[j].tangent > edge * (1.0 + 1e-12)) {
            const std::size_t culprit = ring[i].radius >= ring[j].radius ? i : j;
            throw InputError(corner_name(ring, culprit) + " does not fit: the arcs need " +
                             number((turns[i].tangent + turns[j].tangent) * 1e3) + " mm of an edge " +
                             number(edge * 1e3) + " mm long");
        }
    }
}

}  // namespace

double chord_area_error(double radius, double angle, std::size_t chords) {
    const double theta = angle / static_cast<double>(chords);
    // θ − sin θ loses every digit for small θ: its series θ³/6 − θ⁵/120 + θ⁷/5040 instead.
    const double t2 = theta * theta;
    const double segment =
        theta < 1e-2 ? theta * t2 * (1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0) : theta - std::sin(theta);
    return static_cast<double>(chords) * 0.5 * radius * radius * segment;
}

double rounded_signed_area(const RoundedRing& ring) {
    const std::size_t n = ring.size();
    double area = 0.0;
    for (std::size_t i = 0; i < n; ++i) {  // shoelace about the first corner (no cancellation far away)
        const Vec a = ring[i].at - ring[0].at, b = ring[(i + 1) % n].at - ring[0].at;
        area += 0.5 * cross(a, b);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (ring[i].radius <= 0.0) continue;
        const Turn t = turn_at(ring, i);
        const double r = ring[i].radius;
        const double cut = r * r * (std::tan(0.5 * t.angle) - 0.5 * t.angle);
        area += t.left ? -cut : cut;
    }
    return area;
}

std::size_t arc_count(const RoundedRing& ring) {
    std::size_t count = 0;
    for (const RoundedCorner& c : ring) count += c.radius > 0.0 ? 1 : 0;
    return count;
}

Ring discretise(const RoundedRing& ring, double area_budget_per_arc) {
    const std::size_t n = ring.size();
    std::vector<Turn> turns;
    turns.reserve(n);
    for (std::size_t i = 0; i < n; ++i) turns.push_back(turn_at(ring, i));
    check_fit(ring, turns);

    Ring out;
    const auto push = [&out](Point p) {  // tangent points of neighbouring arcs may coincide
        if (!out.empty() && same_place(out.back(), p)) return;
        out.push_back(p);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Point c = ring[i].at;
        const double r = ring[i].radius;
        if (r <= 0.0) {
            push(c);
            continue;
        }
        const Turn& t = turns[i];
        const Point start{c.x - t.tangent * t.in.x, c.z - t.tangent * t.in.z};
        const Vec normal = t.left ? Vec{-t.in.z, t.in.x} : Vec{t.in.z, -t.in.x};  // towards the arc's centre
        const Point centre{start.x + r * normal.x, start.z + r * normal.z};
        const std::size_t chords = chords_for(r, t.angle, area_budget_per_arc);
        const double start_angle = std::atan2(start.z - centre.z, start.x - centre.x);
        const double sweep = t.left ? t.angle : -t.angle;
        for (std::size_t k = 0; k <= chords; ++k) {
            const double a = start_angle + sweep * static_cast<double>(k) / static_cast<double>(chords);
            push({centre.x + r * std::cos(a), centre.z + r * std::sin(a)});
        }
    }
    while (out.size() > 1 && same_place(out.back(), out.front())) out.pop_back();
    return out;
}

double discretisation_area_error(const RoundedRing& ring, double area_budget_per_arc) {
    double error = 0.0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        if (ring[i].radius <= 0.0) continue;
        const Turn t = turn_at(ring, i);
        error += chord_area_error(ring[i].radius, t.angle, chords_for(ring[i].radius, t.angle, area_budget_per_arc));
    }
    return error;
}

}  // namespace plascap
