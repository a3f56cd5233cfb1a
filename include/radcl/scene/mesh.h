// Radiance triangle meshes (.rtm, "Radiance_tmesh", written by obj2mesh).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "radcl/scene/scene.h"

namespace radcl::scene {

struct TriangleMesh {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<float, 3>> normals; // per vertex; empty if the mesh has none
  std::vector<std::array<float, 2>> uvs;     // per vertex; empty if the mesh has none
  // Per vertex: which of normal/uv the file gives (obj2mesh drops the normals of flat
  // triangles, so a mesh can mix vertices with and without them). Unset entries above are 0.
  std::vector<std::uint8_t> vertex_flags;
  static constexpr std::uint8_t kHasNormal = 1, kHasUV = 2;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::int32_t> triangle_material; // index into `materials` per triangle (-1: void)
  std::vector<std::string> materials;          // names of `objects.objects`, same indices
  // Modifiers stored inside the mesh file (obj2mesh -a/-l). Without them every face is void,
  // and only a non-void modifier on the mesh primitive itself can shade it.
  SceneDescription objects;
  std::array<double, 3> bbox_min{0, 0, 0}, bbox_max{0, 0, 0};
};

// Throws FatalError("(<path>): <Radiance's message>") on bad or truncated data, and
// "cannot open mesh file \"<path>\"" when it cannot be read.
TriangleMesh read_mesh(const std::string& path);

// The same for a mesh file already in memory; `name` labels error messages.
TriangleMesh read_mesh_data(std::string bytes, const std::string& name);

} // namespace radcl::scene
