#include "test_env.h"

#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>

namespace radcl::test {
namespace {
std::string env_or(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v ? v : fallback;
}
} // namespace

std::string data_dir() {
  return env_or("RADCL_TEST_DATA", "tests/data");
}
std::string bin_dir() {
  return env_or("RADCL_BIN", "build/bin");
}
std::string source_dir() {
  return env_or("RADCL_SOURCE_DIR", ".");
}
std::string data(const std::string& name) {
  return data_dir() + "/" + name;
}

int run_command(const std::string& cmd, std::string* out) {
  std::string full = cmd + " 2>&1";
  FILE* p = popen(full.c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0)
    if (out) out->append(buf, n);
  int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

} // namespace radcl::test
