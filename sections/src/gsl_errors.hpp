#pragma once
// GSL's default error handler aborts the program. Inside this scope GSL returns its status codes
// instead, and the callers turn them into error estimates or messages. Restores the previous
// handler on exit (GSL's handler is process-wide: not thread-safe).
#include <gsl/gsl_errno.h>

namespace plascap::detail {

class GslErrorsReturned {
public:
    GslErrorsReturned() : previous_(gsl_set_error_handler_off()) {}
    ~GslErrorsReturned() { gsl_set_error_handler(previous_); }
    GslErrorsReturned(const GslErrorsReturned&) = delete;
    GslErrorsReturned& operator=(const GslErrorsReturned&) = delete;

private:
    gsl_error_handler_t* previous_;
};

}  // namespace plascap::detail
