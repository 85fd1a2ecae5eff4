// Computes two capacities through an installed plascap and checks them against references:
// the paper's Fig. 2.6 torsion capacity of a 10 mm square (closed form of ∫τy·d dA, 38.2597858232
// N·m; "Plasticity in a physics engine", eq. 2.14), and the plastic modulus of the catalogue's
// IPE 300 (EN 10365 table: Wpl,y = 628.4 cm³), which needs the installed shape catalogue.
#include <cmath>
#include <cstdio>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/shape_designation.hpp"
#include "plascap/sections/shapes.hpp"

int main() {
    const plascap::Section square = plascap::rectangle_section(0.01, 0.01, 200e6);
    const plascap::Capacities c = plascap::compute_capacities(plascap::validate_section(square));
    std::printf("My = %.10f N*m\n", *c.My);
    const plascap::Section ipe = plascap::shape_section("IPE 300", plascap::Material{"", 355e6});
    const double Wpl = *plascap::compute_capacities(plascap::validate_section(ipe)).Mx / 355e6;
    std::printf("IPE 300: Wpl,y = %.1f cm^3\n", Wpl * 1e6);
    return std::fabs(*c.My - 38.2597858232) < 1e-8 && std::fabs(Wpl / 628.4e-6 - 1.0) < 5e-3 ? 0 : 1;
}
