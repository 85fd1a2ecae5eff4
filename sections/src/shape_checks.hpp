#pragma once
// Dimension checks shared by the shape outlines: each throws InputError naming the dimension and
// its value in millimetres (the unit of every published shape table).
#include <cmath>
#include <sstream>
#include <string>

#include "plascap/input_error.hpp"

namespace plascap::detail {

inline std::string mm(double metres) {
    std::ostringstream out;
    out.precision(6);
    out << metres * 1e3 << " mm";
    return out.str();
}

struct Dimension {
    const char* name;
    double value;  // [m]
    std::string text() const { return std::string(name) + " = " + mm(value); }
};

inline void require_positive(Dimension d) {
    if (!std::isfinite(d.value) || d.value <= 0.0)
        throw InputError(std::string(d.name) + " must be a positive length (got " +
                         (std::isfinite(d.value) ? mm(d.value) : std::string("not a finite number")) + ")");
    if (d.value > 1e3) throw InputError(d.text() + " is larger than any structural shape (at most 1000 m)");
}

inline void require_non_negative(Dimension d) {
    if (!std::isfinite(d.value) || d.value < 0.0)
        throw InputError(std::string(d.name) + " must be zero or a positive length (got " +
                         (std::isfinite(d.value) ? mm(d.value) : std::string("not a finite number")) + ")");
}

// a < limit, where limit is described by `what` (e.g. "b" or "h/2").
inline void require_less(Dimension a, double limit, const std::string& what) {
    if (!(a.value < limit)) throw InputError(a.text() + " must be less than " + what + " = " + mm(limit));
}

inline void require_at_most(Dimension a, double limit, const std::string& what) {
    if (!(a.value <= limit * (1.0 + 1e-12)))
        throw InputError(a.text() + " does not fit: it must be at most " + what + " = " + mm(limit));
}

}  // namespace plascap::detail
