// The driver loop: batches of primaries, each generation of their rays through the stages in
// chunks, until no ray is left.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "pipeline_util.h"
#include "radcl/render/pipeline/irradiance_meter.h"
#include "renderer_impl.h"

#include <tbb/task_group.h>

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

namespace {

// rtrace's -on: the textures' part of the normal perturbation at each first hit of `part` (the
// host gave the smoothed meshes' in trace), from the device's patterns (rc_hit_pert), into
// the primaries' results. `k` is made on first use.
void texture_perts(Renderer::Impl& im, std::optional<device::Kernel>& k,
                   std::span<const rc_ray> part, const rc_hit* hits, std::span<PrimaryResult> res) {
  const std::size_t n = part.size();
  if (n == 0) return;
  if (!k) k.emplace(im.program.kernel("rc_hit_pert"));
  device::Buffer rays(im.ctx, n * sizeof(rc_ray)), bhits(im.ctx, n * sizeof(rc_hit)),
      out(im.ctx, n * sizeof(rc_float4));
  rays.write(part.data(), n * sizeof(rc_ray));
  bhits.write(hits, n * sizeof(rc_hit));
  k->arg(0, rays).arg(1, bhits).arg(2, static_cast<std::uint32_t>(n));
  im.set_scene_args(*k, 3);
  k->arg(Renderer::Impl::kSceneArgs + 3, out);
  im.ctx.run(*k, n);
  std::vector<rc_float4> p(n);
  out.read(p.data(), n * sizeof(rc_float4));
  for (std::size_t i = 0; i < n; ++i) {
    PrimaryResult& r = res[im.slot(part[i].primary)];
    if (r.hit) r.pert = {p[i].x, p[i].y, p[i].z};
  }
}

} // namespace

std::size_t Renderer::Impl::chunk_rays() const {
  if (settings.tuning.chunk_rays) return settings.tuning.chunk_rays;
  return ctx.zero_copy() ? std::size_t{1} << 16 : std::size_t{1} << 18;
}

std::size_t Renderer::Impl::generation_rays() const {
  if (settings.tuning.generation_rays) return settings.tuning.generation_rays;
  if (!ctx.zero_copy()) return std::size_t{1} << 22;
  // On PoCL 2^18 with few cores: each generation's queues are memory paged in once per
  // process, at a cost the run does not amortise (1,980 sensors at -aa 0 -ad 1024 on 2 cores:
  // 3.9-4.3 s against 4.0-5.0 s with 2^19, 100 huge-page faults instead of 150). With many,
  // a batch of 2^18 rays' primaries (about 50 at -ab 2 -ad 1024) leaves most cores idle in its
  // first generations: 10,000 such sensors on 16 cores took 4.7-5.0 s, 3.8-4.1 s with 2^22.
  // The cache's passes make small generations; they keep the size they were measured with.
  if (uses_cache(settings) || ctx.info().compute_units < 8) return std::size_t{1} << 18;
  return std::size_t{1} << 22;
}

void Renderer::Impl::run(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results) {
  const std::size_t wave = std::max<std::size_t>(1, settings.wave_size);
  const std::size_t cap = generation_rays();
  for (std::size_t first = 0; first < rays.size();) {
    std::size_t n = std::min(wave, rays.size() - first);
    // rcontrib: a batch's bins in double stay within 256 MB (10^4 sensors of 2,305 bins
    // would take 550 MB at once).
    if (settings.contrib)
      n = std::min(n, std::max<std::size_t>(1, (std::size_t{1} << 25) /
                                                   (3 * settings.contrib->total_bins() + 1)));
    if (!uses_cache(settings)) {
      // Before any batch is measured, a guess: -ad rays at the first bounce, and about 16
      // times as many at the second (-ab 2 -ad 1024 gives 9,000).
      const double ad = std::max(1, settings.ad);
      const double per = rays_per_primary > 0 ? rays_per_primary
                         : settings.ab > 1    ? 16 * ad
                         : settings.ab > 0    ? ad
                                              : 1.0;
      n = std::min(n, std::max<std::size_t>(1, static_cast<std::size_t>(cap / per)));
    }
    peak_generation = 0;
    render_batch(rays.subspan(first, n), results.subspan(first, n), first);
    rays_per_primary = std::max(rays_per_primary, static_cast<double>(peak_generation) / n);
    first += n;
  }
}

