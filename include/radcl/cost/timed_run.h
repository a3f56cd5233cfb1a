// Runs a renderer as a user would, timed by the wall clock: its standard input and output
// files, extra environment variables, and its error output kept for a failure's message.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace radcl::cost {

struct TimedRun {
  std::vector<std::string> argv; // argv[0] is the program's path
  std::string in, out;           // files for standard input ("": /dev/null) and output
  std::vector<std::pair<std::string, std::string>> env; // set on top of ours
};

struct RunTime {
  double seconds = 0;
  int status = 0;     // exit status; 128 + signal when killed
  std::string errors; // the last 2,000 characters of its standard error
};

// Runs `r` to its end. Throws FatalError when it cannot be started.
RunTime run_timed(const TimedRun& r);

// run_timed, and FatalError with the program's message when it fails.
double run_or_fail(const TimedRun& r);

} // namespace radcl::cost
