// The exact N–Mx–Mz surface against closed forms (docs/yield-surface.md; docs/references.md).
#include <gtest/gtest.h>

#include <cmath>

#include "plascap/input_error.hpp"
#include "plascap/sections/interaction_curves.hpp"
#include "plascap/sections/section_yield.hpp"
#include "plascap/sections/shape_designation.hpp"
#include "plascap/sections/shapes.hpp"
#include "plascap/sections/yield_surface.hpp"
#include "test_support.hpp"

namespace plascap {
namespace {

using test::box;
using test::part;
using test::section_of;

const double kPi = std::acos(-1.0);
constexpr double kExact = 1e-9;  // the tolerance for closed forms on polygons

YieldSurface surface_of(const Section& s) { return YieldSurface(validate_section(s)); }

// Rectangle b × h (b along x, h along z), fy = fc: n² + m = 1 about either axis (e.g. Neal, "The
// Plastic Methods of Structural Analysis", 1977, §1.6).
TEST(YieldSurface, RectangleAxialForceAndBendingAboutEitherAxis) {
    const double b = 0.2, h = 0.3, fy = 355e6;
    const YieldSurface s = surface_of(rectangle_section(b, h, fy));
    const double Np = fy * b * h, Mxp = fy * b * h * h / 4, Mzp = fy * h * b * b / 4;
    for (double n : {-0.9, -0.5, -0.1, 0.0, 0.3, 0.5, 0.75, 0.99}) {
        for (double sign : {1.0, -1.0}) {
            const double m = sign * (1.0 - n * n);
            EXPECT_NEAR(s.utilisation({n * Np, m * Mxp, 0.0}), 1.0, kExact) << "n " << n << " Mx";
            EXPECT_NEAR(s.utilisation({n * Np, 0.0, m * Mzp}), 1.0, kExact) << "n " << n << " Mz";
            EXPECT_NEAR(s.utilisation({0.4 * n * Np, 0.4 * m * Mxp, 0.0}), 0.4, kExact);
        }
    }
    EXPECT_NEAR(s.utilisation({Np, 0, 0}), 1.0, kExact);
    EXPECT_NEAR(s.utilisation({-2 * Np, 0, 0}), 2.0, kExact);
    EXPECT_EQ(s.utilisation({0, 0, 0}), 0.0);
}

// Square a × a bent about its diagonal: M = a³·fy/(3√2), so Mx = Mz = a³·fy/6 (the box of
// independent limits would allow Mx = Mz = Mp = a³·fy/4).
TEST(YieldSurface, SquareAboutItsDiagonal) {
    const double a = 0.1, fy = 235e6;
    const YieldSurface s = surface_of(rectangle_section(a, a, fy));
    const double each = a * a * a * fy / 6;
    for (double sx : {1.0, -1.0})
        for (double sz : {1.0, -1.0}) EXPECT_NEAR(s.utilisation({0, sx * each, sz * each}), 1.0, kExact);
    const double Mp = a * a * a * fy / 4;
    EXPECT_NEAR(s.utilisation({0, Mp, Mp}), 1.5, kExact);  // the box's corner is 50 % outside
}

// Doubly symmetric I (sharp corners), fy = fc, bending about x (strong axis):
//   neutral axis in the web (|N| ≤ fy·tw·hw): M_N = Mp − N²/(4·fy·tw);
//   in a flange at level t (hw/2 ≤ t ≤ h/2): N = fy·(A − 2b(h/2 − t)), M = fy·b·(h²/4 − t²).
Section i_section(double h, double b, double tw, double tf, double fy) {
    const double hw = h - 2 * tf;
    return section_of({part({{-b / 2, -h / 2}, {b / 2, -h / 2}, {b / 2, -hw / 2}, {tw / 2, -hw / 2}, {tw / 2, hw / 2},
                             {b / 2, hw / 2}, {b / 2, h / 2}, {-b / 2, h / 2}, {-b / 2, hw / 2}, {-tw / 2, hw / 2},
                             {-tw / 2, -hw / 2}, {-b / 2, -hw / 2}},
                            fy)});
}

TEST(YieldSurface, ISectionAxisInTheWebAndInAFlange) {
    const double h = 0.3, b = 0.15, tw = 0.0071, tf = 0.0107, fy = 355e6, hw = h - 2 * tf;
    const YieldSurface s = surface_of(i_section(h, b, tw, tf, fy));
    const double A = 2 * b * tf + tw * hw;
    const double Mp = fy * (b * tf * (h - tf) + tw * hw * hw / 4);
    for (double share : {0.0, 0.3, 0.7, 1.0}) {
        const double N = share * fy * tw * hw;
        for (double sign : {1.0, -1.0}) {
            EXPECT_NEAR(s.utilisation({sign * N, Mp - N * N / (4 * fy * tw), 0}), 1.0, kExact) << share;
            EXPECT_NEAR(s.utilisation({N, sign * (Mp - N * N / (4 * fy * tw)), 0}), 1.0, kExact) << share;
        }
    }
    for (double t : {hw / 2 + 0.2 * tf, hw / 2 + 0.5 * tf, hw / 2 + 0.9 * tf}) {
        const double N = fy * (A - 2 * b * (h / 2 - t)), M = fy * b * (h * h / 4 - t * t);
        EXPECT_NEAR(s.utilisation({N, M, 0}), 1.0, kExact) << t;
        EXPECT_NEAR(s.utilisation({-N, -M, 0}), 1.0, kExact) << t;
    }
}

// Solid circle radius R and tube Ro/Ri, neutral axis at y0 from the centre: the stress block's
// N = fy·(A − 2·A_seg), M = 2·fy·S_seg, with the circular segment beyond y0 of area
// A_seg(R) = R²·acos(y0/R) − y0·√(R² − y0²) and first moment S_seg(R) = ⅔(R² − y0²)^{3/2}
// (for the solid circle this is n = (2β + sin 2β)/π, m = cos³β with y0 = R·sin β). The sections
// are regular 4096-gons, whose area differs from the circle's by 4e-7: hence 1e-5.
double segment_area(double R, double y0) { return std::abs(y0) >= R ? 0.0 : R * R * std::acos(y0 / R) - y0 * std::sqrt(R * R - y0 * y0); }
double segment_moment(double R, double y0) { return std::abs(y0) >= R ? 0.0 : 2.0 / 3.0 * std::pow(R * R - y0 * y0, 1.5); }

TEST(YieldSurface, CircleAndTubeParametricForms) {
    const double Ro = 0.1, Ri = 0.08, fy = 275e6;
    const std::size_t n = 4096;
    const YieldSurface solid = surface_of(section_of({part(regular_polygon_ring(n, Ro), fy)}));
    Ring hole = regular_polygon_ring(n, Ri);
    std::reverse(hole.begin(), hole.end());
    const YieldSurface tube = surface_of(section_of({part(regular_polygon_ring(n, Ro), fy, {hole})}));
    for (double y0 : {0.0, 0.02, 0.05, 0.085, 0.095}) {
        const double A = kPi * Ro * Ro, N = fy * (A - 2 * segment_area(Ro, y0)), M = 2 * fy * segment_moment(Ro, y0);
        EXPECT_NEAR(solid.utilisation({N, M, 0}), 1.0, 1e-5) << y0;
        EXPECT_NEAR(solid.utilisation({N, M / std::sqrt(2.0), M / std::sqrt(2.0)}), 1.0, 1e-5) << y0;
        const double At = kPi * (Ro * Ro - Ri * Ri);
        const double Nt = fy * (At - 2 * (segment_area(Ro, y0) - segment_area(Ri, y0)));
        const double Mt = 2 * fy * (segment_moment(Ro, y0) - segment_moment(Ri, y0));
        EXPECT_NEAR(tube.utilisation({Nt, 0, Mt}), 1.0, 1e-5) << y0;
    }
}

// Reinforced concrete, fc ≠ fy, by hand stress blocks: a b × h rectangle of concrete (tension fct,
// compression fcc) with two bars of area As at depth d from the top and two at d' (fy = fc = fs).
// A horizontal neutral axis at depth x from the top, concrete and bars above it compressed:
//   N = fct·b·(h − x) − fcc·b·x + Σ bars (±fs − (±f_concrete))·As,
//   M about the centroid from the same forces' levels.
TEST(YieldSurface, ReinforcedConcreteByHandStressBlocks) {
    const double b = 0.3, h = 0.5, fct = 2e6, fcc = 30e6, fs = 500e6, As = 4.91e-4, cover = 0.05;
    Material concrete{"concrete", fct};
    concrete.fc = fcc;
    Part p{box(-b / 2, -h / 2, b / 2, h / 2), {}, concrete};
    const Material steel{"steel", fs};
    for (double x : {-b / 4, b / 4})
        for (double z : {-h / 2 + cover, h / 2 - cover}) p.bars.push_back({{x, z}, As, steel});
    const YieldSurface s = surface_of(section_of({p}));
    const double top = h / 2;
    // Moments about x (capacities.hpp: Mx = −∫z·σ dA); the bars' levels are ±(h/2 − cover).
    const auto hand = [&](double x, bool compressed_above) {
        const double level = top - x;  // z of the axis
        const double sa = compressed_above ? -fcc : fct, sb = compressed_above ? fct : -fcc;  // concrete above / below
        double N = sa * b * (top - level) + sb * b * (level + top);
        double Mx = -(sa * b * (top - level) * (top + level) / 2 + sb * b * (level + top) * (level - top) / 2);
        for (double z : {-h / 2 + cover, h / 2 - cover}) {
            const bool above = z > level;
            const double steel_stress = (above == compressed_above) ? -fs : fs;
            const double concrete_stress = above ? sa : sb;
            N += 2 * As * (steel_stress - concrete_stress);
            Mx += -z * 2 * As * (steel_stress - concrete_stress);
        }
        return SectionResultant{N, Mx, 0};
    };
    for (double x : {0.03, 0.1, 0.2, 0.3, 0.47}) {
        for (bool above : {true, false}) {
            const SectionResultant r = hand(above ? x : h - x, above);
            EXPECT_NEAR(s.utilisation(r), 1.0, kExact) << "x " << x << (above ? " top" : " bottom") << " compressed";
            const SurfaceHit hit = s.along({0.5 * r.N, 0.5 * r.Mx, 0});
            EXPECT_NEAR(hit.point.N, r.N, kExact * std::abs(r.N) + 1e-6);
        }
    }
    // The neutral axis through a row of bars: the bars may carry any stress between −fs and fs, so
    // the surface has a flat facet there (a kink of h); its midpoint and a point near its end.
    const double level = h / 2 - cover, x_top = top - level;
    for (double share : {0.5, 0.9}) {
        const SectionResultant lo = hand(x_top - 1e-12, true), hi = hand(x_top + 1e-12, true);
        const SectionResultant mid{lo.N + share * (hi.N - lo.N), lo.Mx + share * (hi.Mx - lo.Mx), 0};
        EXPECT_NEAR(s.utilisation(mid), 1.0, kExact) << "facet at " << share;
    }
    const double Nt = fct * b * h + 4 * As * (fs - fct), Nc = fcc * b * h + 4 * As * (fs - fcc);
    EXPECT_NEAR(s.utilisation({Nt, 0, 0}), 1.0, kExact);
    EXPECT_NEAR(s.utilisation({-Nc, 0, 0}), 1.0, kExact);
}

// The normal is the utilisation's gradient: compare with central differences.
TEST(YieldSurface, NormalIsTheGradientOfTheUtilisation) {
    const YieldSurface s = surface_of(i_section(0.3, 0.15, 0.0071, 0.0107, 355e6));
    const SectionResultant load{4e5, 1.5e5, 2.0e4};
    const SurfaceHit hit = s.along(load);
    EXPECT_NEAR(hit.normal.N * hit.point.N + hit.normal.Mx * hit.point.Mx + hit.normal.Mz * hit.point.Mz, 1.0, 1e-12);
    const auto d = [&](SectionResultant plus, SectionResultant minus, double step) {
        return (s.utilisation(plus) - s.utilisation(minus)) / (2 * step);
    };
    const double hN = 1.0, hM = 0.1;
    // ∇U at the load = the normal at its surface point (U is homogeneous of degree 1, so ∇U(L) = ∇U(L/U)).
    EXPECT_NEAR(d({load.N + hN, load.Mx, load.Mz}, {load.N - hN, load.Mx, load.Mz}, hN), hit.normal.N, 1e-5 * std::abs(hit.normal.N));
    EXPECT_NEAR(d({load.N, load.Mx + hM, load.Mz}, {load.N, load.Mx - hM, load.Mz}, hM), hit.normal.Mx, 1e-5 * std::abs(hit.normal.Mx));
    EXPECT_NEAR(d({load.N, load.Mx, load.Mz + hM}, {load.N, load.Mx, load.Mz - hM}, hM), hit.normal.Mz, 1e-5 * std::abs(hit.normal.Mz));
}

// Moving a section and its reference point changes nothing; turning it turns (Mx, Mz) with it
// (the moment vector Mx·e_x + Mz·e_z rotates with the section).
TEST(YieldSurface, InvariantUnderMovingAndTurning) {
    const Ring l = {{0, 0}, {0.1, 0}, {0.1, 0.01}, {0.01, 0.01}, {0.01, 0.15}, {0, 0.15}};  // an angle
    const YieldSurface base = surface_of(section_of({part(l, 355e6)}));
    const double angle = 0.7, c = std::cos(angle), sn = std::sin(angle);
    Ring turned, moved;
    for (Point p : l) {
        turned.push_back({c * p.x - sn * p.z, sn * p.x + c * p.z});
        moved.push_back({p.x + 3.0, p.z - 2.0});
    }
    const YieldSurface rot = surface_of(section_of({part(turned, 355e6)}));
    const YieldSurface shifted = surface_of(section_of({part(moved, 355e6)}));
    for (SectionResultant load : {SectionResultant{2e5, 3e4, -1e4}, SectionResultant{-4e5, -1e4, 2e4},
                                  SectionResultant{1e4, 2e4, 2e4}}) {
        const double u = base.utilisation(load);
        EXPECT_NEAR(shifted.utilisation(load), u, 1e-11 * u);
        EXPECT_NEAR(rot.utilisation({load.N, c * load.Mx - sn * load.Mz, sn * load.Mx + c * load.Mz}), u, 1e-11 * u);
    }
}

}  // namespace
}  // namespace plascap

