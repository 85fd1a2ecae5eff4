#include "body_energy.hpp"

namespace plascap {
namespace {

using Mat = std::array<Vec3, 3>;  // rows

Mat from_quaternion(const Quaternion& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

}  // namespace

double kinetic_energy(const SceneBody& body, const BodyState& s) {
    const double m = body.mass;
    const auto& [a, b, c] = body.size;
    const Vec3 principal = body.inertia ? *body.inertia : Vec3{m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12};
    const Mat r = from_quaternion(s.orientation);
    // ω in the body's frame: the columns of R are the body axes in the world.
    const Vec3 w_body = {dot({r[0][0], r[1][0], r[2][0]}, s.angular_velocity), dot({r[0][1], r[1][1], r[2][1]}, s.angular_velocity),
                         dot({r[0][2], r[1][2], r[2][2]}, s.angular_velocity)};
    double rotational = 0.0;
    for (int i = 0; i < 3; ++i) rotational += principal[i] * w_body[i] * w_body[i];
    return 0.5 * m * dot(s.velocity, s.velocity) + 0.5 * rotational;
}

Vec3 world_point(const BodyState& s, const Vec3& local) {
    const Mat r = from_quaternion(s.orientation);
    Vec3 p = s.position;
    for (int i = 0; i < 3; ++i) p[i] += dot(r[i], local);
    return p;
}

Vec3 body_point(const BodyState& s, const Vec3& world) {
    const Mat r = from_quaternion(s.orientation);  // local = Rᵀ(world − centre)
    const Vec3 d = difference(world, s.position);
    return {r[0][0] * d[0] + r[1][0] * d[1] + r[2][0] * d[2], r[0][1] * d[0] + r[1][1] * d[1] + r[2][1] * d[2],
            r[0][2] * d[0] + r[1][2] * d[1] + r[2][2] * d[2]};
}

}  // namespace plascap
