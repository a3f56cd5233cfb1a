// Ray queries: the caller's double ray is re-centred and rounded for Embree's traversal, with
// Embree's interval widened by a float slack; the exact interval is enforced by the callbacks
// and the answer is rebuilt in double from the winning primitive.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "impl.h"
#include "radcl/util/error.h"

namespace radcl::geometry {
namespace {

bool setup(const SceneGeometry::Impl& g, const Vec3& org, const Vec3& dir, double tmin, double tmax,
           bool free_origin, RayContext& rc, RTCRay& ray) {
  rtcInitIntersectContext(&rc.ctx);
  rc.impl = &g;
  const double l = length(dir);
  if (!(l > 0) || !std::isfinite(l)) return false;
  rc.org = org;
  rc.dir = scale(dir, 1 / l);
  Vec3 o = sub(org, g.centre);
  double reach = std::max({std::abs(o[0]), std::abs(o[1]), std::abs(o[2])});
  if (!std::isfinite(reach)) return false;
  // An origin far outside the scene (a view point 1e19 away) starts the float traversal where
  // the ray meets the scene's bounding sphere, found in double as Radiance traces: Embree rejects
  // coordinates past 1.8e18 (its assertion ends the program) and rounds a scene to nothing
  // long before that. Distances stay measured from the caller's origin.
  if (reach > g.far) {
    const double radius = g.radius;
    const double along = -dot(o, rc.dir);
    const Vec3 nearest = madd(o, rc.dir, along);
    if (!(length(nearest) <= radius) || along < 0) return false; // passes the scene by
    // Short of the sphere by the rounding of `along`: a shift that overshot into the scene
    // would start the ray inside it; one too short to reach it is a miss below.
    const double slop = 4 * reach * std::numeric_limits<double>::epsilon();
    rc.shift = std::max(0.0, along - radius - slop);
    o = madd(o, rc.dir, rc.shift);
    reach = std::max({std::abs(o[0]), std::abs(o[1]), std::abs(o[2])});
    // The entry point is as exact as double places it (Radiance's own limit); one that float
    // still cannot hold (an origin 1e300 away) is a miss.
    if (!(reach <= radius + 2 * slop + 1.0) || !(reach < 1e17)) return false;
    rc.org = add(g.centre, o);
    tmin = tmin < 0 ? tmin : std::max(0.0, tmin - rc.shift);
    tmax -= rc.shift;
  }
  if (tmin < 0) {
    // The origin was moved off the surface it leaves (RC_TMIN_OFF): nothing is skipped, and no
    // surface counts as holding the origin.
    rc.tmin = 0;
    rc.on = 0;
  } else {
    rc.tmin = std::max(tmin, std::max(g.eps, g.eps_rel * reach));
    // Points handed over in float relative to the centre are off their surface by up to three
    // half units in the last place of their largest coordinate. A meter holds no surface: a
    // fin 0.5 mm from one 4 km out (1.6 mm of rounding there) is in its view.
    rc.on = free_origin ? 0.0 : 4e-7 * reach + 1e-12;
  }
  rc.tmax = tmax;
  if (!(rc.tmax > rc.tmin)) return false;
  // As the main scene's from_world (a translation) maps rc.org and rc.dir, bit for bit.
  rc.org0 = sub(rc.org, g.centre);
  rc.len0 = length(rc.dir);
  ray.org_x = static_cast<float>(o[0]);
  ray.org_y = static_cast<float>(o[1]);
  ray.org_z = static_cast<float>(o[2]);
  ray.dir_x = static_cast<float>(rc.dir[0]);
  ray.dir_y = static_cast<float>(rc.dir[1]);
  ray.dir_z = static_cast<float>(rc.dir[2]);
  const double slack = g.margin + 1e-6 * rc.tmin;
  ray.tnear = static_cast<float>(std::max(0.0, rc.tmin - slack));
  const double far = rc.tmax + g.margin + 1e-6 * rc.tmax;
  ray.tfar = far < 1e37 ? static_cast<float>(far) : std::numeric_limits<float>::infinity();
  ray.time = 0;
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
  return true;
}

} // namespace

namespace {

// Radiance's smoothed mesh normal (o_mesh): where all three vertices of mesh triangle `tri`
// carry a normal, the normal interpolated at the hit with the point's barycentric weights (in
// double from `local`, the point in the prototype's centred frame), carried to world as the
// flat normal is and made unit; its difference from `flat` (world, unit) is the perturbation.
// Zero without normals, on a degenerate triangle, or where the interpolation vanishes.
Vec3 mesh_pert(const Prototype& p, const PlacementRecord& rec, std::uint32_t tri, const Vec3& local,
               const Vec3& flat) {
  const scene::TriangleMesh& m = *p.mesh;
  const auto& t = m.triangles[tri];
  for (std::uint32_t vi : t)
    if (vi >= m.vertex_flags.size() || vi >= m.normals.size() ||
        !(m.vertex_flags[vi] & scene::TriangleMesh::kHasNormal))
      return {0, 0, 0};
  // Weights of v1 and v2 from the sub-triangle areas, signed along the face normal.
  const Vec3& v0 = p.mesh_vertices[t[0]];
  const Vec3 e1 = sub(p.mesh_vertices[t[1]], v0), e2 = sub(p.mesh_vertices[t[2]], v0);
  const Vec3 fn = cross(e1, e2), q = sub(local, v0);
  const double area2 = dot(fn, fn);
  if (!(area2 > 0)) return {0, 0, 0};
  const double w1 = dot(cross(q, e2), fn) / area2, w2 = dot(cross(e1, q), fn) / area2;
  const double w[3] = {1 - w1 - w2, w1, w2};
  Vec3 n{0, 0, 0};
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c)
      n[c] += w[k] * m.normals[t[k]][c];
  n = rec.to_world.vector(n);
  const double len = length(n);
  if (!(len > 0)) return {0, 0, 0};
  return sub(scale(n, 1 / len), flat);
}

// The answer from Embree's winning primitive and what the callbacks kept of it, in double,
// written field by field into `out` (a hit built aside and copied in stalled on forwarding its
// stores, and clearing a fresh one first cost as much: together a fifth of the query's own
// time); every field is written.
void answer(const SceneGeometry::Impl& g, const RayContext& rc, unsigned geom, unsigned prim,
            unsigned inst, float u, float v, std::optional<Hit>& out) {
  if (geom == RTC_INVALID_GEOMETRY_ID) {
    out.reset();
    return;
  }
  if (!out) out.emplace();
  Hit& h = *out;
  h.placement = inst == RTC_INVALID_GEOMETRY_ID ? 0 : g.top_geom_placement[inst];
  const PlacementRecord& rec = g.records[h.placement];
  const Prototype& p = g.prototypes[rec.prototype];
  h.instance = g.placements[h.placement].instance_object;
  Vec3 n;
  if (geom == p.user_geom) {
    if (!rc.user_hit || rc.geom != geom || rc.inst != inst)
      throw std::logic_error("geometry: lost the exact user-geometry hit");
    h.t = rc.t;
    n = rc.normal;
    h.object = p.analytic[prim].object;
    h.prim = 0;
    h.u = h.v = 0;
  } else {
    // The filter accepted this triangle last, with its exact distance and plane normal (the
    // same local ray, so the same values); without the filter (raw queries) they are computed.
    if (rc.best && !rc.raw) {
      h.t = rc.best_t;
      n = rc.best_normal;
    } else {
      const Vec3 o = rec.from_world.point(rc.org), d = rec.from_world.vector(rc.dir);
      if (!triangle_distance(p, prim, o, d, length(d), h.t, n)) {
        out.reset();
        return;
      }
    }
    h.u = u;
    h.v = v;
    if (p.mesh != nullptr) {
      h.object = rec.mesh_object;
      h.prim = p.mesh_triangle[prim];
    } else {
      const PolygonRecord& pol = p.polygons[p.triangle_polygon[prim]];
      h.object = pol.object;
      h.prim = prim - pol.first_triangle;
    }
  }
  h.point = madd(rc.org, rc.dir, h.t);
  h.t += rc.shift;
  h.normal = normalized(rec.to_world.vector(n));
  h.front = dot(h.normal, rc.dir) < 0;
  // A mesh prototype holds triangles only.
  h.pert = p.mesh != nullptr ? mesh_pert(p, rec, h.prim, rec.from_world.point(h.point), h.normal)
                             : Vec3{0, 0, 0};
}

template <int K> struct Packet;
template <> struct Packet<4> {
  using RayHit = RTCRayHit4;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    rtcIntersect4(v, s, c, r);
  }
};
template <> struct Packet<8> {
  using RayHit = RTCRayHit8;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    rtcIntersect8(v, s, c, r);
  }
};
template <> struct Packet<16> {
  using RayHit = RTCRayHit16;
  static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) {
    rtcIntersect16(v, s, c, r);
  }
};

