// Internal state of SceneGeometry, shared by the builder, the Embree callbacks and queries.
//
// Every placed file (the main scene, each instanced octree, each mesh) is a *prototype*: its
// surfaces in its own coordinates minus its bounding-box centre, converted to float only then.
// The main prototype's Embree scene is the top-level scene; other prototypes are Embree
// instances in it. Callbacks never use Embree's float ray: they take the caller's double ray
// from the intersect context and map it with the placement's double transform.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "analytic.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/geometry/triangulate.h"
#include "vec.h"

namespace radcl::geometry {

struct PolygonRecord {
  std::int32_t object = -1;
  Vec3 normal{};
  double offset = 0; // plane: normal . p = offset (prototype-centred once built)
  std::uint32_t first_triangle = 0;
};

// Leaf surfaces of one file, in that file's coordinates.
struct LeafSet {
  std::vector<PolygonRecord> polygons;
  std::vector<Vec3> vertices; // polygon vertices projected onto their plane
  std::vector<Tri> triangles;
  std::vector<std::uint32_t> triangle_polygon; // triangle -> polygon record
  std::vector<AnalyticSurface> analytic;
  std::array<Vec3, 2> bounds{};
  bool empty = true;
  void grow(const std::array<Vec3, 2>& b);
};

struct Prototype {
  RTCScene scene = nullptr;
  Vec3 centre{};
  std::array<Vec3, 2> bounds{}; // in the file's own coordinates
  bool empty = true;
  unsigned tri_geom = RTC_INVALID_GEOMETRY_ID;
  unsigned user_geom = RTC_INVALID_GEOMETRY_ID;
  std::vector<PolygonRecord> polygons;
  std::vector<std::uint32_t> triangle_polygon;
  std::vector<AnalyticSurface> analytic;
  // Meshes: Embree triangle -> mesh triangle, and the mesh's vertices (centred).
  const scene::TriangleMesh* mesh = nullptr;
  std::vector<std::uint32_t> mesh_triangle;
  std::vector<Vec3> mesh_vertices;
};

struct PlacementRecord {
  int prototype = 0;
  Affine to_world;   // file coordinates -> world
  Affine from_world; // world -> prototype-centred coordinates
  std::int32_t mesh_object = -1;
};

struct SceneGeometry::Impl {
  RTCDevice device = nullptr;
  RTCScene top = nullptr; // also prototypes[0].scene
  std::string embree_error;
  std::deque<Prototype> prototypes; // stable addresses: Embree holds pointers to them
  std::vector<PlacementRecord> records;
  std::vector<Placement> placements;
  std::vector<int> top_geom_placement; // top-level geomID -> placement (instances only)
  std::array<Vec3, 2> world_bounds{};
  Vec3 centre{};
  double eps = 1e-6;    // nearest hit a query accepts, at least
  double eps_rel = 0;   // and this times the ray origin's largest centred coordinate
  double margin = 1e-6; // slack for Embree's float distances
  double radius = 0;    // of the bounding sphere about the centre, margin included
  double far = 0;       // origins farther (largest centred coordinate) start at that sphere
  // Rays a query block hands Embree at once (1, 4, 8 or 16): the widest packet the CPU
  // traverses natively, or RADCL_RAY_PACKET's.
  int packet = 1;
  SurfaceCounts counts;
  std::vector<DistantSource> sources;
  std::vector<std::shared_ptr<const void>> keep_alive; // placed octrees and meshes

