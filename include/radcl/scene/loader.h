// Loads what rtrace/rpict are given: one octree, or one or more .rad files, plus every octree
// and mesh that instance/mesh primitives reference (each file loaded once).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "radcl/scene/mesh.h"
#include "radcl/scene/scene.h"

namespace radcl::scene {

struct LoadedScene {
  SceneDescription main;
  // Keyed by the path found on RAYPATH; instance/mesh primitives name them in sargs[0].
  std::map<std::string, std::shared_ptr<const SceneDescription>> octrees;
  std::map<std::string, std::shared_ptr<const TriangleMesh>> meshes;
};

// An input ending in ".oct" or starting with the octree magic is an octree (only one allowed);
// anything else is read as scene files. Instance octrees are loaded recursively; a cycle of
// instances is a fatal error.
LoadedScene load_scene(const std::vector<std::string>& inputs);

// An octree given as bytes (rpict with no octree argument reads it from standard input), with
// the instances and meshes it references. `name` labels error messages.
LoadedScene load_octree_data(std::string bytes, const std::string& name);

} // namespace radcl::scene
