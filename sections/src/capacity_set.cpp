#include "plascap/sections/capacity_set.hpp"

#include "plascap/input_error.hpp"

namespace plascap {

std::string to_string(Capacity capacity) {
    switch (capacity) {
        case Capacity::N: return "N";
        case Capacity::Qx: return "Qx";
        case Capacity::Qz: return "Qz";
        case Capacity::Mx: return "Mx";
        case Capacity::Mz: return "Mz";
        case Capacity::My: return "My";
        case Capacity::N_neg: return "N_neg";
        case Capacity::Mx_neg: return "Mx_neg";
        case Capacity::Mz_neg: return "Mz_neg";
    }
    return "?";
}

CapacitySet CapacitySet::parse(std::string_view list) {
    CapacitySet set;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        std::string_view name = list.substr(start, comma - start);
        while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
        while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
        bool known = false;
        for (Capacity c : kAllCapacities) {
            if (name == to_string(c)) {
                set.insert(c);
                known = true;
            }
        }
        if (!known)
            throw InputError("unknown capacity '" + std::string(name) + "' (choose from N, Qx, Qz, Mx, Mz, My, N_neg, Mx_neg, Mz_neg)");
        start = comma + 1;
    }
    return set;
}

}  // namespace plascap