// Lane k of a packet: a single ray as setup() made it.
template <class RH> void put_lane(RH& rh, int k, const RTCRay& r) {
  rh.ray.org_x[k] = r.org_x;
  rh.ray.org_y[k] = r.org_y;
  rh.ray.org_z[k] = r.org_z;
  rh.ray.dir_x[k] = r.dir_x;
  rh.ray.dir_y[k] = r.dir_y;
  rh.ray.dir_z[k] = r.dir_z;
  rh.ray.tnear[k] = r.tnear;
  rh.ray.tfar[k] = r.tfar;
  rh.ray.time[k] = r.time;
  rh.ray.mask[k] = r.mask;
  rh.ray.id[k] = static_cast<unsigned>(k);
  rh.ray.flags[k] = r.flags;
  rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
}

// Rays [0, n) (n <= K) in one packet; every lane's query is set up and answered as a single
// ray's, so the answers are intersect()'s.
template <int K>
void intersect_packet(const SceneGeometry::Impl& g, const Ray* rays, std::size_t n,
                      std::optional<Hit>* hits) {
  alignas(64) typename Packet<K>::RayHit rh;
  alignas(64) int valid[K];
  std::array<RayContext, K> lanes;
  RayContext head;
  rtcInitIntersectContext(&head.ctx);
  head.impl = &g;
  head.lanes = lanes.data();
  bool any = false;
  for (int k = 0; k < K; ++k) {
    valid[k] = 0;
    if (static_cast<std::size_t>(k) >= n) continue;
    const Ray& q = rays[k];
    RTCRay r;
    if (!setup(g, q.org, q.dir, q.tmin, q.tmax, q.free_origin, lanes[k], r)) continue;
    lanes[k].closest = true;
    put_lane(rh, k, r);
    valid[k] = -1;
    any = true;
  }
  if (any) Packet<K>::intersect(valid, g.top, &head.ctx, &rh);
  for (std::size_t k = 0; k < n; ++k) {
    if (valid[k])
      answer(g, lanes[k], rh.hit.geomID[k], rh.hit.primID[k], rh.hit.instID[0][k], rh.hit.u[k],
             rh.hit.v[k], hits[k]);
    else
      hits[k].reset();
  }
}

} // namespace

