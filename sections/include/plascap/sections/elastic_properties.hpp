#pragma once
// Elastic section properties by Green's theorem (exact for polygons; Steger 1996, "On the
// calculation of arbitrary moments of polygons"), about the centroid:
//   Ixx = ∫(z − zc)² dA (bending about x), Izz = ∫(x − xc)² dA, Ixz = ∫(x − xc)(z − zc) dA;
//   principal I1 ≥ I2 = (Ixx + Izz)/2 ± √(((Ixx − Izz)/2)² + Ixz²), the axis of I1 at angle θ from x
//   towards z, tan 2θ = 2·Ixz/(Izz − Ixx) (Gere & Goodno, Mechanics of Materials, §12.8);
//   elastic moduli Wx = Ixx/max|z − zc|, Wz = Izz/max|x − xc| (extreme fibre); radii r = √(I/A).
// Composite sections: when every part (and bar) gives E, the stiffnesses EA, EIxx, EIzz, EIxz are
// modulus weighted about the modulus-weighted centroid (transformed section).
#include <optional>

#include "plascap/sections/geometry.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap {

struct SectionStiffness {
    Point centroid;   // modulus-weighted centroid, section coordinates [m]
    double EA = 0.0;  // [N]
    double EIxx = 0.0, EIzz = 0.0, EIxz = 0.0;  // about that centroid [N·m²]
};

struct ElasticProperties {
    double area = 0.0;                    // [m²]
    Point centroid;                       // [m], section coordinates
    double Ixx = 0.0, Izz = 0.0, Ixz = 0.0;  // [m⁴], about the centroid
    double I1 = 0.0, I2 = 0.0;            // principal second moments [m⁴], I1 ≥ I2
    double principal_angle = 0.0;         // axis of I1, from x towards z [rad], in (−π/2, π/2]
    double Wx = 0.0, Wz = 0.0;            // elastic section moduli [m³]
    double rx = 0.0, rz = 0.0;            // radii of gyration √(Ixx/A), √(Izz/A) [m]
    std::optional<SectionStiffness> stiffness;  // when every material gives E
};

ElasticProperties elastic_properties(const ValidSection& section);

}  // namespace plascap
