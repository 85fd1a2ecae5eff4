#pragma once
// The one exception type for bad input: its message names the problem and where it is
// (e.g. "part 0, hole 1, vertex 3: ..."). Tools map it to exit code 2.
#include <stdexcept>
#include <string>

namespace plascap {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace plascap