std::optional<Hit> SceneGeometry::intersect(const Vec3d& org, const Vec3d& dir, double tmin,
                                            double tmax, bool free_origin) const {
  const Impl& g = *impl_;
  RayContext rc;
  RTCRayHit rh;
  if (!setup(g, org, dir, tmin, tmax, free_origin, rc, rh.ray)) return std::nullopt;
  rc.closest = true;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(g.top, &rc.ctx, &rh);
  std::optional<Hit> h;
  answer(g, rc, rh.hit.geomID, rh.hit.primID, rh.hit.instID[0], rh.hit.u, rh.hit.v, h);
  return h;
}

void SceneGeometry::intersect_block(const Ray* rays, std::size_t n,
                                    std::optional<Hit>* hits) const {
  const Impl& g = *impl_;
  for (std::size_t a = 0; a < n; a += static_cast<std::size_t>(g.packet)) {
    const std::size_t m = std::min(n - a, static_cast<std::size_t>(g.packet));
    switch (m == 1 ? 1 : g.packet) {
    case 16:
      intersect_packet<16>(g, rays + a, m, hits + a);
      break;
    case 8:
      intersect_packet<8>(g, rays + a, m, hits + a);
      break;
    case 4:
      intersect_packet<4>(g, rays + a, m, hits + a);
      break;
    default:
      const Ray& q = rays[a];
      hits[a] = intersect(q.org, q.dir, q.tmin, q.tmax, q.free_origin);
    }
  }
}

