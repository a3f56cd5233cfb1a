// Reader for Radiance octrees (.oct), frozen and unfrozen.
#pragma once

#include <string>

#include "radcl/scene/rad_reader.h"
#include "radcl/scene/scene.h"

namespace radcl::scene {

// Reads `path`: header, cube, and the scene — re-read from the named .rad files (relative to the
// current directory) for an unfrozen octree, or decoded from the binary object section for a
// frozen one. The octree's own spatial tree is validated (object count, set members are
// surfaces) but not kept: radcl builds its own acceleration structure.
// A path starting with '!' is a command whose output is the octree.
SceneDescription read_octree(const std::string& path);

// The same for an octree already in memory (rpict reading it from standard input); `name`
// labels error messages, `policy` governs reading the scene files an unfrozen octree names.
SceneDescription read_octree_data(std::string bytes, const std::string& name,
                                  const ReadPolicy& policy = {});

class ByteReader;

// Decodes Radiance's binary scene section (frozen octrees, mesh materials): the type-name
// table, then object records appended to `scene` with modifier numbers offset by the objects
// already there, up to the 0xFF end marker. Returns false when the data ended before the
// marker at a record boundary (Radiance treats that as the end; callers decide).
bool read_binary_scene(ByteReader& in, int objsize, SceneDescription& scene);

} // namespace radcl::scene
