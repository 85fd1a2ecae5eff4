// Computes the paper's Fig. 2.6 torsion capacity through an installed plascap and checks it
// against the closed form (../shared/reference/values.md): 38.2597858232 N·m.
#include <cmath>
#include <cstdio>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/shapes.hpp"

int main() {
    const plascap::Section square = plascap::rectangle_section(0.01, 0.01, 200e6);
    const plascap::Capacities c = plascap::compute_capacities(plascap::validate_section(square));
    std::printf("My = %.10f N*m\n", *c.My);
    return std::fabs(*c.My - 38.2597858232) < 1e-8 ? 0 : 1;
}
