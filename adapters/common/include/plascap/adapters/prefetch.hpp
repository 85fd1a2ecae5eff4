#pragma once
// Asking the CPU to load a joint's memory before it is needed. A plastic joint's state is a few
// kilobytes (its law, driver and engine rows); a world steps its joints in turn, and once they
// no longer fit in the cache (a few thousand joints), each joint's turn waited on memory: the
// adapter's own share of a step grew 2.4× per joint from 1,000 to 10,000 joints (bench_ode_joints).
// Loading the joint a few turns ahead while the current one computes brought that share back to its
// 1,000-joint cost (docs/adapters.md, "Cost").
// __builtin_prefetch is GCC's and Clang's ("Other Built-in Functions", GCC manual): a hint that
// never faults, so any address may be given.
#include <cstddef>

namespace plascap {

// How many joints ahead a world's loop loads: enough to hide a memory access behind the joints'
// work (about 0.1–0.3 µs each), few enough that the loaded lines are still in the cache when used.
inline constexpr std::size_t kPrefetchAhead = 4;
// What a joint's object points to (its engine rows) is loaded half as far ahead: the pointer is read
// from the object, which must have arrived by then, or reading it waits on memory.
inline constexpr std::size_t kPrefetchRowsAhead = kPrefetchAhead / 2;

// A group of joints loads ahead once their state passes this size: below it the state stays in
// the cache from one step to the next (1,000 ODE joints, 3.4 MB, cost the same per joint as 100),
// and the prefetches would only add their instructions (about 1 % of a joint's step).
inline constexpr std::size_t kPrefetchFromBytes = std::size_t{4} << 20;

inline constexpr std::size_t kCacheLine = 64;  // bytes, on x86-64 and ARMv8 cores

enum class PrefetchFor { Reading = 0, Writing = 1 };  // __builtin_prefetch's second argument

// Loads the cache lines of the `Bytes` bytes from `start`: one prefetch per line, unrolled (as a
// loop, the count, the add and the branch tripled the instructions). GCC 12 dropped every prefetch
// of a fold expression of 45 of them; this loop keeps them all.
template <std::size_t Bytes, PrefetchFor use>
void prefetch_bytes(const void* start) {
    constexpr std::size_t kLines = (Bytes + kCacheLine - 1) / kCacheLine;
    const char* bytes = static_cast<const char*>(start);
#pragma GCC unroll 128
    for (std::size_t line = 0; line < kLines; ++line)
        __builtin_prefetch(bytes + line * kCacheLine, static_cast<int>(use));
}

// Loads `object` for reading and writing.
template <class T>
void prefetch_object(const T* object) {
    prefetch_bytes<sizeof(T), PrefetchFor::Writing>(object);
}

}  // namespace plascap
