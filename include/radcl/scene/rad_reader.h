// Reader for Radiance scene files (.rad): comments, !commands, primitives, alias.
#pragma once

#include <istream>
#include <string>

#include "radcl/scene/scene.h"

namespace radcl::scene {

// What reading a scene may do besides parsing bytes. Everything is allowed by default, as in
// Radiance; callers that read untrusted input (the fuzz targets) turn the side effects off, and
// a disabled action is a FatalError like any other bad input.
struct ReadPolicy {
  bool run_commands = true; // `!command` lines and '!' file names, run by /bin/sh
  bool open_files = true;   // scene files named by path (e.g. in an unfrozen octree)
};

// Appends the primitives of file `path` (opened relative to the current directory, as Radiance
// does; a name starting with '!' is run by /bin/sh and its output parsed) to `scene`.
// Throws FatalError with Radiance's message form, e.g.
//   (room.rad line 12): bad arguments for polygon "w1"
void read_rad_file(SceneDescription& scene, const std::string& path, const ReadPolicy& policy = {});

// Same for an already opened stream; `name` is used in messages.
void read_rad_stream(SceneDescription& scene, std::istream& in, const std::string& name,
                     const ReadPolicy& policy = {});

// Checks a primitive's argument counts (and its transform, where its type has one whose
// position is known without reading data files) against the limits of Radiance's code for
// that type. Returns "" if fine, else the problem ("bad # arguments", "bad transform"), which
// the reader reports as `(file line N): bad # arguments for plastic "x"`.
std::string check_arguments(const Object& obj);

} // namespace radcl::scene
