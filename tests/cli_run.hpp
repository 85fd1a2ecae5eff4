#pragma once
// Runs a tool binary as a user would, for the end-to-end tests: exit code, stdout and stderr.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace plascap::test {

struct CliRun {
    int exit_code;
    std::string out;
    std::string err;
};

inline CliRun run_tool(const std::string& binary, const std::string& arguments) {
    // One stderr file per process: ctest runs the test cases in parallel.
    const std::string err_file = ::testing::TempDir() + "plascap_stderr_" + std::to_string(getpid()) + ".txt";
    const std::string command = "\"" + binary + "\" " + arguments + " 2>\"" + err_file + "\"";
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    const int status = pclose(pipe);
    std::stringstream err;
    err << std::ifstream(err_file).rdbuf();
    std::remove(err_file.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out, err.str()};
}

}  // namespace plascap::test
