// The folder holding the running program (from /proc/self/exe), for finding what ships beside
// it: the other tools a scene's commands call, the OpenImageIO module in ../lib.
#pragma once

#include <string>

namespace radcl {

// Empty if /proc/self/exe cannot be read.
std::string program_folder();

} // namespace radcl
