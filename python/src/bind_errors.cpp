// Bad input raises plascap.InputError, a ValueError carrying the message the command-line tools
// print after "error:" (plascap::InputError names the problem and where it is).
#include "bindings.hpp"
#include "plascap/input_error.hpp"

namespace plascap::python {

void bind_errors(py::module_& m) {
    py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
}

}  // namespace plascap::python