void Renderer::Impl::render_batch(std::span<const PrimaryRay> prim, std::span<PrimaryResult> res,
                                  std::size_t first_index) {
  Timed timed(prof, Phase::Batch);
  assign_slots(prim, first_index);
  // The generation queues come from a pool that outlives the batch: growing fresh ones to
  // millions of rays in every batch paged in (and cleared) new memory each time.
  Spare<RayQueue> queue_hold(spare_rays, RayQueue(PinnedAlloc<rc_ray, true>(&ctx))),
      next_hold(spare_rays, RayQueue(PinnedAlloc<rc_ray, true>(&ctx)));
  Spare<HitQueue> hits_hold(spare_hits, HitQueue(PinnedAlloc<rc_hit>(&ctx)));
  RayQueue& queue = queue_hold.v;
  HitQueue& hits = hits_hold.v;
  // Room for a whole generation up front (address space only until used): growing by doubling
  // paged in and copied 390 MB in 2,000 sensors' run on 2 cores, a tenth of its CPU time.
  for (RayQueue* v : {&queue, &next_hold.v})
    if (v->capacity() < 2 * generation_rays()) v->reserve(2 * generation_rays());
  queue.assign(prim.size(), rc_ray{}); // fields a primary does not set stay 0
  leak_lists.assign(1, 0u);
  leak_uploaded = 0;
  batch.sums.assign(prim.size(), Vec3d{0, 0, 0});
  if (settings.contrib) batch.contrib.assign(prim.size() * 3 * settings.contrib->total_bins(), 0.0);
  batch.mirrored_sums.assign(prim.size(), Vec3d{0, 0, 0});
  batch.results = res;
  batch.root_depth.assign(prim.size(), 0);
  if (tree) {
    tally.reset(prim.size(), settings.seed, settings.trace != RenderSettings::Trace::Off,
                settings.std_error);
    tally.set_profile(&prof);
  }
  start_primaries(prim, res, queue, first_index);
  const std::vector<rc_hit> meters = meter_hits(prim, queue);
  timed.stop();
  trace_generations(queue, next_hold.v, hits, meters, res);
  timed.start(Phase::Batch);
  const auto finish = [&](std::size_t i) {
    res[i].value = tree ? tally.sum(i) : batch.sums[i];
    res[i].mirrored = tree ? tally.mirrored(i) : batch.mirrored_sums[i];
    if (settings.std_error) res[i].std_error = tally.std_error(i);
    if (settings.contrib) {
      const std::size_t w = 3 * settings.contrib->total_bins();
      res[i].contrib.assign(batch.contrib.begin() + static_cast<std::ptrdiff_t>(i * w),
                            batch.contrib.begin() + static_cast<std::ptrdiff_t>((i + 1) * w));
    }
  };
  if (settings.trace != RenderSettings::Trace::Off) {
    for (std::size_t i = 0; i < prim.size(); ++i) {
      finish(i);
      res[i].traced = traced(i);
    }
  } else {
    for_rows(prim.size(), finish);
  }
}

void Renderer::Impl::assign_slots(std::span<const PrimaryRay> prim, std::size_t first_index) {
  batch.first = first_index;
  batch.ids.clear();
  if (std::any_of(prim.begin(), prim.end(), [](const PrimaryRay& r) { return r.id != RC_NONE; })) {
    std::vector<std::uint32_t> ids(prim.size());
    for (std::size_t k = 0; k < prim.size(); ++k)
      ids[k] = prim[k].id != RC_NONE ? prim[k].id : static_cast<std::uint32_t>(first_index + k);
    batch.ids.assign(ids);
  }
}

