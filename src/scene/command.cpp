#include "radcl/scene/command.h"

#include <climits>
#include <cstdlib>
#include <mutex>
#include <unistd.h>

namespace radcl::scene {

namespace {

// The folder of /proc/self/exe, once; empty if it cannot be read.
std::string own_folder() {
  char buf[PATH_MAX];
  ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return {};
  std::string p(buf, static_cast<std::size_t>(n));
  std::size_t slash = p.rfind('/');
  return slash == std::string::npos ? std::string() : p.substr(0, slash);
}

} // namespace

std::FILE* open_command(const std::string& command) {
  static std::once_flag once;
  std::call_once(once, [] {
    std::string dir = own_folder();
    if (dir.empty()) return;
    const char* old = std::getenv("PATH");
    std::string path = old && *old ? std::string(old) + ":" + dir : dir;
    ::setenv("PATH", path.c_str(), 1);
  });
  return ::popen(command.c_str(), "r");
}

} // namespace radcl::scene
