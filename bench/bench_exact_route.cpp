// The exact route's cost: all six capacities, a subset, and validation, against vertex count.
// Target (cubature issue): all six capacities of a 1,000-vertex polygon in <= 20 µs.
#include <benchmark/benchmark.h>

#include <optional>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/shapes.hpp"
#include "plascap/sections/yield_surface.hpp"

namespace {

plascap::Section polygon_section(std::size_t n) {
    plascap::Section s;
    s.parts.push_back({plascap::regular_polygon_ring(n, 0.1, 0.1), {}, plascap::Material{"", 355e6}});
    return s;
}

void AllSixCapacities(benchmark::State& state) {
    const plascap::ValidSection section = plascap::validate_section(polygon_section(static_cast<std::size_t>(state.range(0))));
    for (auto _ : state) benchmark::DoNotOptimize(plascap::compute_capacities(section));
    state.SetComplexityN(state.range(0));
}
BENCHMARK(AllSixCapacities)->Arg(4)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Complexity();

void AxialAndBendingOnly(benchmark::State& state) {
    const plascap::ValidSection section = plascap::validate_section(polygon_section(static_cast<std::size_t>(state.range(0))));
    const plascap::CapacitySet wanted = plascap::CapacitySet().insert(plascap::Capacity::N).insert(plascap::Capacity::Mx);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::compute_capacities(section, wanted));
}
BENCHMARK(AxialAndBendingOnly)->Arg(1000);

void TorsionOnly(benchmark::State& state) {
    const plascap::ValidSection section = plascap::validate_section(polygon_section(static_cast<std::size_t>(state.range(0))));
    const plascap::CapacitySet wanted = plascap::CapacitySet().insert(plascap::Capacity::My);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::compute_capacities(section, wanted));
}
BENCHMARK(TorsionOnly)->Arg(1000);

void Validation(benchmark::State& state) {
    const plascap::Section section = polygon_section(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(plascap::validate_section(section));
}
BENCHMARK(Validation)->Arg(4)->Arg(1000)->Arg(100000);

}  // namespace

// The exact N–Mx–Mz utilisation of one skew load (docs/yield-surface.md): from scratch, and warm-
// started from the normal of a nearby load as a joint does step after step.
void Utilisation(benchmark::State& state) {
    const plascap::YieldSurface surface(plascap::validate_section(polygon_section(static_cast<std::size_t>(state.range(0)))));
    const plascap::SectionResultant load{2e6, 1e5, -5e4};
    std::optional<plascap::SectionResultant> warm;
    if (state.range(1) == 1) warm = surface.along({2.01e6, 1.001e5, -5.01e4}).normal;
    int iterations = 0;
    for (auto _ : state) {
        const plascap::SurfaceHit hit = surface.along(load, warm);
        iterations = hit.iterations;
        benchmark::DoNotOptimize(hit.utilisation);
    }
    state.counters["newton_steps"] = iterations;
}
BENCHMARK(Utilisation)->ArgNames({"vertices", "warm"})->ArgsProduct({{4, 100, 1000}, {0, 1}})->Unit(benchmark::kMicrosecond);
