// gensky and gendaylit as library functions: they take the command line (argv[0] included,
// used in messages like Radiance's progname) and return what the program writes, so tests
// can run them in-process and the executables stay thin.
#pragma once

#include <string>
#include <vector>

namespace radcl::sky {

struct ProgramResult {
  std::string out; // stdout
  std::string err; // stderr
  int status = 0;  // exit status
};

ProgramResult run_gensky(const std::vector<std::string>& argv);
ProgramResult run_gendaylit(const std::vector<std::string>& argv);

// Radiance's printargs: words separated by blanks, quoted when they hold white space or an
// inner quote, then a newline.
std::string format_command_line(const std::vector<std::string>& argv);

// printf into a std::string (C formatting is the specification of these outputs).
void appendf(std::string& s, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

// Thrown to end a run early with an exit status (Radiance's generators call exit()).
struct ProgramExit {
  int status;
};

} // namespace radcl::sky
