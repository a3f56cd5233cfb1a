#include "run_program.h"

#include "files.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::test {

ProgramRun Program::run(const std::string& args) const {
  // Input and output through files: run_command's own 2>&1 would mix messages into the output.
  const TempFolder io("run");
  write_file(io / "in", input_);
  const std::string out = (io / "out").string(), err = (io / "err").string();
  ProgramRun r;
  r.rc = run_command("(cd " + (dir_.empty() ? data("scenes") : dir_) + " && " + env_ + bin_dir() +
                     "/" + name_ + " " + args + " < " + (io / "in").string() + " > " + out +
                     (merge_ ? " 2>&1" : " 2> " + err) + ")");
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

} // namespace radcl::test
