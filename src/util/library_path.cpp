#include "radcl/util/library_path.h"

#include <cstdlib>
#include <filesystem>
#include <pwd.h>
#include <unistd.h>

#include "radcl/util/program_folder.h"

#ifndef RADCL_SOURCE_LIB
#define RADCL_SOURCE_LIB ""
#endif
#ifndef RADCL_BUILD_BIN
#define RADCL_BUILD_BIN ""
#endif
#ifndef RADCL_LIB_FROM_BIN
#define RADCL_LIB_FROM_BIN "../lib/radcl"
#endif

namespace radcl {
namespace {

bool readable(const std::string& p) {
  return !p.empty() && access(p.c_str(), R_OK) == 0;
}

std::string join(const std::string& dir, const std::string& name) {
  if (dir.empty()) return name; // empty entry: the current directory
  return dir.back() == '/' ? dir + name : dir + "/" + name;
}

// "~/x" or "~user/x" -> home directory + "/x"; "" if the user is unknown.
std::string expand_home(const std::string& name) {
  std::size_t slash = name.find('/');
  std::string user = name.substr(1, slash == std::string::npos ? std::string::npos : slash - 1);
  std::string rest = slash == std::string::npos ? "" : name.substr(slash);
  const char* home = nullptr;
  if (user.empty()) {
    home = std::getenv("HOME");
    if (!home)
      if (const passwd* pw = getpwuid(getuid())) home = pw->pw_dir;
  } else if (const passwd* pw = getpwnam(user.c_str())) {
    home = pw->pw_dir;
  }
  return home ? std::string(home) + rest : "";
}

bool same_folder(const std::string& a, const std::string& b) {
  std::error_code ea, eb;
  return !a.empty() && !b.empty() &&
         std::filesystem::equivalent(std::filesystem::path(a), std::filesystem::path(b), ea) &&
         !ea && !eb;
}

} // namespace

std::string installed_library_dir() {
  std::string bin = program_folder();
  return bin.empty() ? "" : join(bin, RADCL_LIB_FROM_BIN);
}

std::vector<std::string> radcl_library_dirs() {
  if (const char* lib = std::getenv("RADCL_LIB"))
    return *lib ? std::vector<std::string>{lib} : std::vector<std::string>{};
  std::vector<std::string> dirs;
  if (std::string inst = installed_library_dir(); !inst.empty()) dirs.push_back(inst);
  // Only a program in the build tree reads the source tree: an installed copy must not depend
  // on the source tree being there.
  if (*RADCL_SOURCE_LIB && same_folder(program_folder(), RADCL_BUILD_BIN))
    dirs.emplace_back(RADCL_SOURCE_LIB);
  return dirs;
}

std::string find_library_file(const std::string& name) {
  if (name.empty()) return "";
  if (name[0] == '/' || name[0] == '.') return readable(name) ? name : "";
  if (name[0] == '~') {
    std::string p = expand_home(name);
    return readable(p) ? p : "";
  }
  const char* env = std::getenv("RAYPATH");
  std::string path = env ? env : ":/usr/local/lib/ray";
  // Entries as getpath() walks them: split at ':'; a trailing ':' adds no (empty) entry.
  std::size_t pos = 0;
  do {
    std::size_t end = path.find(':', pos);
    std::string dir = path.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    pos = end == std::string::npos ? path.size() : end + 1;
    std::string p = join(dir, name);
    if (readable(p)) return p;
  } while (pos < path.size());
  // radcl's own files (rayinit.cal, skybright.cal, ...) come last, so anything on RAYPATH,
  // Radiance's library included, wins.
  for (const std::string& dir : radcl_library_dirs())
    if (std::string p = join(dir, name); readable(p)) return p;
  return "";
}

} // namespace radcl
