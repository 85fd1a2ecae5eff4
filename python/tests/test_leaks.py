"""The module does not leak: 10^5 calls keep the resident memory flat."""
import gc

import plascap


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def test_a_hundred_thousand_calls_keep_memory_flat():
    section = plascap.Section.rectangle(0.2, 0.1, fy=1e5)
    for _ in range(10_000):  # warm up: allocator pools, pybind11's type caches
        section.capacities().as_dict()
    gc.collect()
    before = resident_bytes()
    for i in range(100_000):
        c = section.capacities(only="N,Mx") if i % 2 else section.capacities()
        c.as_dict()
        if i % 1000 == 0:
            plascap.Section.rectangle(0.2 + i * 1e-9, 0.1, fy=1e5)
    gc.collect()
    grown = resident_bytes() - before
    assert grown < 2 * 1024 * 1024, f"resident memory grew {grown} bytes over 10^5 calls"
