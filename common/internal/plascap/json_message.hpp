#pragma once
// A JSON library's error text made fit for a user: without nlohmann's "[json.exception.<kind>.<id>] "
// prefix, and with bytes that are not printable ASCII shown as \xNN (the message quotes the
// offending input, which may be binary).
#include <cstdio>
#include <initializer_list>
#include <string>

#include "plascap/input_error.hpp"

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

// Throws InputError "WHERE: unknown key "K"WHAT (known keys: a, b, c)" for the first key of a JSON
// object (any type with items() yielding key()) that is not in `known`: a misspelt key must not be
// silently ignored.
template <class JsonObject>
void reject_unknown_keys(const JsonObject& object, const std::string& where, std::initializer_list<const char*> known,
                         const std::string& what = "") {
    for (const auto& item : object.items()) {
        bool ok = false;
        std::string list;
        for (const char* key : known) {
            ok = ok || item.key() == key;
            list += (list.empty() ? "" : ", ") + std::string(key);
        }
        if (!ok) throw InputError(where + ": unknown key \"" + item.key() + "\"" + what + " (known keys: " + list + ")");
    }
}

}  // namespace plascap
