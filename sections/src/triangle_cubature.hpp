#pragma once
// Cubature over one triangle with GSL, through the collapsed-square (Duffy) map
//   p(u, w) = a + u·(b − a) + u·w·(c − b),   u, w ∈ [0, 1],   dA = 2·area·u du dw
// (M. G. Duffy, SIAM J. Numer. Anal. 19 (1982) 1260). The corner a is the collapsed one: an
// integrand with a cone tip there (|p − a|) becomes smooth in (u, w), so the joint point of My
// goes in corner a.
#include <cstddef>
#include <memory>
#include <optional>

#include "plascap/sections/geometry.hpp"

namespace plascap::detail {

struct Triangle {
    Point a, b, c;  // a: the collapsed corner
};

// Where f∘p is a polynomial in u or in w on a triangle, the rule integrates that direction with
// the Gauss–Legendre rule that is exact for its degree instead of adaptively.
struct PolynomialDegree {
    std::optional<int> u, w;  // degree of f(p(u, w)) in u and in w; empty: not a polynomial
};

// f(p) at a point of the section plane.
class Integrand {
public:
    virtual ~Integrand() = default;
    virtual double operator()(Point p) const = 0;
    virtual PolynomialDegree degree_on(const Triangle& triangle) const = 0;
};

struct Estimate {
    double value = 0.0;
    double error = 0.0;  // estimated absolute error, ≥ 0
};

class TriangleRule {
public:
    // Nested one-dimensional adaptive Gauss–Kronrod (gsl_integration_qag, 21-point rule) in u and
    // in w, each to the relative tolerance. Error = outer estimate + the largest inner one.
    static TriangleRule adaptive(double relative_tolerance);
    // Gauss–Legendre tensor rule (gsl_integration_glfixed) with `order` points per direction.
    // Error = |Q(order) − Q(⌈order/2⌉)|: the lower rule's error, which bounds the higher one's
    // (for order 1, |Q(1) − Q(2)|).
    static TriangleRule fixed(int order);
    // Both add round-off bounds: 4ε·Σ|wᵢ·fᵢ| for the sums, and that of the Jacobian 2·area.

    TriangleRule(TriangleRule&&) noexcept;
    TriangleRule& operator=(TriangleRule&&) noexcept;
    ~TriangleRule();

    Estimate integrate(const Triangle& triangle, const Integrand& f) const;
    // Integrand evaluations so far (for reports).
    std::size_t evaluations() const;

private:
    struct Impl;
    explicit TriangleRule(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace plascap::detail
