// Ray queries: the caller's double ray is re-centred and rounded for Embree's traversal, with
// Embree's interval widened by a float slack; the exact interval is enforced by the callbacks
// and the answer is rebuilt in double from the winning primitive.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
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
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

  const unsigned inst = rh.hit.instID[0];
  Hit h;
  h.placement = inst == RTC_INVALID_GEOMETRY_ID ? 0 : g.top_geom_placement[inst];
  const PlacementRecord& rec = g.records[h.placement];
  const Prototype& p = g.prototypes[rec.prototype];
  h.instance = g.placements[h.placement].instance_object;
  Vec3 n;
  if (rh.hit.geomID == p.user_geom) {
    if (!rc.user_hit || rc.geom != rh.hit.geomID || rc.inst != inst)
      throw std::logic_error("geometry: lost the exact user-geometry hit");
    h.t = rc.t;
    n = rc.normal;
    h.object = p.analytic[rh.hit.primID].object;
  } else {
    // The filter accepted this triangle last, with its exact distance and plane normal (the
    // same local ray, so the same values); without the filter (raw queries) they are computed.
    if (rc.best && !rc.raw) {
      h.t = rc.best_t;
      n = rc.best_normal;
    } else {
      const Vec3 o = rec.from_world.point(rc.org), d = rec.from_world.vector(rc.dir);
      if (!triangle_distance(p, rh.hit.primID, o, d, length(d), h.t, n)) return std::nullopt;
    }
    h.u = rh.hit.u;
    h.v = rh.hit.v;
    if (p.mesh != nullptr) {
      h.object = rec.mesh_object;
      h.prim = p.mesh_triangle[rh.hit.primID];
    } else {
      const PolygonRecord& pol = p.polygons[p.triangle_polygon[rh.hit.primID]];
      h.object = pol.object;
      h.prim = rh.hit.primID - pol.first_triangle;
    }
  }
  h.point = madd(rc.org, rc.dir, h.t);
  h.t += rc.shift;
  h.normal = normalized(rec.to_world.vector(n));
  h.front = dot(h.normal, rc.dir) < 0;
  return h;
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
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      hits[i] =
          intersect(rays[i].org, rays[i].dir, rays[i].tmin, rays[i].tmax, rays[i].free_origin);
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

void SceneGeometry::intersect_raw(std::span<const Ray> rays, std::span<float> t) const {
  if (t.size() != rays.size()) throw std::invalid_argument("intersect_raw: size mismatch");
  const Impl& g = *impl_;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 64), [&](const auto& r) {
    RayContext rc;
    rc.impl = &g;
    rc.raw = true;
    rc.tmax = 1e300;
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      rtcInitIntersectContext(&rc.ctx);
      const Ray& q = rays[i];
      RTCRayHit rh;
      rh.ray.org_x = static_cast<float>(q.org[0] - g.centre[0]);
      rh.ray.org_y = static_cast<float>(q.org[1] - g.centre[1]);
      rh.ray.org_z = static_cast<float>(q.org[2] - g.centre[2]);
      rh.ray.dir_x = static_cast<float>(q.dir[0]);
      rh.ray.dir_y = static_cast<float>(q.dir[1]);
      rh.ray.dir_z = static_cast<float>(q.dir[2]);
      rh.ray.tnear = static_cast<float>(std::max(0.0, q.tmin)); // a negative tmin: none
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.time = 0;
      rh.ray.mask = ~0u;
      rh.ray.id = 0;
      rh.ray.flags = 0;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(g.top, &rc.ctx, &rh);
      t[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                                      : rh.ray.tfar;
    }
  });
}

} // namespace radcl::geometry