namespace plascap {
namespace {

// A sampled loop is convex when every turn between consecutive edges has the same sense.
void expect_convex(const std::vector<SectionResultant>& loop, double SectionResultant::*a, double SectionResultant::*b,
                   double scale_a, double scale_b, const char* what) {
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
        const SectionResultant &p = loop[i], &q = loop[(i + 1) % n], &r = loop[(i + 2) % n];
        const double e1a = (q.*a - p.*a) / scale_a, e1b = (q.*b - p.*b) / scale_b;
        const double e2a = (r.*a - q.*a) / scale_a, e2b = (r.*b - q.*b) / scale_b;
        EXPECT_GE(e1a * e2b - e1b * e2a, -1e-12) << what << " turns the wrong way at sample " << i;
    }
}

TEST(InteractionCurves, ConvexLoopsOnTheSurface) {
    const ShapeOptions fine;
    const YieldSurface s(validate_section(shape_section("IPE 300", Material{"S355", 355e6}, fine)));
    const SectionResultant k = s.scale();
    const auto nmx = n_mx_curve(s, 96), nmz = n_mz_curve(s, 96), mm = mx_mz_curve(s, 0.3 * k.N, 96);
    ASSERT_EQ(nmx.size(), 96u);
    for (const auto& p : nmx) EXPECT_NEAR(s.utilisation(p), 1.0, 1e-10);
    for (const auto& p : mm) {
        EXPECT_NEAR(s.utilisation(p), 1.0, 1e-10);
        EXPECT_NEAR(p.N, 0.3 * k.N, 1e-9 * k.N);
    }
    expect_convex(nmx, &SectionResultant::N, &SectionResultant::Mx, k.N, k.Mx, "N-Mx");
    expect_convex(nmz, &SectionResultant::N, &SectionResultant::Mz, k.N, k.Mz, "N-Mz");
    expect_convex(mm, &SectionResultant::Mx, &SectionResultant::Mz, k.Mx, k.Mz, "Mx-Mz");
    EXPECT_THROW(mx_mz_curve(s, 1.01 * s.full_tension().N, 16), InputError);
}

// EN 1993-1-1 §6.2.9.1(5) for rolled I sections, n = N/Npl, a = min((A − 2·b·tf)/A, 0.5):
//   strong axis M_N = Mpl·(1 − n)/(1 − 0.5·a) (≤ Mpl); weak axis M_N = Mpl for n ≤ a, else
//   Mpl·[1 − ((n − a)/(1 − a))²]. The clause calls them approximations. The exact surface of the
//   real IPE 300 (root radii): weak axis within 4 % of Mpl; strong axis 6.5 % below at n = 0.2 (where
//   §6.2.9.1(4) allows ignoring N; the formula's plateau ends at n = a/2) and within 4 % from n = 0.3.
TEST(InteractionCurves, RolledISectionAgainstEurocodeApproximations) {
    const double fy = 355e6, b = 0.15, tf = 0.0107;
    const YieldSurface s(validate_section(shape_section("IPE 300", Material{"S355", fy})));
    const double Npl = s.full_tension().N, A = Npl / fy;
    const double a = std::min((A - 2 * b * tf) / A, 0.5);
    const double Mx_pl = 1.0 / s.along({0, 1.0, 0}).utilisation, Mz_pl = 1.0 / s.along({0, 0, 1.0}).utilisation;
    double worst_x = 0, worst_z = 0, worst_x_past_onset = 0;
    for (double n = 0.0; n < 0.96; n += 0.05) {
        const double en_x = std::min(1.0, (1 - n) / (1 - 0.5 * a));
        const double en_z = n <= a ? 1.0 : 1 - std::pow((n - a) / (1 - a), 2);
        const double exact_x = s.from({n * Npl, 0, 0}, {0, 1.0, 0}).point.Mx / Mx_pl;
        const double exact_z = s.from({n * Npl, 0, 0}, {0, 0, 1.0}).point.Mz / Mz_pl;
        worst_x = std::max(worst_x, std::abs(exact_x - en_x));
        if (n > 0.29) worst_x_past_onset = std::max(worst_x_past_onset, std::abs(exact_x - en_x));
        worst_z = std::max(worst_z, std::abs(exact_z - en_z));
    }
    EXPECT_LT(worst_x, 0.07);  // 6.5 % at n = 0.2, where §6.2.9.1(4) lets the reduction be ignored
    EXPECT_LT(worst_x_past_onset, 0.04);
    EXPECT_LT(worst_z, 0.04);
    RecordProperty("worst_strong", std::to_string(worst_x));
    RecordProperty("worst_weak", std::to_string(worst_z));
    std::printf("EN 1993-1-1 6.2.9.1 vs exact, IPE 300: strong axis %.4f (%.4f from n = 0.3), weak axis %.4f of Mpl\n",
                worst_x, worst_x_past_onset, worst_z);
}

}  // namespace
}  // namespace plascap

