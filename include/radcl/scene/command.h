// Scene commands (`!gensky 3 21 12`, `!xform ...`): run through the shell as Radiance does,
// with radcl's own tools (gensky, gendaylit) found even where Radiance is not installed.
#pragma once

#include <cstdio>
#include <string>

namespace radcl::scene {

// popen(command, "r") with the folder of the running radcl executable added at the end of
// PATH (the user's own tools, e.g. an installed Radiance, still come first).
std::FILE* open_command(const std::string& command);

} // namespace radcl::scene