  ~Impl();
  void check_embree() const; // throws FatalError if Embree reported an error
  const PlacementRecord& record_for_instance(unsigned inst_id) const {
    return records[inst_id == RTC_INVALID_GEOMETRY_ID ? 0 : top_geom_placement[inst_id]];
  }
};

// The caller's ray, carried through Embree to the callbacks (Embree hands back the context
// pointer it was given, so the extension must follow the Embree context).
struct RayContext {
  RTCIntersectContext ctx;
  const SceneGeometry::Impl* impl = nullptr;
  Vec3 org{}, dir{}; // world, dir unit
  // The main scene's local ray (org less the centre) and |dir|, made once per query: most
  // candidates are its surfaces, and each filter call would otherwise transform and measure.
  Vec3 org0{};
  double len0 = 1;
  double tmin = 0, tmax = 0;
  double shift = 0; // a far origin moved this far along the ray to the scene (setup in query)
  // An origin this close (world distance) to a surface lies on it (float rounding of the point
  // the ray leaves): that surface is not met again at the origin (intersect_analytic).
  double on = 0;
  // Last user-geometry hit accepted (exact values for the final answer).
  bool user_hit = false;
  unsigned inst = RTC_INVALID_GEOMETRY_ID, geom = RTC_INVALID_GEOMETRY_ID, prim = 0;
  double t = 0;
  Vec3 normal{};
  // The hit accepted last (the current closest), exact: surfaces met at exactly the same
  // distance go to the lower key (outer instance, then object number), as Radiance keeps the
  // first of them it tests, whatever order Embree offers them in.
  bool best = false;
  double best_t = 0;
  std::uint64_t best_key = 0;
  Vec3 best_normal{};   // a triangle's (local) plane normal: the answer needs not compute it again
  bool closest = false; // a closest-hit query (not an occlusion test)
  bool raw = false;     // SceneGeometry::intersect_raw: the filter accepts every candidate
  // A packet query: the context Embree is given heads it, and lane k's ray is lanes[k]
  // (Embree calls back with the packet's size and lane order); null: the context is the ray.
  RayContext* lanes = nullptr;
  RayContext& lane(unsigned k) { return lanes ? lanes[k] : *this; }
  // Whether a candidate at exact distance cand_t loses to the current closest hit.
  bool loses(double cand_t, std::uint64_t key) const {
    return best && (cand_t > best_t || (cand_t == best_t && key > best_key));
  }
  void accept(double cand_t, std::uint64_t key, const Vec3& normal = {}) {
    best = true;
    best_t = cand_t;
    best_key = key;
    best_normal = normal;
  }
};

// Order of surfaces for ties: main scene first, then instances by Embree id; within one, by
// object number (a mesh: by triangle).
inline std::uint64_t tie_key(unsigned inst, std::uint32_t object) {
  return (static_cast<std::uint64_t>(inst + 1u) << 32) | object;
}

// Collects the visible leaf surfaces (polygons and quadrics) of `desc`; `all` keeps surfaces
// without a material (inside an instance whose own modifier shades them).
LeafSet collect_leaves(const scene::SceneDescription& desc, bool all, SurfaceCounts& counts);
// Whether the modifier chain of object `i` reaches something that shades.
bool has_material(const scene::SceneDescription& desc, std::int32_t i);

// Creates the Embree geometries of a prototype in `scene` (not committed).
void build_leaf_prototype(RTCDevice device, RTCScene scene, LeafSet&& leaves, const Vec3& centre,
                          Prototype& proto);
void build_mesh_prototype(RTCDevice device, RTCScene scene, const scene::TriangleMesh& mesh,
                          bool all, Prototype& proto, SurfaceCounts& counts);

// Exact parametric distance along (o, d), prototype-centred, to Embree triangle `prim` of the
// prototype; false if the ray is parallel to it (Radiance's test).
// `len` is |d|.
bool triangle_distance(const Prototype& p, unsigned prim, const Vec3& o, const Vec3& d, double len,
                       double& t, Vec3& normal);

// Embree callbacks (embree_callbacks.cpp).
void user_bounds(const RTCBoundsFunctionArguments* args);
void user_intersect(const RTCIntersectFunctionNArguments* args);
void user_occluded(const RTCOccludedFunctionNArguments* args);
void triangle_filter(const RTCFilterFunctionNArguments* args);

} // namespace radcl::geometry
