// Reader for Radiance scene files (.rad): comments, !commands, primitives, alias.
#pragma once

#include <istream>
#include <string>

#include "radcl/scene/scene.h"

namespace radcl::scene {

// Appends the primitives of file `path` (opened relative to the current directory, as Radiance
// does; a name starting with '!' is run by /bin/sh and its output parsed) to `scene`.
// Throws FatalError with Radiance's message form, e.g.
//   (room.rad line 12): bad arguments for polygon "w1"
void read_rad_file(SceneDescription& scene, const std::string& path);

// Same for an already opened stream; `name` is used in messages.
void read_rad_stream(SceneDescription& scene, std::istream& in, const std::string& name);

} // namespace radcl::scene