void Renderer::Impl::start_primaries(std::span<const PrimaryRay> prim, std::span<PrimaryResult> res,
                                     RayQueue& queue, std::size_t first_index) {
  const bool in_medium = has_medium(settings);
  const Vec3d medium = in_medium ? settings.me : Vec3d{0, 0, 0};
  for_rows(prim.size(), [&](std::size_t i) {
    Vec3d d = unit(prim[i].dir);
    Vec3d o = prim[i].org;
    res[i] = PrimaryResult{};
    res[i].point = o;
    rc_ray& r = queue[i];
    r.org = f4(o[0] - centre[0], o[1] - centre[1], o[2] - centre[2], 0);
    r.dir = f4(d[0], d[1], d[2], prim[i].tmax > 0 ? prim[i].tmax : INFINITY);
    r.coef = f4(1, 1, 1, 1);
    r.primary = prim[i].id != RC_NONE ? prim[i].id : static_cast<std::uint32_t>(first_index + i);
    r.flags = RC_RAY_PRIMARY;
    r.tally = static_cast<std::uint32_t>(i);
    r.dist0 = 0;                              // patterns' T counts from the primary's start
    r.cext_r = static_cast<float>(medium[0]); // primaries start in the global medium
    r.cext_g = static_cast<float>(medium[1]);
    r.cext_b = static_cast<float>(medium[2]);
    r.medium = RC_MEDIUM_GLOBAL;
    r.gecc = static_cast<float>(settings.mg);
    r.slights = 0;
    if (!starts.empty()) { // a hemisphere sample of a record being made
      const RayStart& st = starts[first_index + i];
      r.cext_r = st.cext[0];
      r.cext_g = st.cext[1];
      r.cext_b = st.cext[2];
      r.medium = st.medium;
      r.gecc = st.gecc;
      r.slights = st.slights;
      r.flags = st.flags;
      r.depth = st.depth;
      r.ambient_depth = st.ambient_depth;
      r.coef.w = st.weight;
      r.dist0 = st.dist0;
      r.org.w = RC_TMIN_OFF; // its origin is already beside the surface
    }
    batch.root_depth[i] = r.depth;
  });
}

std::vector<rc_hit> Renderer::Impl::meter_hits(std::span<const PrimaryRay> prim,
                                               RayQueue& queue) const {
  // -I: the measurement point is a diffuse meter facing the given direction, meter_offset()
  // along it (where Radiance's reversed primary ray meets it); its hits stand in for the first
  // generation's trace. (A vector of its own: the pooled `hits` keeps its room for the chunks.)
  std::vector<rc_hit> meters;
  if (settings.irradiance_I && nesting == 0) {
    meters.resize(prim.size());
    for (std::size_t i = 0; i < prim.size(); ++i) {
      Vec3d d = unit(prim[i].dir);
      const Vec3d p = meter_point(geom, prim[i].org, d);
      rc_hit& h = meters[i];
      h = rc_hit{};
      h.pos = f4(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2], 1e-5);
      h.nrm = f4(d[0], d[1], d[2], 0);
      h.surface = RC_SURF_IRRADIANCE;
      h.source = RC_NONE;
      h.front = 1;
      queue[i].dir = f4(-d[0], -d[1], -d[2], INFINITY);
    }
  }
  return meters;
}

