#pragma once
// Which capacities a caller wants. compute_capacities() does only the work they need:
// N and Q cost one pass over the vertices, Mx and Mz a neutral-axis solve each, My one
// transcendental per edge.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace plascap {

enum class Capacity : std::uint8_t { N, Qx, Qz, Mx, Mz, My };

inline constexpr std::array<Capacity, 6> kAllCapacities = {Capacity::N,  Capacity::Qx, Capacity::Qz,
                                                           Capacity::Mx, Capacity::Mz, Capacity::My};

// "N", "Qx", "Qz", "Mx", "Mz", "My".
std::string to_string(Capacity capacity);

class CapacitySet {
public:
    constexpr CapacitySet() = default;
    static constexpr CapacitySet all() { return CapacitySet(0x3f); }

    constexpr CapacitySet& insert(Capacity c) {
        bits_ |= bit(c);
        return *this;
    }
    constexpr bool contains(Capacity c) const { return (bits_ & bit(c)) != 0; }
    constexpr bool empty() const { return bits_ == 0; }

    // A comma-separated list such as "N,My"; throws InputError naming an unknown entry.
    static CapacitySet parse(std::string_view list);

private:
    constexpr explicit CapacitySet(std::uint8_t bits) : bits_(bits) {}
    static constexpr std::uint8_t bit(Capacity c) { return static_cast<std::uint8_t>(1u << static_cast<unsigned>(c)); }
    std::uint8_t bits_ = 0;
};

}  // namespace plascap
