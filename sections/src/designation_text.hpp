#pragma once
// How a shape designation is read before it is matched or parsed: upper case, '×' (UTF-8) and '*'
// as 'X', a decimal comma as a point. Shared by the catalogue lookup and the parametric parser.
#include <cctype>
#include <string>
#include <string_view>

namespace plascap::detail {

inline std::string designation_upper(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == 0xC3 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x97) {
            out += 'X';  // '×'
            ++i;
        } else {
            out += c == '*' ? 'X' : c == ',' ? '.' : static_cast<char>(std::toupper(c));
        }
    }
    return out;
}

}  // namespace plascap::detail
