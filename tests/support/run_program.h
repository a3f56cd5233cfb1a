// The CLI and golden tests run the build's programs (rtrace, rpict, radcl) the same way: through
// the shell in some folder, standard input from text, and output and messages read back apart.
#pragma once

#include <string>
#include <utility>

namespace radcl::test {

struct ProgramRun {
  int rc = -1;     // exit status (run_command's)
  std::string out; // standard output (and messages too, with merge_err())
  std::string err; // standard error
};

// One program of the build and how to run it, set up by chained calls:
//   Program("rtrace").input(rays).in(dir).run("-h -ab 0 scene.rad")
class Program {
public:
  explicit Program(std::string name) : name_(std::move(name)) {}
  Program& input(std::string text) { // standard input
    input_ = std::move(text);
    return *this;
  }
  Program& in(std::string dir) { // the working folder; tests/data/scenes unless set
    dir_ = std::move(dir);
    return *this;
  }
  Program& env(std::string assignments) { // a prefix such as "RADCL_SEED=3 "
    env_ = std::move(assignments);
    return *this;
  }
  Program& merge_err() { // messages into out, in order (2>&1)
    merge_ = true;
    return *this;
  }
  // `<env> <bin_dir>/<name> <args>` through the shell.
  ProgramRun run(const std::string& args) const;

private:
  std::string name_, input_, dir_, env_;
  bool merge_ = false;
};

} // namespace radcl::test
