// Writes Radiance triangle meshes (.rtm, "Radiance_tmesh") the way obj2mesh does: the same
// cube, uv limits, triangle octree, vertex sharing, patch layout and material records, so that
// Radiance's own reader (and read_mesh) accept the file and ray-trace it through its octree.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "radcl/scene/mesh.h"

namespace radcl::scene {

struct MeshWriteOptions {
  // Header lines between "#?RADIANCE" and FORMAT=, e.g. the producing command line.
  std::vector<std::string> header_lines;
  // obj2mesh's treatment of vertex normals: a triangle whose normals all lie within 0.18
  // degrees of its face normal is stored without them, and one whose normals all point
  // against its winding is turned over. Off: normals are kept as given.
  bool obj2mesh_normals = true;
  int objlim = 9;         // obj2mesh -n: triangles in an octree leaf before it is split
  int resolution = 16384; // obj2mesh -r: smallest leaf is cube size / resolution
};

struct MeshWriteInfo {
  // For each triangle in the order read_mesh() returns them: its index in the input mesh.
  // Triangles are stored in the octree-walk order obj2mesh uses, not in input order.
  std::vector<std::uint32_t> source_triangle;
  std::size_t skipped_degenerate = 0; // zero-area triangles, which obj2mesh drops too
  std::size_t vertices = 0, patches = 0, octree_leaves = 0;
  std::array<double, 3> cube_origin{0, 0, 0};
  double cube_size = 0;
};

// Appends the whole file to `out`. Uses positions, normals/uvs where vertex_flags has them
// (a triangle keeps a normal or uv only where all three of its vertices have one),
// triangles, triangle_material (empty: all void) and objects (the material definitions that
// triangle_material indexes; obj2mesh stores objects 0..highest used). Throws FatalError
// for a mesh obj2mesh could not write: no non-degenerate triangle, a material index without
// a definition, void faces mixed with materials, a non-modifier among the stored objects.
MeshWriteInfo encode_mesh(const TriangleMesh& mesh, std::string& out,
                          const MeshWriteOptions& options = {});

// encode_mesh() into a file, replaced only once the whole mesh has been written.
MeshWriteInfo write_mesh(const TriangleMesh& mesh, const std::string& path,
                         const MeshWriteOptions& options = {});

} // namespace radcl::scene
