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
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::int32_t> triangle_material; // index into `materials` per triangle (-1: void)
  std::vector<std::string> materials;          // modifier names used by the faces
  SceneDescription objects; // modifiers stored inside the mesh file (obj2mesh -a), if any
  std::array<double, 3> bbox_min{0, 0, 0}, bbox_max{0, 0, 0};
};

TriangleMesh read_mesh(const std::string& path);

} // namespace radcl::scene
