#include "member_frame.hpp"

#include <cmath>

#include "plascap/input_error.hpp"

namespace plascap::detail {

MemberFrame member_frame(const std::optional<Vec3>& z_axis, const Vec3& along, const Vec3& gravity, const std::string& where) {
    Vec3 z_raw;
    if (z_axis) {
        z_raw = *z_axis;
    } else {  // default: up (against gravity), or world x for a member along it
        z_raw = norm(gravity) > 0 ? scaled(gravity, -1.0) : Vec3{0, 1, 0};
        if (norm(cross(normalised(z_raw), along)) < 1e-6) z_raw = {1, 0, 0};
    }
    const Vec3 across = difference(z_raw, scaled(along, dot(z_raw, along)));
    if (!(norm(across) > 1e-6 * norm(z_raw))) throw InputError(where + ".z_axis: is zero or along the member");
    MemberFrame f;
    f.y = along;
    f.z = normalised(across);
    f.x = cross(f.y, f.z);
    return f;
}

// Shepperd, J. Guidance and Control 1, 1978: from the largest of the four squared components.
Quaternion quaternion_of(const MemberFrame& f) {
    const double m00 = f.x[0], m11 = f.y[1], m22 = f.z[2];
    const double m21 = f.y[2], m12 = f.z[1], m02 = f.z[0], m20 = f.x[2], m10 = f.x[1], m01 = f.y[0];
    const double trace = m00 + m11 + m22;
    Quaternion q;
    if (trace > 0) {
        const double s = 2.0 * std::sqrt(1.0 + trace);
        q = {0.25 * s, (m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s};
    } else if (m00 > m11 && m00 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m00 - m11 - m22);
        q = {(m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s};
    } else if (m11 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m11 - m00 - m22);
        q = {(m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + m22 - m00 - m11);
        q = {(m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s};
    }
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= n;
    return q;
}

}  // namespace plascap::detail
