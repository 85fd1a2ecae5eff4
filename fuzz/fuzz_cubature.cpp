// libFuzzer target: any bytes through the section reader, validation and the cubature route
// (CGAL mesh with the kink cuts, Delaunay refinement for the fixed rule, GSL cubature).
// Contract under test: an InputError, or finite non-negative capacities with finite non-negative
// error estimates; never a crash, a hang (runaway refinement) or another exception.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "plascap/input_error.hpp"
#include "plascap/sections/cubature.hpp"
#include "plascap/sections/section_json.hpp"

namespace {

void check(const plascap::CubatureResult& r) {
    for (plascap::Capacity k : plascap::kAllCapacities) {
        const double value = *r.capacities.get(k), error = *r.estimated_error(k);
        if (!std::isfinite(value) || value < 0.0 || !std::isfinite(error) || error < 0.0) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const plascap::ValidSection section = plascap::validate_section(plascap::parse_section_json(text));
        plascap::CubatureOptions options;
        options.tolerance = 1e-6;
        check(plascap::cubature_capacities(section, plascap::CapacitySet::all(), options));
        options.rule = plascap::CubatureRule::Fixed;
        options.order = 3;
        check(plascap::cubature_capacities(section, plascap::CapacitySet::all(), options));
    } catch (const plascap::InputError&) {
        // refused with a message: fine
    }
    return 0;
}