void Renderer::Impl::trace_generations(RayQueue& queue, RayQueue& next, HitQueue& hits,
                                       const std::vector<rc_hit>& meters,
                                       std::span<PrimaryResult> res) {
  // Each generation of rays goes through in chunks: trace, leak tests and shading of one
  // chunk before the next, so the per-ray scratch (Embree's answers, slots, shadow requests)
  // is bounded by the chunk and reused, not freshly mapped and cleared for a generation of
  // millions. Chunks keep queue order, so sums and records do not depend on their size.
  // Embree traces the next chunk while this one is shaded (a task beside the shading, which
  // leaves cores idle between its kernels and its host steps); the trace only writes that
  // chunk's hits and its primaries' geometric results, which shading never reads, and every
  // device command stays on this thread.
  bool first_wave = true;
  // The caller's primaries on a scene with textures: their perturbation for -on needs the
  // device's patterns (a mesh's smoothing alone the host knows).
  const bool texture_pert = nesting == 0 && starts.empty() && meters.empty() &&
                            (cs.features.has(RC_OBJ_TEXFUNC) || cs.features.has(RC_OBJ_TEXDATA));
  std::optional<device::Kernel> pert_kernel;
  // Three chunks' hits in turn: the one shaded, the next one traced beside it, and the last
  // one, which the tally fed beside the shading (feed_tally) may still read.
  Spare<HitQueue> ahead_hold(spare_hits, HitQueue(PinnedAlloc<rc_hit>(&ctx))),
      behind_hold(spare_hits, HitQueue(PinnedAlloc<rc_hit>(&ctx)));
  HitQueue &ahead = ahead_hold.v, &behind = behind_hold.v;
  // Declared after what the tally reads, so that it is waited for before those go, however
  // the batch ends.
  struct TallyWait {
    Impl& impl;
    ~TallyWait() {
      try {
        impl.wait_tally();
      } catch (...) { // the batch is ending on another error already
      }
    }
  } tally_wait{*this};
  const std::size_t chunk = chunk_rays();
  const bool overlap = settings.tuning.overlap;
  // A chunk's room at once: pinned memory is costly to take and give back.
  for (HitQueue* h : {&hits, &ahead, &behind})
    if (h->capacity() < chunk) h->reserve(chunk);
  gen_copy.start_batch();
  while (!queue.empty()) {
    const std::size_t n = queue.size();
    batch.generation = std::span<const rc_ray>(queue.data(), n);
    peak_generation = std::max(peak_generation, n);
    const auto part_at = [&](std::size_t a) {
      return std::span<const rc_ray>(queue.data() + a, std::min(n, a + chunk) - a);
    };
    const auto hits_at = [&](std::size_t a, HitQueue& h) {
      if (first_wave && !meters.empty())
        h.assign(meters.begin() + static_cast<std::ptrdiff_t>(a),
                 meters.begin() + static_cast<std::ptrdiff_t>(std::min(n, a + chunk)));
      else
        trace(part_at(a), h, res, first_wave);
    };
    hits_at(0, hits);
    for (std::size_t a = 0; a < n; a += chunk) {
      const std::span<const rc_ray> part = part_at(a);
      tbb::task_group tracing;
      const bool more = a + chunk < n;
      if (more && tally_reads(ahead)) wait_tally();
      if (more && overlap)
        ahead_arena.execute([&] { tracing.run([&] { hits_at(a + chunk, ahead); }); });
      test_leaks(part, hits);
      if (first_wave && texture_pert) texture_perts(*this, pert_kernel, part, hits.data(), res);
      // Shade in slices whose slots fit a modest allocation (a slice keeps queue order, so
      // sums stay in order).
      const std::size_t limit = settings.tuning.slice_bytes;
      size_slots(part, hits);
      for (std::size_t sa = 0; sa < part.size();) {
        std::size_t per_ray = cap_shadow * sizeof(rc_shadow) + cap_spawn * sizeof(rc_ray);
        // Slices start at multiples of 256 rays: there the kernels may read a queue in place
        // (a sub-buffer's start is aligned).
        std::size_t sb =
            std::min(part.size(), sa + std::max<std::size_t>(256, limit / per_ray / 256 * 256));
        shade_slice(part.data() + sa, hits.data() + sa, sb - sa, next);
        sa = sb;
      }
      ahead_arena.execute([&] { tracing.wait(); });
      if (more && !overlap) hits_at(a + chunk, ahead);
      std::swap(hits, ahead);
      std::swap(ahead, behind);
    }
    first_wave = false;
    wait_tally();
    if (tree)
      for (auto req = tally.take_requests(); !req.empty(); req = tally.take_requests())
        supersample(req, next);
    std::swap(queue, next);
    next.clear();
    gen_copy.advance();
  }
  batch.generation = {};
}

