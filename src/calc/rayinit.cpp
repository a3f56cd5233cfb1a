#include "radcl/calc/program.h"
#include "radcl/util/error.h"
#include "radcl/util/library_path.h"

namespace radcl::calc {

// Found as every function file is (RAYPATH, then radcl's own library), as Radiance finds it.
std::string Program::rayinit_path() {
  std::string p = find_library_file("rayinit.cal");
  if (p.empty()) throw FatalError("cannot find function file \"rayinit.cal\"");
  return p;
}

void Program::load_rayinit() {
  load_file(rayinit_path(), "");
}

} // namespace radcl::calc
