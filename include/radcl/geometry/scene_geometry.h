// The Embree scene built from a loaded Radiance scene: ray queries that give the hits Radiance's
// own intersection code gives (polygons as triangles refined against the polygon's plane,
// spheres/cones/cylinders/rings as exact double-precision user geometry, instances and meshes
// as Embree instances).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "radcl/scene/loader.h"

namespace radcl::geometry {

using Vec3d = std::array<double, 3>;

struct Hit {
  double t = 0;       // world distance along the (normalised) ray direction
  Vec3d point{};      // world coordinates
  Vec3d normal{};     // unit geometric normal in Radiance's orientation (not flipped to the ray)
  bool front = false; // the ray arrives against the normal (Radiance's rod > 0)
  std::int32_t object = -1;   // surface's object number in its own scene (placement().scene);
                              // for a mesh triangle: the mesh primitive's object number
  std::int32_t instance = -1; // main-scene object number of the outermost instance/mesh, or -1
  std::int32_t placement = 0; // index into SceneGeometry::placements() (0 = main scene)
  std::uint32_t prim = 0;     // triangle within the polygon / mesh triangle index; 0 otherwise
  float u = 0, v = 0;         // barycentrics of that triangle (p = (1-u-v)v0 + u v1 + v v2)
  // The surface's own tilt of the normal (Radiance's r->pert from o_mesh): on a mesh triangle
  // whose three vertices all carry normals, the unit world normal interpolated from them at the
  // hit, less `normal`; zero elsewhere. normal + pert is the smoothed normal.
  Vec3d pert{};
};

struct Ray {
  Vec3d org{};
  Vec3d dir{}; // need not be unit; it is normalised
  double tmin = 0;
  double tmax = 1e300;
  // The origin is a point placed off every surface (an -I meter's): tmin still holds, but no
  // surface passing within the origin's float rounding is taken to be the one it leaves.
  bool free_origin = false;
};

// Where a hit's surface comes from. Placement 0 is the main scene; every further one is an
// instanced octree or a mesh, nested instances flattened (Embree here allows one level).
struct Placement {
  const scene::SceneDescription* scene = nullptr; // scene that Hit::object indexes
  const scene::TriangleMesh* mesh = nullptr;      // set for a mesh placement
  std::string path;                               // octree/mesh key in LoadedScene
  std::int32_t instance_object = -1; // outermost instance/mesh primitive in the main scene
  // Radiance reports an instance with a non-void modifier as the hit surface (its modifier
  // shades everything inside). Outermost such instance, or shade_object = -1.
  const scene::SceneDescription* shade_scene = nullptr;
  std::int32_t shade_object = -1;
  // From the placed file's coordinates to world, row-vector convention (p' = p * m), and the
  // accumulated |scale|.
  std::array<std::array<double, 4>, 4> to_world{
      {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
  double scale = 1;
};

// A distant `source`: not part of the Embree scene; rays that hit nothing are tested here.
struct DistantSource {
  std::int32_t object = -1; // object number in the main scene
  Vec3d direction{};        // unit, towards the source
  double angle = 0;         // full apex angle, degrees
  double solid_angle = 0;   // 2 pi (1 - cos(angle/2))
};

// Surfaces placed in Embree, by type after Radiance's conversions (negative radii etc.). Each
// instanced file's surfaces are counted once however often it is placed.
struct SurfaceCounts {
  std::size_t polygons = 0, triangles = 0, spheres = 0, bubbles = 0, cones = 0, cups = 0,
              cylinders = 0, tubes = 0, rings = 0, instances = 0, meshes = 0, mesh_triangles = 0,
              sources = 0;
  std::size_t skipped_void = 0;       // surfaces without a material (invisible)
  std::size_t skipped_degenerate = 0; // zero-area polygons, cones without orientation
};

struct GeometryOptions {
  // Hits closer than this (world distance) are ignored so that rays leaving a surface do not
  // hit it again. 0: automatic, Radiance's FTINY (1e-6) but at most 1e-7 x the scene diagonal
  // (so that a model in km units behaves as in m), and at least 1e-7 x the largest coordinate
  // of the ray's origin relative to the scene's centre (float rounding far from it).
  double epsilon = 0;
};

class SceneGeometry {
public:
  // Keeps pointers to `scene.main` (placements, shade_scene): it must outlive this object;
  // instanced octrees and meshes are held by their shared pointers.
  // Throws FatalError in Radiance's form for illegal surfaces ("zero radius for sphere \"s\"",
  // "illegal radii for cone \"c\"", "bad # arguments for ..."), unknown instance files and
  // Embree errors; warns (radcl::warning) as Radiance does for zero area, negative radii.
  explicit SceneGeometry(const scene::LoadedScene& scene, const GeometryOptions& options = {});
  ~SceneGeometry();
  SceneGeometry(const SceneGeometry&) = delete;
  SceneGeometry& operator=(const SceneGeometry&) = delete;
  SceneGeometry(SceneGeometry&&) noexcept;
  SceneGeometry& operator=(SceneGeometry&&) noexcept;

  // Nearest hit with tmin < t <= tmax (world distances; t > epsilon() unless tmin < 0, which
  // says the origin is off every surface: then any t > 0). free_origin: as in Ray.
  std::optional<Hit> intersect(const Vec3d& org, const Vec3d& dir, double tmin = 0,
                               double tmax = 1e300, bool free_origin = false) const;
  // Whether anything lies in (tmin, tmax).
  bool occluded(const Vec3d& org, const Vec3d& dir, double tmin = 0, double tmax = 1e300,
                bool free_origin = false) const;

  // Rays [0, n) on the caller's thread, each answered as intersect() answers it: Embree
  // traverses them in packets of packet_width() (rays that leave one point, as a hemisphere's
  // samples, share its node visits), each lane set up and answered in double on its own.
  void intersect_block(const Ray* rays, std::size_t n, std::optional<Hit>* hits) const;
  int packet_width() const;

  // Waves of rays, in parallel over the host cores. Output spans must match the input size.
  void intersect(std::span<const Ray> rays, std::span<std::optional<Hit>> hits) const;
  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;
  // The machine's limit for the same rays, for tests/bench/embree_rays: Embree's float
  // traversal alone (every candidate accepted, nothing tested or rebuilt in double), each
  // ray's float distance (infinity: a miss) written to `t`. Not an answer to shade with.
  // `width`: rays per Embree call (1, 4, 8, 16; 0: packet_width(), as intersect_block).
  void intersect_raw(std::span<const Ray> rays, std::span<float> t, int width = 0) const;

  // World bounding box of everything in Embree (double); its centre is the re-centring origin.
  std::array<Vec3d, 2> bounds() const;
  Vec3d centre() const;
  double epsilon() const;
  const SurfaceCounts& counts() const;
  const std::vector<DistantSource>& distant_sources() const;
  const std::vector<Placement>& placements() const;

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
};

} // namespace radcl::geometry
