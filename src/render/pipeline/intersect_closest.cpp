// Stage: the nearest hit of every ray of a chunk (Embree on the host), as the kernels' records.
#include <array>
#include <chrono>
#include <cmath>

#include "pipeline_util.h"
#include "radcl/render/lights/virtual_sources.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

geometry::Ray Renderer::Impl::query_ray(const rc_ray& r, bool primary) const {
  geometry::Ray ray;
  ray.org = {r.org.x + centre[0], r.org.y + centre[1], r.org.z + centre[2]};
  ray.dir = {r.dir.x, r.dir.y, r.dir.z};
  ray.tmin = r.org.w;
  // The kernels send a positive tmin only from an -I meter's point (rc_leave_org).
  ray.free_origin = r.org.w > 0 && !primary;
  ray.tmax = std::isfinite(r.dir.w) ? r.dir.w : 1e300;
  return ray;
}

// Written field by field into the queue's row: a record built aside and copied in stalls on
// forwarding its narrow stores to the copy's wide loads.
void Renderer::Impl::to_device(const geometry::Ray& ray, const std::optional<geometry::Hit>& h,
                               rc_hit& out) const {
  std::uint32_t surface;
  if (h) {
    out.pos = f4(h->point[0] - centre[0], h->point[1] - centre[1], h->point[2] - centre[2], h->t);
    out.nrm = f4(h->normal[0], h->normal[1], h->normal[2], 0);
    out.uv = f4(h->u, h->v, 0, 0);
    out.pert = f4(h->pert[0], h->pert[1], h->pert[2], 0); // a smoothed mesh's tilt
    surface = cs.surface_of(*h);
    out.prim = h->prim;
    out.front = h->front ? 1 : 0;
  } else {
    out.pos = f4(0, 0, 0, -1);
    out.nrm = f4(0, 0, 0, 0);
    out.uv = f4(0, 0, 0, 0);
    out.pert = f4(0, 0, 0, 0);
    out.prim = 0;
    out.front = 1;
    surface = distant_surface(cs, geom, ray.dir);
  }
  out.surface = surface;
  out.source = surface < cs.surfaces.size() ? cs.surfaces[surface].source : RC_NONE;
}

// RADCL_PROFILE=raw: the chunk's rays as trace() hands them to the query, through Embree's
// float traversal alone, timed apart from every phase.
void Renderer::Impl::trace_raw(std::span<const rc_ray> queue, bool primaries) {
  std::vector<geometry::Ray> rays(queue.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queue.size(), 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      rays[i] = query_ray(queue[i], primaries);
  });
  std::vector<float> t(rays.size());
  const auto t0 = std::chrono::steady_clock::now();
  geom.intersect_raw(rays, t);
  prof.add_raw(rays.size(),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

void Renderer::Impl::trace(std::span<const rc_ray> queue, HitQueue& hits,
                           std::span<PrimaryResult> res, bool primaries) {
  if (prof.raw()) trace_raw(queue, primaries);
  Timed timed(prof, Phase::Trace);
  std::size_t n = queue.size();
  // One pass per ray: the query, then its device record. Embree's double answer is kept
  // only where the loops below read it (the primaries, mirror reflections, straight
  // transmissions); the rest would be memory written and never read.
  std::vector<std::optional<geometry::Hit>>& gh = trace_answers;
  gh.resize(n);
  hits.resize(n);
  constexpr std::uint32_t kKept = RC_RAY_MIRRORED | RC_RAY_THROUGH;
  // Rays of those kinds are rare: the loops below visit only the ranges that hold one, not
  // every 112-byte row of the queue on one core.
  constexpr std::size_t kRange = 256;
  std::vector<std::uint8_t>& kept = trace_kept;
  kept.assign((n + kRange - 1) / kRange, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kept.size()), [&](const auto& ranges) {
    // Blocks of consecutive rays (a hemisphere's samples leave one point) go to Embree in
    // packets.
    constexpr std::size_t kBlock = 16;
    std::array<geometry::Ray, kBlock> ray;
    std::array<std::optional<geometry::Hit>, kBlock> h;
    const std::size_t end = std::min(n, ranges.end() * kRange);
    for (std::size_t a = ranges.begin() * kRange; a < end; a += kBlock) {
      const std::size_t m = std::min(kBlock, end - a);
      for (std::size_t k = 0; k < m; ++k)
        ray[k] = query_ray(queue[a + k], primaries);
      geom.intersect_block(ray.data(), m, h.data());
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = a + k;
        to_device(ray[k], h[k], hits[i]);
        if (queue[i].flags & kKept) kept[i / kRange] = 1; // this task's own ranges
        if (primaries || (queue[i].flags & kKept)) gh[i] = std::move(h[k]);
      }
    }
  });
  (primaries ? stats.primary : stats.secondary) += n;
  // The first hit's mirror reflection: how far it went, for rtrace's R and l. Measured from
  // the surface point it left (its ray starts just beside it: rc_leave).
  auto dist = [](const Vec3d& a, const Vec3d& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
  };
  // In queue order: a primary's straight continuation adds up along it.
  for (std::size_t b = 0; b < kept.size(); ++b) {
    if (!kept[b]) continue;
    for (std::size_t i = b * kRange; i < std::min(n, (b + 1) * kRange); ++i) {
      const std::uint32_t f = queue[i].flags;
      if ((f & RC_RAY_MIRRORED) && (f & RC_RAY_KIND_MASK) == RC_RAY_REFLECTED &&
          queue[i].depth == batch.root_depth[slot(queue[i].primary)] + 1) {
        PrimaryResult& pr = batch.results[slot(queue[i].primary)];
        pr.mirror_t = (f & RC_RAY_TILTED) ? 0.0 : gh[i] ? dist(gh[i]->point, pr.point) : 1e10;
      }
      // The straight continuation through transmitting surfaces: its lengths add up (X), each
      // from the surface point the last one met.
      if ((f & RC_RAY_THROUGH) && (f & RC_RAY_KIND_MASK) == RC_RAY_TRANSMITTED) {
        PrimaryResult& pr = batch.results[slot(queue[i].primary)];
        const Vec3d& from = pr.through_t < 0 ? pr.point : pr.through_at;
        pr.through_t = std::max(pr.through_t, 0.0) + (gh[i] ? dist(gh[i]->point, from) : 1e10);
        if (gh[i]) pr.through_at = gh[i]->point;
      }
    }
  }
  if (!primaries) return;
  for (std::size_t i = 0; i < n; ++i) {
    PrimaryResult& r = res[slot(queue[i].primary)];
    r.surface = hits[i].surface; // also a distant source met by a miss
    if (!gh[i]) continue;
    r.hit = true;
    r.t = gh[i]->t;
    r.point = gh[i]->point;
    r.normal = gh[i]->normal;
    r.pert = gh[i]->pert; // a smoothed mesh's; the textures' come from the device (wave_loop)
    r.surface = hits[i].surface;
  }
}

} // namespace radcl::render
