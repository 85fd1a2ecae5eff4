#pragma once
// Which capacities a caller wants. compute_capacities() does only the work they need:
// N and Q cost one pass over the vertices, Mx and Mz a neutral-axis solve each, My one
// transcendental per edge.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace plascap {

// The paper's six, and the three whose value depends on the sign of the load when a material's
// compression strength differs from its tension strength (capacities.hpp gives the convention).
enum class Capacity : std::uint8_t { N, Qx, Qz, Mx, Mz, My, N_neg, Mx_neg, Mz_neg };
inline constexpr std::size_t kCapacityCount = 9;
inline constexpr std::array<Capacity, kCapacityCount> kAllCapacities = {
    Capacity::N, Capacity::Qx, Capacity::Qz, Capacity::Mx, Capacity::Mz, Capacity::My,
    Capacity::N_neg, Capacity::Mx_neg, Capacity::Mz_neg};

// "N", "Qx", "Qz", "Mx", "Mz", "My", "N_neg", "Mx_neg", "Mz_neg".
std::string to_string(Capacity capacity);

class CapacitySet {
public:
    constexpr CapacitySet() = default;
    static constexpr CapacitySet all() { return CapacitySet(0x1ff); }

    constexpr CapacitySet& insert(Capacity c) {
        bits_ |= bit(c);
        return *this;
    }
    constexpr bool contains(Capacity c) const { return (bits_ & bit(c)) != 0; }
    constexpr bool empty() const { return bits_ == 0; }

    // A comma-separated list such as "N,My"; throws InputError naming an unknown entry.
    static CapacitySet parse(std::string_view list);

private:
    constexpr explicit CapacitySet(std::uint16_t bits) : bits_(bits) {}
    static constexpr std::uint16_t bit(Capacity c) { return static_cast<std::uint16_t>(1u << static_cast<unsigned>(c)); }
    std::uint16_t bits_ = 0;
};

}  // namespace plascap