int SceneGeometry::packet_width() const {
  return impl_->packet;
}

bool SceneGeometry::occluded(const Vec3d& org, const Vec3d& dir, double tmin, double tmax,
                             bool free_origin) const {
  const Impl& g = *impl_;
  RayContext rc;
  RTCRay ray;
  if (!setup(g, org, dir, tmin, tmax, free_origin, rc, ray)) return false;
  rtcOccluded1(g.top, &rc.ctx, &ray);
  return ray.tfar < 0;
}

void SceneGeometry::intersect(std::span<const Ray> rays, std::span<std::optional<Hit>> hits) const {
  if (hits.size() != rays.size()) throw std::invalid_argument("intersect: size mismatch");
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 64), [&](const auto& r) {
    intersect_block(rays.data() + r.begin(), r.size(), hits.data() + r.begin());
  });
}

void SceneGeometry::occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
  if (blocked.size() != rays.size()) throw std::invalid_argument("occluded: size mismatch");
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 64), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      blocked[i] =
          occluded(rays[i].org, rays[i].dir, rays[i].tmin, rays[i].tmax, rays[i].free_origin) ? 1
                                                                                              : 0;
  });
}

namespace {

// A raw ray as Embree alone would take it: float, re-centred, nothing skipped but tmin.
RTCRay raw_ray(const SceneGeometry::Impl& g, const Ray& q) {
  RTCRay r;
  r.org_x = static_cast<float>(q.org[0] - g.centre[0]);
  r.org_y = static_cast<float>(q.org[1] - g.centre[1]);
  r.org_z = static_cast<float>(q.org[2] - g.centre[2]);
  r.dir_x = static_cast<float>(q.dir[0]);
  r.dir_y = static_cast<float>(q.dir[1]);
  r.dir_z = static_cast<float>(q.dir[2]);
  r.tnear = static_cast<float>(std::max(0.0, q.tmin)); // a negative tmin: none
  r.tfar = std::numeric_limits<float>::infinity();
  r.time = 0;
  r.mask = ~0u;
  r.id = 0;
  r.flags = 0;
  return r;
}

template <int K>
void raw_packet(const SceneGeometry::Impl& g, RayContext& rc, const Ray* rays, std::size_t n,
                float* t) {
  alignas(64) typename Packet<K>::RayHit rh;
  alignas(64) int valid[K];
  for (int k = 0; k < K; ++k) {
    valid[k] = static_cast<std::size_t>(k) < n ? -1 : 0;
    if (valid[k]) put_lane(rh, k, raw_ray(g, rays[k]));
  }
  rtcInitIntersectContext(&rc.ctx);
  Packet<K>::intersect(valid, g.top, &rc.ctx, &rh);
  for (std::size_t k = 0; k < n; ++k)
    t[k] = rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                                       : rh.ray.tfar[k];
}

} // namespace

void SceneGeometry::intersect_raw(std::span<const Ray> rays, std::span<float> t, int width) const {
  if (t.size() != rays.size()) throw std::invalid_argument("intersect_raw: size mismatch");
  const Impl& g = *impl_;
  const int w = width > 0 ? width : g.packet;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 64), [&](const auto& r) {
    RayContext rc;
    rc.impl = &g;
    rc.raw = true;
    rc.tmax = 1e300;
    for (std::size_t i = r.begin(); i < r.end(); i += static_cast<std::size_t>(w)) {
      const std::size_t m = std::min(r.end() - i, static_cast<std::size_t>(w));
      if (w == 16) {
        raw_packet<16>(g, rc, rays.data() + i, m, t.data() + i);
      } else if (w == 8) {
        raw_packet<8>(g, rc, rays.data() + i, m, t.data() + i);
      } else if (w == 4) {
        raw_packet<4>(g, rc, rays.data() + i, m, t.data() + i);
      } else {
        rtcInitIntersectContext(&rc.ctx);
        RTCRayHit rh;
        rh.ray = raw_ray(g, rays[i]);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(g.top, &rc.ctx, &rh);
        t[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                                        : rh.ray.tfar;
      }
    }
  });
}

} // namespace radcl::geometry
