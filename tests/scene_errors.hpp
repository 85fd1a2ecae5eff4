#pragma once
// The message a scene's text is refused with, for the reader's tests; "(accepted)" if it is not.
#include <string>

#include "plascap/input_error.hpp"
#include "scene.hpp"

namespace plascap::test {

inline std::string scene_error(const std::string& text) {
    try {
        parse_scene_json(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace plascap::test
