#pragma once
// A plain 3-vector of doubles for the engine-neutral code: world coordinates [m, N, N·m], and the
// few operations the adapters need (one copy for all of them).
#include <array>
#include <cmath>

namespace plascap {

using Vec3 = std::array<double, 3>;

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline Vec3 difference(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

inline Vec3 scaled(const Vec3& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }

// sum += s·v
inline void add_scaled(Vec3& sum, const Vec3& v, double s) {
    sum[0] += v[0] * s, sum[1] += v[1] * s, sum[2] += v[2] * s;
}

inline double norm(const Vec3& v) { return std::sqrt(dot(v, v)); }

// v/|v|; the zero vector stays zero.
inline Vec3 normalised(const Vec3& v) {
    const double n = norm(v);
    return n > 0.0 ? Vec3{v[0] / n, v[1] / n, v[2] / n} : v;
}

}  // namespace plascap
