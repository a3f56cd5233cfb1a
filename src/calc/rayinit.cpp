#include <filesystem>

#include "radcl/calc/program.h"
#include "radcl/util/error.h"

#ifndef RADCL_SOURCE_LIB
#define RADCL_SOURCE_LIB ""
#endif
#ifndef RADCL_INSTALL_LIB
#define RADCL_INSTALL_LIB ""
#endif

namespace radcl::calc {

std::string Program::rayinit_path() {
  for (const char* dir : {RADCL_SOURCE_LIB, RADCL_INSTALL_LIB}) {
    if (!*dir) continue;
    std::filesystem::path p = std::filesystem::path(dir) / "rayinit.cal";
    if (std::filesystem::exists(p)) return p.string();
  }
  throw FatalError("cannot find function file \"rayinit.cal\"");
}

void Program::load_rayinit() {
  load_file(rayinit_path(), "");
}

} // namespace radcl::calc
