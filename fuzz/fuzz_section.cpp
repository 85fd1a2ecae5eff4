// libFuzzer target: any bytes through the section reader, validation and the exact route.
// Contract under test: either an InputError, or finite non-negative capacities; never a crash,
// a hang or another exception. Build and run: see docs/fuzzing.md.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "plascap/input_error.hpp"
#include "plascap/sections/capacities.hpp"
#include "plascap/sections/section_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const plascap::Capacities c = plascap::compute_capacities(plascap::validate_section(plascap::parse_section_json(text)));
        for (plascap::Capacity k : plascap::kAllCapacities) {
            const double value = *c.get(k);
            if (!std::isfinite(value) || value < 0.0) std::abort();
        }
    } catch (const plascap::InputError&) {
        // refused with a message: fine
    }
    return 0;
}
