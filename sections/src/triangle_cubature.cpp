#include "triangle_cubature.hpp"

#include "gsl_errors.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace plascap::detail {
namespace {

constexpr std::size_t kMaxSubintervals = 200;  // per one-dimensional qag

// Points and weights of an n-point Gauss–Legendre rule on [0, 1].
struct LineRule {
    std::vector<double> nodes, weights;
};

LineRule gauss_legendre(int n) {
    gsl_integration_glfixed_table* table = gsl_integration_glfixed_table_alloc(static_cast<std::size_t>(n));
    LineRule rule;
    for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
        double x = 0.0, w = 0.0;
        gsl_integration_glfixed_point(0.0, 1.0, i, &x, &w, table);
        rule.nodes.push_back(x);
        rule.weights.push_back(w);
    }
    gsl_integration_glfixed_table_free(table);
    return rule;
}

// The collapsed-square map (Duffy 1982).
Point duffy_point(const Triangle& t, double u, double w) {
    return {t.a.x + u * (t.b.x - t.a.x) + u * w * (t.c.x - t.b.x),
            t.a.z + u * (t.b.z - t.a.z) + u * w * (t.c.z - t.b.z)};
}

double twice_area(const Triangle& t) {
    return std::abs((t.b.x - t.a.x) * (t.c.z - t.a.z) - (t.c.x - t.a.x) * (t.b.z - t.a.z));
}

// Round-off bound of twice_area(): the corners carry ε·R each (R: their largest distance from the
// origin), the edges ε·(R + h) (h: the longest edge), so the cross product ≈ 4ε·(R + h)·h. It
// matters for the slivers of a many-vertex polygon's triangulation.
double twice_area_roundoff(const Triangle& t) {
    const double r = std::max({std::hypot(t.a.x, t.a.z), std::hypot(t.b.x, t.b.z), std::hypot(t.c.x, t.c.z)});
    const double h = std::max({std::hypot(t.b.x - t.a.x, t.b.z - t.a.z), std::hypot(t.c.x - t.b.x, t.c.z - t.b.z),
                               std::hypot(t.a.x - t.c.x, t.a.z - t.c.z)});
    return 4.0 * std::numeric_limits<double>::epsilon() * (r + h) * h;
}

// The size of f on the triangle, for the absolute tolerance floor of integrands that vanish.
double integrand_scale(const Triangle& t, const Integrand& f) {
    const Point centre{(t.a.x + t.b.x + t.c.x) / 3.0, (t.a.z + t.b.z + t.c.z) / 3.0};
    return std::max({std::abs(f(t.a)), std::abs(f(t.b)), std::abs(f(t.c)), std::abs(f(centre))});
}


// One line integral over [0, 1]: its value, error estimate and Σ|wᵢ·fᵢ| (for round-off).
struct LineResult {
    double value = 0.0;
    double error = 0.0;
    double magnitude = 0.0;
};

// How one direction of the square is integrated: adaptively when `workspace` is set, else by
// the Gauss nodes of `gauss`, with `companion`'s for an error estimate when set.
struct LineMethod {
    const LineRule* gauss = nullptr;
    const LineRule* companion = nullptr;
    gsl_integration_workspace* workspace = nullptr;
    double tolerance = 0.0;
    double floor = 0.0;  // absolute tolerance: integrands that vanish on a line
};

template <class Fn>
double call(double x, void* fn) {
    return (*static_cast<Fn*>(fn))(x);
}

template <class Fn>
LineResult integrate_line(Fn& fn, const LineMethod& method) {
    LineResult result;
    if (method.workspace != nullptr) {
        gsl_function f{&call<Fn>, &fn};
        gsl_integration_qag(&f, 0.0, 1.0, method.floor, method.tolerance, kMaxSubintervals, GSL_INTEG_GAUSS21,
                            method.workspace, &result.value, &result.error);
        result.magnitude = std::abs(result.value);
        return result;
    }
    for (std::size_t i = 0; i < method.gauss->nodes.size(); ++i) {
        const double term = method.gauss->weights[i] * fn(method.gauss->nodes[i]);
        result.value += term;
        result.magnitude += std::abs(term);
    }
    if (method.companion != nullptr) {
        double low = 0.0;
        for (std::size_t i = 0; i < method.companion->nodes.size(); ++i)
            low += method.companion->weights[i] * fn(method.companion->nodes[i]);
        result.error = std::abs(result.value - low);
    }
    return result;
}

