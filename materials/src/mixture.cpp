#include "plascap/materials/mixture.hpp"

#include <cstdio>
#include <optional>

#include "plascap/input_error.hpp"

namespace plascap {
namespace {

std::optional<double> mix(const std::optional<double>& a, const std::optional<double>& b, double ratio) {
    if (!a || !b) return std::nullopt;
    return (1.0 - ratio) * *a + ratio * *b;  // rule of mixtures (Voigt)
}

}  // namespace

Material smeared_mixture(const Material& matrix, const Material& reinforcement, double ratio) {
    if (!(ratio > 0.0 && ratio < 1.0)) throw InputError("reinforcement ratio must be between 0 and 1 (exclusive)");
    Material m;
    char name[160];
    std::snprintf(name, sizeof name, "%s + %g %% %s", matrix.name.empty() ? "matrix" : matrix.name.c_str(), ratio * 100.0,
                  reinforcement.name.empty() ? "reinforcement" : reinforcement.name.c_str());
    m.name = name;
    m.description = "reinforcement spread evenly over the part (rule of mixtures)";
    m.fy = (1.0 - ratio) * matrix.fy + ratio * reinforcement.fy;
    m.fc = (1.0 - ratio) * matrix.compression_strength() + ratio * reinforcement.compression_strength();
    m.E = mix(matrix.E, reinforcement.E, ratio);
    m.nu = matrix.nu;
    if (m.E && m.nu) m.G = *m.E / (2.0 * (1.0 + *m.nu));
    m.density = mix(matrix.density, reinforcement.density, ratio);
    m.ultimate_strain = reinforcement.ultimate_strain;
    m.max_plastic_rotation = reinforcement.max_plastic_rotation;
    m.shear = reinforcement.shear;
    return m;
}

}  // namespace plascap
