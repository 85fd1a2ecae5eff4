#pragma once
// The engine benchmarks' common counters (issue 16): every variant's step time over the rigid
// baseline's — the same scene with the engine's own fixed joints — measured in the same process, so
// that the ratio does not depend on the machine or its load that minute; and the cost per joint.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <utility>
#include <vector>

namespace bench {

// Seconds per call of `step`, the median of 5 batches after a warm-up.
template <class Step>
double seconds_per_step(Step&& step, int joints) {
    const int per_batch = std::max(5, 20000 / joints);
    for (int i = 0; i < 3; ++i) step();
    std::vector<double> batches;
    for (int b = 0; b < 5; ++b) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < per_batch; ++i) step();
        batches.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / per_batch);
    }
    std::nth_element(batches.begin(), batches.begin() + 2, batches.end());
    return batches[2];
}

// Runs the benchmark loop over `step`; returns its seconds per step.
template <class Step>
double timed_loop(benchmark::State& state, Step&& step) {
    const auto start = std::chrono::steady_clock::now();
    for (auto _ : state) step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
           static_cast<double>(state.iterations());
}

// Runs and times the loop over `step`, and sets the counters: vs_rigid (this step's time over
// `rigid` seconds) and ns_per_joint.
inline void set_counters(benchmark::State& state, double own, double rigid, int joints) {
    state.counters["vs_rigid"] = own / rigid;
    state.counters["ns_per_joint"] = own / joints * 1e9;
}

template <class Step>
void time_steps(benchmark::State& state, Step&& step, double rigid, int joints) {
    set_counters(state, timed_loop(state, step), rigid, joints);
}

// The rigid baseline's seconds per step for each (joints, setting): what the baseline benchmark
// itself last measured (time_baseline), or, when a filter left it out, measured once here.
inline std::map<std::pair<int, int>, double>& baselines() {
    static std::map<std::pair<int, int>, double> seen;
    return seen;
}

template <class Measure>
double cached_baseline(int joints, int setting, Measure&& measure) {
    const auto key = std::pair{joints, setting};
    if (auto it = baselines().find(key); it != baselines().end()) return it->second;
    return baselines()[key] = measure();
}

// Runs the rigid baseline's own benchmark loop and keeps its time for the variants after it.
template <class Step>
void time_baseline(benchmark::State& state, Step&& step, int joints, int setting) {
    const double own = baselines()[std::pair{joints, setting}] = timed_loop(state, step);
    set_counters(state, own, own, joints);
}

}  // namespace bench
