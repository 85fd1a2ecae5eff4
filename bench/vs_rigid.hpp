#pragma once
// The engine benchmarks' common counters (issue 16): every variant's step time over the rigid
// baseline's — the same scene with the engine's own fixed joints — and the cost per joint.
//
// The ratio is timed interleaved: a batch of the variant's steps, then a batch of the baseline's,
// round after round, and vs_rigid is the median of the rounds' ratios. A machine that slows for a
// while (another process, a frequency change) slows both sides of a round alike, so the ratio does
// not depend on the minute it was measured in — as it did when the baseline was timed once, before
// the variants (a reading of 2.02 where the medians of the two times gave 1.15).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace bench {

// Seconds per call of `step` over one batch of `count` calls.
template <class Step>
double batch_seconds(Step&& step, int count) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / count;
}

inline double median(std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
}

// The median over 7 interleaved rounds of (a batch of `step`) / (a batch of `baseline`), after a
// warm-up of both; a batch is at least 5 steps and about 20,000 joint-steps.
template <class Step, class Baseline>
double interleaved_ratio(Step&& step, Baseline&& baseline, int joints) {
    const int per_batch = std::max(5, 20000 / joints);
    batch_seconds(step, 3);  // warm-up
    batch_seconds(baseline, 3);
    std::vector<double> ratios;
    for (int round = 0; round < 7; ++round) {
        const double own = batch_seconds(step, per_batch);
        ratios.push_back(own / batch_seconds(baseline, per_batch));
    }
    return median(ratios);
}

// Runs the benchmark loop over `step`; returns its seconds per step.
template <class Step>
double timed_loop(benchmark::State& state, Step&& step) {
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
           static_cast<double>(state.iterations());
}

inline void set_counters(benchmark::State& state, double own_seconds, double vs_rigid, int joints) {
    state.counters["vs_rigid"] = vs_rigid;
    state.counters["ns_per_joint"] = own_seconds / joints * 1e9;
}

// Times the benchmark loop over `step` (the reported time and ns_per_joint), then its ratio to
// `baseline_step`, which steps the rigid baseline's scene, interleaved (vs_rigid).
template <class Step, class Baseline>
void time_steps(benchmark::State& state, Step&& step, Baseline&& baseline_step, int joints) {
    const double own = timed_loop(state, step);
    set_counters(state, own, interleaved_ratio(step, baseline_step, joints), joints);
}

// The rigid baseline's own benchmark: its time and ns_per_joint; vs_rigid is 1 by definition.
template <class Step>
void time_baseline(benchmark::State& state, Step&& step, int joints) {
    set_counters(state, timed_loop(state, step), 1.0, joints);
}

}  // namespace bench