namespace plascap {
namespace {

// A thin tube under N and T carries uniform σ = N/A and τ = T/(2π·R²·t); von Mises,
// σ² + 3τ² = fy², is then n² + t² = 1 with Np = fy·A and Tp = (fy/√3)·2π·R²·t: the reduction
// U = √(u_NM² + η²) is exact there.
TEST(SectionYield, ThinTubeUnderAxialForceAndTorsionIsVonMises) {
    const double R = 0.1, t = 0.001, fy = 355e6;
    Ring outer = regular_polygon_ring(2048, R + t / 2), hole = regular_polygon_ring(2048, R - t / 2);
    std::reverse(hole.begin(), hole.end());
    const ValidSection v = validate_section(section_of({part(outer, fy, {hole})}));
    const double A = 2 * kPi * R * t, Tp = fy / std::sqrt(3.0) * 2 * kPi * R * R * t;
    const SectionYield yield(YieldSurface(v), {fy / std::sqrt(3.0) * A, fy / std::sqrt(3.0) * A, Tp});
    for (double n : {0.0, 0.3, 0.6, 0.9}) {
        const double sigma = n * fy, tau = std::sqrt((fy * fy - sigma * sigma) / 3.0);
        const double N = sigma * A, T = tau * 2 * kPi * R * R * t;
        EXPECT_NEAR(yield.utilisation({N, 0, 0, 0, 0, T}), 1.0, 1e-5) << n;  // the 2048-gon's area: 1e-5
        EXPECT_NEAR(yield.utilisation({-N, 0, 0, 0, 0, -T}), 1.0, 1e-5) << n;
    }
}

// Shear and torsion add linearly into η, and the gradient is U's: central differences.
TEST(SectionYield, ShearTorsionShareAndGradient) {
    const ValidSection v = validate_section(rectangle_section(0.2, 0.3, 355e6));
    const SectionYield yield(YieldSurface(v), {1e6, 2e6, 5e4});
    EXPECT_NEAR(shear_torsion_share({0, 3e5, 4e5 * 2, 0, 0, -1e4}, yield.shear_torsion()), 0.5 + 0.2, 1e-15);
    const SectionLoads load{2e6, 2e5, -3e5, 1e5, -4e4, 1e4};
    const SectionYieldState st = yield.evaluate(load);
    const auto du = [&](double SectionLoads::*c, double step) {
        SectionLoads plus = load, minus = load;
        plus.*c += step, minus.*c -= step;
        return (yield.utilisation(plus) - yield.utilisation(minus)) / (2 * step);
    };
    EXPECT_NEAR(du(&SectionLoads::N, 10.0), st.gradient.N, 1e-5 * std::abs(st.gradient.N));
    EXPECT_NEAR(du(&SectionLoads::Qx, 1.0), st.gradient.Qx, 1e-5 * std::abs(st.gradient.Qx));
    EXPECT_NEAR(du(&SectionLoads::Qz, 1.0), st.gradient.Qz, 1e-5 * std::abs(st.gradient.Qz));
    EXPECT_NEAR(du(&SectionLoads::Mx, 1.0), st.gradient.Mx, 1e-5 * std::abs(st.gradient.Mx));
    EXPECT_NEAR(du(&SectionLoads::Mz, 1.0), st.gradient.Mz, 1e-5 * std::abs(st.gradient.Mz));
    EXPECT_NEAR(du(&SectionLoads::T, 1.0), st.gradient.T, 1e-5 * std::abs(st.gradient.T));
    EXPECT_THROW(SectionYield(YieldSurface(v), {1e6, 0.0, 5e4}), InputError);
}

}  // namespace
}  // namespace plascap
