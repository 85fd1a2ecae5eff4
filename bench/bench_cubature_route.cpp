// The cubature route's cost (CGAL mesh + GSL cubature). Target (cubature issue): the paper's
// square to 1e-10 relative in <= 100 µs, meshing included. Run: build/bench/bench_cubature_route
#include <benchmark/benchmark.h>

#include "plascap/sections/cubature.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/torsion_constant.hpp"
#include "plascap/sections/section_mesh.hpp"
#include "plascap/sections/shapes.hpp"

namespace {

// The paper's 10 mm square, fy = 200 MPa (Fig. 2.6).
plascap::ValidSection paper_square() { return plascap::validate_section(plascap::rectangle_section(0.01, 0.01, 200e6)); }

plascap::ValidSection polygon(std::size_t n) {
    plascap::Section s;
    s.parts.push_back({plascap::regular_polygon_ring(n, 0.1, 0.1), {}, plascap::Material{"", 355e6}});
    return plascap::validate_section(s);
}

void PaperSquareAllSix(benchmark::State& state) {
    const plascap::ValidSection section = paper_square();
    plascap::CubatureOptions options;
    options.tolerance = 1e-10;
    for (auto _ : state) benchmark::DoNotOptimize(plascap::cubature_capacities(section, plascap::CapacitySet::all(), options));
}
BENCHMARK(PaperSquareAllSix)->Unit(benchmark::kMicrosecond);

void PaperSquareTorsionOnly(benchmark::State& state) {
    const plascap::ValidSection section = paper_square();
    const plascap::CapacitySet wanted = plascap::CapacitySet().insert(plascap::Capacity::My);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::cubature_capacities(section, wanted));
}
BENCHMARK(PaperSquareTorsionOnly)->Unit(benchmark::kMicrosecond);

void PaperSquareMeshOnly(benchmark::State& state) {
    const plascap::ValidSection section = paper_square();
    plascap::MeshOptions options;
    options.z_cuts = {0.0};
    options.x_cuts = {0.0};
    options.vertex = plascap::Point{0.0, 0.0};
    for (auto _ : state) benchmark::DoNotOptimize(plascap::mesh_section(section, options));
}
BENCHMARK(PaperSquareMeshOnly)->Unit(benchmark::kMicrosecond);

void PolygonAllSix(benchmark::State& state) {
    const plascap::ValidSection section = polygon(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(plascap::cubature_capacities(section));
    state.SetComplexityN(state.range(0));
}
BENCHMARK(PolygonAllSix)->Arg(16)->Arg(256)->Arg(4096)->Unit(benchmark::kMicrosecond);

void FixedRuleRefinedMesh(benchmark::State& state) {
    const plascap::ValidSection section = paper_square();
    plascap::CubatureOptions options;
    options.rule = plascap::CubatureRule::Fixed;
    options.order = 4;
    options.max_area = 1e-4 / static_cast<double>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(plascap::cubature_capacities(section, plascap::CapacitySet::all(), options));
}
BENCHMARK(FixedRuleRefinedMesh)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace

// Issue 5's targets: J of the 100 × 50 mm rectangle to 1e-4 (≤ 20 ms), and T_p of a 100-vertex polygon.
void TorsionConstantRectangle(benchmark::State& state) {
    const plascap::ValidSection section = plascap::validate_section(plascap::rectangle_section(0.1, 0.05, 355e6));
    for (auto _ : state) benchmark::DoNotOptimize(plascap::saint_venant_torsion(section));
}
BENCHMARK(TorsionConstantRectangle)->Unit(benchmark::kMillisecond);

void PlasticTorsion100gon(benchmark::State& state) {
    const plascap::ValidSection section = polygon(100);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::plastic_torsion(section));
}
BENCHMARK(PlasticTorsion100gon)->Unit(benchmark::kMillisecond);
