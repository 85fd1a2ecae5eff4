#include "scene_json_values.hpp"

#include <cmath>

#include "plascap/input_error.hpp"

namespace plascap::scene_json {
namespace {

std::string kind_of(const Json& value) { return value.type_name(); }

}  // namespace

const Json& member(const Json& object, const char* key, const std::string& where) {
    const auto it = object.find(key);
    if (it == object.end()) throw InputError(where + ": missing \"" + key + "\"");
    return *it;
}

void require_object(const Json& value, const std::string& where) {
    if (!value.is_object()) throw InputError(where + ": expected an object, got " + kind_of(value));
}

double finite_number(const Json& value, const std::string& where) {
    if (!value.is_number()) throw InputError(where + ": expected a number, got " + kind_of(value));
    const double number = value.get<double>();
    if (!std::isfinite(number)) throw InputError(where + ": the number is not finite");
    return number;
}

double positive_number(const Json& value, const std::string& where) {
    const double number = finite_number(value, where);
    if (!(number > 0.0)) throw InputError(where + ": must be positive (got " + value.dump() + ")");
    return number;
}

Vec3 vec3(const Json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 3) throw InputError(where + ": expected [x, y, z]");
    return {finite_number(value[0], where + "[0]"), finite_number(value[1], where + "[1]"),
            finite_number(value[2], where + "[2]")};
}

Vec3 unit_vec3(const Json& value, const std::string& where) {
    const Vec3 v = vec3(value, where);
    const double length = std::hypot(v[0], v[1], v[2]);
    if (!(length > 1e-12)) throw InputError(where + ": the direction has zero length");
    return {v[0] / length, v[1] / length, v[2] / length};
}

Quaternion unit_quaternion(const Json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 4) throw InputError(where + ": expected [w, x, y, z]");
    Quaternion q{};
    double norm = 0.0;
    for (std::size_t i = 0; i < 4; ++i) {
        q[i] = finite_number(value[i], where + "[" + std::to_string(i) + "]");
        norm += q[i] * q[i];
    }
    norm = std::sqrt(norm);
    if (!(norm > 1e-12)) throw InputError(where + ": the quaternion has zero length");
    for (double& c : q) c /= norm;
    return q;
}

std::string text(const Json& value, const std::string& where) {
    if (!value.is_string()) throw InputError(where + ": expected a string, got " + kind_of(value));
    return value.get<std::string>();
}

}  // namespace plascap::scene_json
