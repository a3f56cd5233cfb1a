// Auxiliary-file search (scene-format.md §1.4, octree-format.md §6.1), then radcl's own lib/.
#include "radcl/scene/raypath.h"

#include <cstdlib>
#include <pwd.h>
#include <unistd.h>

#ifndef RADCL_SOURCE_LIB
#define RADCL_SOURCE_LIB ""
#endif
#ifndef RADCL_INSTALL_LIB
#define RADCL_INSTALL_LIB ""
#endif

namespace radcl::scene {
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

} // namespace

std::string find_on_raypath(const std::string& name) {
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

  // radcl's own function files (rayinit.cal, skybright.cal, ...) come last, so anything on
  // RAYPATH, Radiance's library included, wins.
  // RADCL_LIB replaces both built-in directories; set but empty, it turns them off.
  if (const char* lib = std::getenv("RADCL_LIB")) {
    std::string p = *lib ? join(lib, name) : "";
    return readable(p) ? p : "";
  }
  for (const char* dir : {RADCL_SOURCE_LIB, RADCL_INSTALL_LIB}) {
    std::string p = *dir ? join(dir, name) : "";
    if (readable(p)) return p;
  }
  return "";
}

} // namespace radcl::scene
