// Reader for Radiance octrees (.oct), frozen and unfrozen.
#pragma once

#include <string>

#include "radcl/scene/scene.h"

namespace radcl::scene {

// Reads `path`: header, cube, and the scene — re-read from the named .rad files (relative to the
// current directory) for an unfrozen octree, or decoded from the binary object section for a
// frozen one. The octree's own spatial tree is validated (object count, set members are
// surfaces) but not kept: radcl builds its own acceleration structure.
SceneDescription read_octree(const std::string& path);

} // namespace radcl::scene