void Renderer::Impl::supersample(const std::vector<TallyTree::SuperRequest>& req, RayQueue& next) {
  Timed timed(prof, Phase::Super);
  std::size_t n = req.size();
  std::vector<rc_ray> rays(n);
  std::vector<rc_hit> hit(n);
  std::vector<std::uint32_t> off(n), data;
  for (std::size_t i = 0; i < n; ++i) {
    rays[i] = req[i].ray;
    hit[i] = req[i].hit;
    off[i] = static_cast<std::uint32_t>(data.size());
    data.push_back(req[i].which);
    data.insert(data.end(), req[i].counts.begin(), req[i].counts.end());
  }
  device::Buffer& brays = scratch(kRays, rays);
  device::Buffer& bhits = scratch(kHits, hit);
  device::Buffer& boff = scratch(kSuperOff, off);
  device::Buffer& bdata = scratch(kSuperData, data);
  device::Buffer& bnshadow = scratch(kNShadow, n * 4);
  device::Buffer& bnspawn = scratch(kNSpawn, n * 4);
  run_count(brays, bhits, bnshadow, bnspawn, n, &boff, &bdata);
  std::vector<std::uint32_t> spawn_off = bnspawn.to_vector<std::uint32_t>(n);
  std::vector<std::uint32_t> counts = spawn_off;
  std::uint32_t nspawn = prefix_sum(spawn_off);
  std::vector<std::uint32_t> zeros(n, 0);
  device::Buffer& bsoff = scratch(kShadowOff, zeros);
  device::Buffer& bpoff = scratch(kSpawnOff, spawn_off);
  device::Buffer& bshadows = scratch(kShadows, sizeof(rc_shadow));
  device::Buffer& bspawned = scratch(kSpawned, std::size_t{nspawn} * sizeof(rc_ray));
  device::Buffer& bimm = scratch(kImm, n * sizeof(rc_float4));
  ShadeLaunch l{&brays, &bhits, &bsoff, &bpoff, &bshadows, &bspawned, &bimm};
  l.super = 1;
  l.super_off = &boff;
  l.super_data = &bdata;
  run_shade(l, n);
  std::vector<rc_ray> children = bspawned.to_vector<rc_ray>(nspawn);
  for (std::size_t i = 0; i < n; ++i)
    tally.supersampled(req[i], children.data() + spawn_off[i], counts[i]);
  const std::size_t at = next.size();
  append_children(children, next);
  gen_copy.upload(next.data() + at, at, next.size() - at);
}

void Renderer::Impl::append_children(const std::vector<rc_ray>& children, RayQueue& next) {
  if (!collecting) {
    next.insert(next.end(), children.begin(), children.end());
    return;
  }
  for (const rc_ray& r : children)
    if ((r.flags & RC_RAY_KIND_MASK) == RC_RAY_AMBMISS)
      misses.push_back(r);
    else
      next.push_back(r);
}

void Renderer::Impl::set_misses_aside(RayQueue& next, std::size_t first) {
  if (!collecting) return;
  std::size_t k = first;
  for (std::size_t i = first; i < next.size(); ++i) {
    if ((next[i].flags & RC_RAY_KIND_MASK) == RC_RAY_AMBMISS)
      misses.push_back(next[i]);
    else
      next[k++] = next[i];
  }
  // The device's copy of these rows was made before they closed up.
  if (k != next.size()) gen_copy.upload(next.data() + first, first, k - first);
  next.resize(k);
}

} // namespace radcl::render
