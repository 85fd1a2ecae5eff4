// repr(): the one format of the bindings' __repr__ for plain records.
#include <sstream>

#include "bindings.hpp"

namespace plascap::python {

std::string repr(const std::string& type, std::initializer_list<std::pair<const char*, double>> fields) {
    std::ostringstream out;
    out << type << '(';
    const char* separator = "";
    for (const auto& [name, value] : fields) {
        out << separator << name << '=' << value;
        separator = ", ";
    }
    out << ')';
    return out.str();
}

}  // namespace plascap::python
