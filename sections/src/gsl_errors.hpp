#pragma once
// GSL's default error handler aborts the program. While any of these scopes is alive GSL returns
// its status codes instead, and the callers turn them into error estimates or messages. GSL's
// handler is process-wide, so the scopes are counted: the first one (on any thread) turns the
// handler off, the last one to end restores the previous handler. Threads may compute sections
// in parallel (the shape table does).
#include <gsl/gsl_errno.h>

#include <mutex>

namespace plascap::detail {

class GslErrorsReturned {
public:
    GslErrorsReturned() {
        const std::lock_guard<std::mutex> lock(state().mutex);
        if (state().scopes++ == 0) state().previous = gsl_set_error_handler_off();
    }
    ~GslErrorsReturned() {
        const std::lock_guard<std::mutex> lock(state().mutex);
        if (--state().scopes == 0) gsl_set_error_handler(state().previous);
    }
    GslErrorsReturned(const GslErrorsReturned&) = delete;
    GslErrorsReturned& operator=(const GslErrorsReturned&) = delete;

private:
    struct State {
        std::mutex mutex;
        int scopes = 0;
        gsl_error_handler_t* previous = nullptr;
    };
    static State& state() {
        static State s;
        return s;
    }
};

}  // namespace plascap::detail
