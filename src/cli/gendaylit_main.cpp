// gendaylit: radcl's own version of Radiance's generator (see radcl/sky/program.h).
#include "radcl/sky/program.h"

#include <cstdio>

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv, argv + argc);
  const radcl::sky::ProgramResult r = radcl::sky::run_gendaylit(args);
  // Warnings first: what Radiance's unbuffered stderr does when stdout is a pipe.
  std::fwrite(r.err.data(), 1, r.err.size(), stderr);
  std::fwrite(r.out.data(), 1, r.out.size(), stdout);
  return r.status;
}