constexpr int kExactRules = 8;  // exact Gauss rules kept for polynomial degrees up to 15

}  // namespace

struct TriangleRule::Impl {
    bool adaptive = true;
    double tolerance = 1e-10;
    LineRule high, low;                            // fixed rule and its error companion
    std::vector<LineRule> exact;                   // exact[n − 1]: n-point Gauss–Legendre
    gsl_integration_workspace* outer = nullptr;
    gsl_integration_workspace* inner = nullptr;
    std::size_t evaluations = 0;

    Impl() {
        for (int n = 1; n <= kExactRules; ++n) exact.push_back(gauss_legendre(n));
    }
    ~Impl() {
        if (outer != nullptr) gsl_integration_workspace_free(outer);
        if (inner != nullptr) gsl_integration_workspace_free(inner);
    }

    // A polynomial of degree d needs n Gauss points with 2n − 1 ≥ d.
    LineMethod method(std::optional<int> polynomial_degree, gsl_integration_workspace* workspace, double floor) const {
        LineMethod m;
        if (polynomial_degree && *polynomial_degree / 2 + 1 <= kExactRules) {
            m.gauss = &exact[static_cast<std::size_t>(*polynomial_degree / 2)];
        } else if (adaptive) {
            m.workspace = workspace;
            m.tolerance = tolerance;
            m.floor = floor;
        } else {
            m.gauss = &high;
            m.companion = &low;
        }
        return m;
    }

    Estimate integrate(const Triangle& t, const Integrand& f) {
        const double area2 = twice_area(t);
        if (area2 == 0.0) return {};
        const GslErrorsReturned errors_returned;
        const PolynomialDegree degree = f.degree_on(t);
        const double floor = adaptive ? 1e-3 * tolerance * integrand_scale(t, f) : 0.0;
        if (adaptive) evaluations += 4;
        // The Jacobian's factor u raises the degree in u by one.
        const LineMethod along_u = method(degree.u ? std::optional<int>(*degree.u + 1) : std::nullopt, outer, floor);
        const LineMethod along_w = method(degree.w, inner, floor);
        double inner_error = 0.0;  // largest u·e(u) of the inner integrals
        auto outer_integrand = [&](double u) {
            auto inner_integrand = [&](double w) {
                ++evaluations;
                return f(duffy_point(t, u, w));
            };
            const LineResult line = integrate_line(inner_integrand, along_w);
            inner_error = std::max(inner_error, u * line.error);
            return u * line.value;
        };
        const LineResult total = integrate_line(outer_integrand, along_u);
        // The inner errors reach the total through ∫ u·e(u) du ≤ max u·e(u).
        const double roundoff = 4.0 * std::numeric_limits<double>::epsilon() * total.magnitude;
        return {area2 * total.value,
                area2 * (total.error + inner_error + roundoff) + twice_area_roundoff(t) * total.magnitude};
    }
};

TriangleRule::TriangleRule(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TriangleRule::TriangleRule(TriangleRule&&) noexcept = default;
TriangleRule& TriangleRule::operator=(TriangleRule&&) noexcept = default;
TriangleRule::~TriangleRule() = default;

TriangleRule TriangleRule::adaptive(double relative_tolerance) {
    auto impl = std::make_unique<Impl>();
    impl->adaptive = true;
    impl->tolerance = relative_tolerance;
    impl->outer = gsl_integration_workspace_alloc(kMaxSubintervals);
    impl->inner = gsl_integration_workspace_alloc(kMaxSubintervals);
    return TriangleRule(std::move(impl));
}

TriangleRule TriangleRule::fixed(int order) {
    auto impl = std::make_unique<Impl>();
    impl->adaptive = false;
    impl->high = gauss_legendre(order);
    impl->low = gauss_legendre(order == 1 ? 2 : (order + 1) / 2);  // the 1-point rule has no lower one
    return TriangleRule(std::move(impl));
}

Estimate TriangleRule::integrate(const Triangle& triangle, const Integrand& f) const {
    return impl_->integrate(triangle, f);
}

std::size_t TriangleRule::evaluations() const { return impl_->evaluations; }

}  // namespace plascap::detail
