// Standard shapes: generating a catalogue shape, its exact capacities, and J (FEM, to 1e-4) and
// T_p (sand heap, to 1e-3) for representative rows, on the arcs the catalogue table uses (J: 1e-5,
// T_p: 1e-4 of the area) and J also on the default arcs (1e-6). Goal (issue 13): J and T_p of any
// catalogue shape <= 50 ms each.
#include <benchmark/benchmark.h>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/shape_designation.hpp"
#include "plascap/sections/shape_table.hpp"
#include "plascap/sections/torsion_constant.hpp"
#include "plascap/sections/valid_section.hpp"

namespace {

const char* const kShapes[] = {"IPE 300", "HEB 200", "HEM 1000", "UPE 200", "L 60x40x5", "SHS 200x200x10", "CHS 168.3x8"};

plascap::ValidSection shape(int index, double area_tolerance) {
    return plascap::validate_section(
        plascap::shape_section(kShapes[index], plascap::Material{"", 355e6}, plascap::ShapeOptions{area_tolerance}));
}

void GenerateAndValidate(benchmark::State& state) {
    state.SetLabel(kShapes[state.range(0)]);
    for (auto _ : state) benchmark::DoNotOptimize(shape(static_cast<int>(state.range(0)), 1e-6));
}
BENCHMARK(GenerateAndValidate)->DenseRange(0, 6)->Unit(benchmark::kMicrosecond);

void ExactCapacities(benchmark::State& state) {
    state.SetLabel(kShapes[state.range(0)]);
    const plascap::ValidSection section = shape(static_cast<int>(state.range(0)), 1e-6);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::compute_capacities(section));
}
BENCHMARK(ExactCapacities)->DenseRange(0, 6)->Unit(benchmark::kMicrosecond);

void SaintVenantJ(benchmark::State& state) {
    state.SetLabel(kShapes[state.range(0)]);
    const plascap::ValidSection section = shape(static_cast<int>(state.range(0)), 1e-5);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::saint_venant_torsion(section, plascap::TorsionOptions{1e-4}));
}
BENCHMARK(SaintVenantJ)->DenseRange(0, 6)->Unit(benchmark::kMillisecond)->Iterations(5);

void SaintVenantJDefaultArcs(benchmark::State& state) {
    state.SetLabel(kShapes[state.range(0)]);
    const plascap::ValidSection section = shape(static_cast<int>(state.range(0)), 1e-6);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::saint_venant_torsion(section, plascap::TorsionOptions{1e-4}));
}
BENCHMARK(SaintVenantJDefaultArcs)->DenseRange(0, 6)->Unit(benchmark::kMillisecond)->Iterations(3);

void PlasticTorque(benchmark::State& state) {
    state.SetLabel(kShapes[state.range(0)]);
    const plascap::ValidSection section = shape(static_cast<int>(state.range(0)), 1e-4);
    for (auto _ : state) benchmark::DoNotOptimize(plascap::plastic_torsion(section, plascap::TorsionOptions{1e-3}));
}
BENCHMARK(PlasticTorque)->DenseRange(0, 6)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace
