// Embree geometries of one prototype: a triangle geometry (polygons or a mesh) with a filter
// that checks hits against the exact double-precision plane, and a user geometry holding the
// quadrics.
#include <algorithm>
#include <cmath>
#include <limits>

#include "impl.h"

namespace radcl::geometry {
namespace {

constexpr double kParallel = 1e-6; // Radiance's FTINY for |cos| of rays along a plane

unsigned attach_triangles(RTCDevice device, RTCScene scene, const std::vector<Vec3>& verts,
                          const Vec3& centre, const std::vector<Tri>& tris, Prototype& proto) {
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), verts.size()));
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris.size()));
  if (vb == nullptr || ib == nullptr) {
    rtcReleaseGeometry(g);
    return RTC_INVALID_GEOMETRY_ID;
  }
  for (std::size_t i = 0; i < verts.size(); ++i)
    for (int k = 0; k < 3; ++k)
      vb[3 * i + k] = static_cast<float>(verts[i][k] - centre[k]);
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k)
      ib[3 * i + k] = tris[i][k];
  rtcSetGeometryUserData(g, &proto);
  rtcSetGeometryIntersectFilterFunction(g, triangle_filter);
  rtcSetGeometryOccludedFilterFunction(g, triangle_filter);
  rtcCommitGeometry(g);
  const unsigned id = rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  return id;
}

} // namespace

void build_leaf_prototype(RTCDevice device, RTCScene scene, LeafSet&& leaves, const Vec3& centre,
                          Prototype& proto) {
  proto.scene = scene;
  proto.centre = centre;
  proto.bounds = leaves.bounds;
  proto.empty = leaves.empty;
  proto.polygons = std::move(leaves.polygons);
  for (auto& p : proto.polygons)
    p.offset -= dot(p.normal, centre);
  proto.triangle_polygon = std::move(leaves.triangle_polygon);
  proto.analytic = std::move(leaves.analytic);
  for (auto& s : proto.analytic)
    shift(s, centre);
  if (!leaves.triangles.empty())
    proto.tri_geom =
        attach_triangles(device, scene, leaves.vertices, centre, leaves.triangles, proto);
  if (!proto.analytic.empty()) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(proto.analytic.size()));
    rtcSetGeometryUserData(g, &proto);
    rtcSetGeometryBoundsFunction(g, user_bounds, nullptr);
    rtcSetGeometryIntersectFunction(g, user_intersect);
    rtcSetGeometryOccludedFunction(g, user_occluded);
    rtcCommitGeometry(g);
    proto.user_geom = rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
  }
}

void build_mesh_prototype(RTCDevice device, RTCScene scene, const scene::TriangleMesh& mesh,
                          bool all, Prototype& proto, SurfaceCounts& counts) {
  proto.scene = scene;
  proto.mesh = &mesh;
  std::vector<Tri> tris;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    // Without a modifier of its own, a mesh shows only faces that have a material.
    const bool has = i < mesh.triangle_material.size() && mesh.triangle_material[i] >= 0;
    if (!all && !has) {
      ++counts.skipped_void;
      continue;
    }
    const auto& t = mesh.triangles[i];
    if (std::max({t[0], t[1], t[2]}) >= mesh.positions.size()) continue;
    tris.push_back(t);
    proto.mesh_triangle.push_back(static_cast<std::uint32_t>(i));
  }
  counts.mesh_triangles += tris.size();
  if (tris.empty()) return;
  // Bounds of the vertices used; the centre makes the float copy precise.
  proto.bounds = {mesh.positions[tris[0][0]], mesh.positions[tris[0][0]]};
  for (const auto& t : tris)
    for (std::uint32_t vi : t)
      for (int k = 0; k < 3; ++k) {
        proto.bounds[0][k] = std::min(proto.bounds[0][k], mesh.positions[vi][k]);
        proto.bounds[1][k] = std::max(proto.bounds[1][k], mesh.positions[vi][k]);
      }
  proto.empty = false;
  proto.centre = scale(add(proto.bounds[0], proto.bounds[1]), 0.5);
  proto.mesh_vertices.resize(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    proto.mesh_vertices[i] = sub(mesh.positions[i], proto.centre);
  proto.tri_geom = attach_triangles(device, scene, mesh.positions, proto.centre, tris, proto);
}

bool triangle_distance(const Prototype& p, unsigned prim, const Vec3& o, const Vec3& d, double len,
                       double& t, Vec3& normal) {
  if (p.mesh != nullptr) {
    // Mesh faces use the triangle's own plane, as Radiance's mesh code does.
    const auto& tri = p.mesh->triangles[p.mesh_triangle[prim]];
    const Vec3& v0 = p.mesh_vertices[tri[0]];
    const Vec3 n = cross(sub(p.mesh_vertices[tri[1]], v0), sub(p.mesh_vertices[tri[2]], v0));
    const double den = dot(n, d);
    if (den == 0) return false;
    t = dot(sub(v0, o), n) / den;
    normal = normalized(n);
    return true;
  }
  const PolygonRecord& pol = p.polygons[p.triangle_polygon[prim]];
  const double den = dot(pol.normal, d);
  if (std::abs(den) <= kParallel * len) return false;
  t = (pol.offset - dot(pol.normal, o)) / den;
  normal = pol.normal;
  return true;
}

} // namespace radcl::geometry
