// Embree callbacks. The context is a RayContext: a single query's (N is 1), or the head of a
// packet's (N is the packet's size, lane k the packet's ray k: RayContext::lane). Distances are
// parametric along the caller's unit world direction, which Embree's instance transforms
// preserve, so local and world t agree.
#include <cmath>
#include <limits>

#include "impl.h"

namespace radcl::geometry {
namespace {

// Padding so float boxes enclose the double surfaces despite rounding of the box and of the
// float ray Embree traverses with.
void write_bounds(const std::array<Vec3, 2>& b, RTCBounds* out) {
  double size = 0;
  for (int k = 0; k < 3; ++k)
    size = std::max(size, b[1][k] - b[0][k]);
  float lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    const double pad = 1e-5 * size + 1e-6 * std::max(std::abs(b[0][k]), std::abs(b[1][k]));
    lo[k] = std::nextafter(static_cast<float>(b[0][k] - pad), -INFINITY);
    hi[k] = std::nextafter(static_cast<float>(b[1][k] + pad), INFINITY);
  }
  out->lower_x = lo[0], out->lower_y = lo[1], out->lower_z = lo[2];
  out->upper_x = hi[0], out->upper_y = hi[1], out->upper_z = hi[2];
}

struct LocalRay {
  Vec3 o, d;
  double len; // |d|
};

LocalRay local_ray(const RayContext& rc, unsigned inst_id) {
  // The main scene's transform is the translation by minus the centre (builder.cpp).
  if (inst_id == RTC_INVALID_GEOMETRY_ID) return {rc.org0, rc.dir, rc.len0};
  const PlacementRecord& pr = rc.impl->record_for_instance(inst_id);
  const Vec3 d = pr.from_world.vector(rc.dir);
  return {pr.from_world.point(rc.org), d, length(d)};
}

} // namespace

void user_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* proto = static_cast<const Prototype*>(args->geometryUserPtr);
  write_bounds(analytic_bounds(proto->analytic[args->primID]), args->bounds_o);
}

void user_intersect(const RTCIntersectFunctionNArguments* args) {
  auto* head = reinterpret_cast<RayContext*>(args->context);
  const auto* proto = static_cast<const Prototype*>(args->geometryUserPtr);
  const unsigned inst = args->context->instID[0];
  const AnalyticSurface& s = proto->analytic[args->primID];
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] == 0) continue;
    RayContext* rc = &head->lane(k);
    const LocalRay lr = local_ray(*rc, inst);
    float& tfar = RTCRayN_tfar(ray, args->N, k);
    double t;
    Vec3 n;
    // Embree's tfar is the closest hit rounded to float; the exact one decides, ties included.
    const double bound = std::min(rc->tmax, rc->best ? std::nextafter(rc->best_t, INFINITY)
                                                     : static_cast<double>(tfar));
    if (!intersect_analytic(s, lr.o, lr.d, rc->tmin, bound, t, n, rc->on * lr.len)) continue;
    const std::uint64_t key = tie_key(inst, static_cast<std::uint32_t>(s.object));
    if (rc->loses(t, key)) continue;
    rc->accept(t, key);
    tfar = static_cast<float>(t);
    RTCHitN_Ng_x(hit, args->N, k) = static_cast<float>(n[0]);
    RTCHitN_Ng_y(hit, args->N, k) = static_cast<float>(n[1]);
    RTCHitN_Ng_z(hit, args->N, k) = static_cast<float>(n[2]);
    RTCHitN_u(hit, args->N, k) = 0;
    RTCHitN_v(hit, args->N, k) = 0;
    RTCHitN_primID(hit, args->N, k) = args->primID;
    RTCHitN_geomID(hit, args->N, k) = args->geomID;
    RTCHitN_instID(hit, args->N, k, 0) = inst;
    rc->user_hit = true;
    rc->inst = inst;
    rc->geom = args->geomID;
    rc->prim = args->primID;
    rc->t = t;
    rc->normal = n;
  }
}

void user_occluded(const RTCOccludedFunctionNArguments* args) {
  auto* head = reinterpret_cast<RayContext*>(args->context);
  const auto* proto = static_cast<const Prototype*>(args->geometryUserPtr);
  const unsigned inst = args->context->instID[0];
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] == 0) continue;
    RayContext& rc = head->lane(k);
    const LocalRay lr = local_ray(rc, inst);
    float& tfar = RTCRayN_tfar(args->ray, args->N, k);
    double t;
    Vec3 n;
    if (intersect_analytic(proto->analytic[args->primID], lr.o, lr.d, rc.tmin,
                           std::min(rc.tmax, static_cast<double>(tfar)), t, n, rc.on * lr.len))
      tfar = -std::numeric_limits<float>::infinity();
  }
}

// Embree's float distance only nominates a triangle; the exact distance to the polygon's
// plane decides whether it lies in (tmin, tmax) — this is what stops rays leaving a surface
// from hitting it again.
void triangle_filter(const RTCFilterFunctionNArguments* args) {
  auto* head = reinterpret_cast<RayContext*>(args->context);
  if (head->raw) return;
  const auto* proto = static_cast<const Prototype*>(args->geometryUserPtr);
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] == 0) continue;
    RayContext* rc = &head->lane(k);
    const unsigned inst = RTCHitN_instID(args->hit, args->N, k, 0);
    const unsigned prim = RTCHitN_primID(args->hit, args->N, k);
    const LocalRay lr = local_ray(*rc, inst);
    double t;
    Vec3 n;
    // A ray whose origin lies in the triangle's plane (within rc->on) cannot meet it again.
    if (!triangle_distance(*proto, prim, lr.o, lr.d, lr.len, t, n) ||
        !(t > rc->tmin && t < rc->tmax) || std::abs(t * dot(n, lr.d)) <= rc->on * lr.len) {
      args->valid[k] = 0;
      continue;
    }
    const std::uint32_t object =
        proto->mesh != nullptr
            ? proto->mesh_triangle[prim]
            : static_cast<std::uint32_t>(proto->polygons[proto->triangle_polygon[prim]].object);
    const std::uint64_t key = tie_key(inst, object);
    if (rc->closest && rc->loses(t, key)) {
      args->valid[k] = 0;
      continue;
    }
    // Occlusion queries stop at any hit; only closest-hit queries keep the best.
    if (rc->closest) rc->accept(t, key, n);
  }
}

} // namespace radcl::geometry
