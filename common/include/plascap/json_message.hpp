#pragma once
// A JSON library's error text made fit for a user: without nlohmann's "[json.exception.<kind>.<id>] "
// prefix, and with bytes that are not printable ASCII shown as \xNN (the message quotes the
// offending input, which may be binary).
#include <cstdio>
#include <string>

namespace plascap {

inline std::string readable_json_message(std::string message) {
    if (!message.empty() && message[0] == '[') {
        const std::size_t end = message.find("] ");
        if (end != std::string::npos) message.erase(0, end + 2);
    }
    std::string printable;
    for (unsigned char c : message) {
        if (c >= 0x20 && c < 0x7f) {
            printable += static_cast<char>(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", c);
            printable += hex;
        }
    }
    return printable;
}

}  // namespace plascap
