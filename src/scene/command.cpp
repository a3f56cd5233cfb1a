#include "radcl/scene/command.h"

#include <cstdlib>
#include <mutex>

#include "radcl/util/program_folder.h"

namespace radcl::scene {

std::FILE* open_command(const std::string& command) {
  static std::once_flag once;
  std::call_once(once, [] {
    std::string dir = program_folder();
    if (dir.empty()) return;
    const char* old = std::getenv("PATH");
    std::string path = old && *old ? std::string(old) + ":" + dir : dir;
    ::setenv("PATH", path.c_str(), 1);
  });
  return ::popen(command.c_str(), "r");
}

} // namespace radcl::scene
