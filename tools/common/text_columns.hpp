#pragma once
// Fixed-width text columns for the tools' tables.
#include <cstddef>
#include <string>

namespace plascap::tools {

// Pads to `width` columns as a terminal shows them (UTF-8 continuation bytes take none).
inline std::string padded(const std::string& text, std::size_t width) {
    std::size_t columns = 0;
    for (unsigned char ch : text) columns += (ch & 0xC0) != 0x80;
    return text + std::string(columns < width ? width - columns : 0, ' ');
}

}  // namespace plascap::tools
