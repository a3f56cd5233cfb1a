// Paths the test environment provides (set by tests/CMakeLists.txt for every test).
#pragma once

#include <string>

namespace radcl::test {

std::string data_dir();                    // tests/data
std::string bin_dir();                     // build/bin
std::string source_dir();                  // repository root
std::string data(const std::string& name); // data_dir() + "/" + name

// Runs a shell command, returns its exit status; stdout and stderr captured into `out`.
int run_command(const std::string& cmd, std::string* out = nullptr);

} // namespace radcl::test
