#pragma once
// The exit-code contract every plascap tool keeps (README, "section-calc"): 0 on success, 2 on bad
// input or a bad command line with one message on stderr, 1 on an internal failure.
#include <CLI/CLI.hpp>

#include <iostream>

#include "plascap/input_error.hpp"

namespace plascap {

// Parses the command line into `app`'s options, then calls run() and maps its exceptions.
template <class Run>
int tool_main(const char* name, CLI::App& app, int argc, char** argv, Run run) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help, --version
    } catch (const CLI::ParseError& e) {
        std::cerr << name << ": error: " << e.what() << " (see --help)\n";
        return 2;
    }
    try {
        return run();
    } catch (const InputError& e) {
        std::cerr << name << ": error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << name << ": internal error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace plascap
