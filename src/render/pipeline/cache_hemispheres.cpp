// The hemispheres of new cache records: their samples rendered as primaries, -as super-samples,
// then the record kernel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "pipeline_util.h"
#include "radcl/rng.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

void Renderer::Impl::supersample_hemispheres(const std::vector<rc_amb_hemi>& hemis,
                                             const std::vector<PrimaryRay>& rays,
                                             const std::vector<RayStart>& start,
                                             std::vector<PrimaryResult>& res,
                                             std::vector<double>& nearest) {
  if (settings.as <= 0) return;
  Timed timed(prof, Phase::Sample);
  std::vector<PrimaryRay> extra;
  std::vector<RayStart> extra_start;
  std::vector<std::size_t> division; // the sample slot each extra one refines
  for (const rc_amb_hemi& h : hemis) {
    const std::size_t ns = h.ns, n2 = ns * ns;
    if (n2 <= 49) continue;
    bool ok = true;
    for (std::size_t k = 0; k < n2 && ok; ++k)
      ok = sample_length(res[h.first + k]) > 1e-6;
    int cnt = static_cast<int>(settings.as * h.pos.w + 0.5);
    if (!ok || cnt <= 8) continue;
    std::vector<double> b(n2), e(n2, 0.0);
    for (std::size_t k = 0; k < n2; ++k)
      b[k] = bright(res[h.first + k].value);
    bool black_pair = false; // see TallyTree::allocate
    auto diff = [&](std::size_t a, std::size_t c) {
      const double s = b[a] + b[c];
      if (s <= 0) {
        black_pair = true;
        return;
      }
      const double d = (b[a] - b[c]) * (b[a] - b[c]) / s;
      e[a] += d;
      e[c] += d;
    };
    for (std::size_t i = 0; i < ns; ++i)
      for (std::size_t j = 0; j < ns; ++j) {
        const std::size_t k = i * ns + j;
        if (i) diff(k, k - ns);
        if (j) diff(k, k - 1);
        if (i && j) diff(k, k - ns - 1);
      }
    if (black_pair) continue;
    // Corners and edges have fewer neighbours.
    for (std::size_t k : {std::size_t{0}, ns - 1, (ns - 1) * ns, n2 - 1})
      e[k] *= 8.0 / 3.0;
    for (std::size_t i = 1; i + 1 < ns; ++i) {
      e[i * ns] *= 8.0 / 5.0;
      e[i * ns + ns - 1] *= 8.0 / 5.0;
      e[i] *= 8.0 / 5.0;
      e[(ns - 1) * ns + i] *= 8.0 / 5.0;
    }
    double rem = 0;
    for (double v : e)
      rem += v;
    const PrimaryRay& first = rays[h.first];
    rc_rng_key key = rc_make_key(first.id, 0x73757072u, 0, settings.seed);
    std::uint32_t dim = 0;
    for (std::size_t k = 0; k < n2 && cnt > 0 && rem > 1e-9; ++k) {
      const int nss = static_cast<int>(e[k] / rem * cnt + rc_random(key, dim++));
      const std::size_t i = k / ns, j = k % ns;
      const Vec3d n = {h.nrm.x, h.nrm.y, h.nrm.z}, ux = {h.ux.x, h.ux.y, h.ux.z},
                  uy = {h.uy.x, h.uy.y, h.uy.z};
      for (int m = 1; m <= nss && cnt > 0; ++m, --cnt) {
        const Vec3d dir = hemisphere_dir(n, ux, uy, (j + rc_random(key, dim + 1)) / ns,
                                         (i + rc_random(key, dim)) / ns);
        dim += 2;
        extra.push_back({first.org, dir, 0, next_sample_id++});
        extra_start.push_back(start[h.first]);
        division.push_back(h.first + k);
      }
      rem -= e[k];
    }
  }
  if (extra.empty()) return;
  std::vector<PrimaryResult> more(extra.size());
  timed.stop();
  {
    Nested nested(*this);
    build_render(extra, more, extra_start);
  }
  timed.start(Phase::Sample);
  // Each division's value: the mean of its samples; its distance: the nearest (its point
  // stays the first sample's).
  std::vector<int> count(res.size(), 1);
  for (std::size_t x = 0; x < extra.size(); ++x) {
    PrimaryResult& r = res[division[x]];
    const int c = ++count[division[x]];
    for (int k = 0; k < 3; ++k)
      r.value[k] += (more[x].value[k] - r.value[k]) / c;
    nearest[division[x]] = std::min(nearest[division[x]], sample_length(more[x]));
  }
}

double Renderer::Impl::sample_length(const PrimaryResult& r) {
  if (!r.hit) return 1e10;
  const double beyond = bright(r.mirrored) > 0.5 * bright(r.value) ? r.mirror_t : r.through_t;
  return std::min(1e10, r.t + std::max(beyond, 0.0));
}

Renderer::Impl::NewHemispheres
Renderer::Impl::hemisphere_rays(const std::vector<const rc_ray*>& chosen) {
  NewHemispheres out;
  std::vector<rc_amb_hemi>& hemis = out.hemis;
  std::vector<PrimaryRay>& rays = out.rays;
  std::vector<RayStart>& start = out.start;
  const HemisphereSettings hs{settings.ambient_min_radius, settings.ambient_max_radius,
                              settings.aa};
  // Which misses are sampled, each hemisphere's frame, first sample and ids, in order;
  // then the samples themselves, hemispheres in parallel (their ids fixed by that order).
  struct Frame {
    const rc_ray* m;
    Vec3d n, ux, uy;
    std::uint32_t rec; // the record's random key; its samples' ids follow it
    float sw;
  };
  std::vector<Frame> frames;
  std::size_t total = 0;
  for (const rc_ray* m : chosen) {
    const double wt = ambient_record_weight(static_cast<int>(m->ambient_depth), m->coef.w);
    const float sw = static_cast<float>(kAvgRefl * m->coef.w);
    if (sw < static_cast<float>(settings.lw)) continue; // rayorigin refuses every sample
    if (settings.lr > 0 && static_cast<int>(m->depth) + 1 > settings.lr) continue;
    const int ns = std::max(7, static_cast<int>(std::sqrt(settings.ad * wt) + 0.5));
    const Vec3d n = {m->dir.x, m->dir.y, m->dir.z};
    // A tangent axis: n crossed with the world axis it is least along.
    int a = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(n[k]) < std::fabs(n[a])) a = k;
    Vec3d e{0, 0, 0};
    e[a] = 1;
    const Vec3d ux =
        unit({n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0]});
    const Vec3d uy = {n[1] * ux[2] - n[2] * ux[1], n[2] * ux[0] - n[0] * ux[2],
                      n[0] * ux[1] - n[1] * ux[0]};
    hemis.push_back(make_hemisphere({m->org.x, m->org.y, m->org.z}, n, ux,
                                    static_cast<unsigned>(ns), static_cast<unsigned>(total),
                                    static_cast<int>(m->ambient_depth), wt, hs));
    frames.push_back({m, n, ux, uy, next_sample_id, sw});
    const std::size_t n2 = static_cast<std::size_t>(ns) * static_cast<std::size_t>(ns);
    next_sample_id += static_cast<std::uint32_t>(1 + n2);
    total += n2;
  }
  rays.resize(total);
  start.resize(total);
  tbb::parallel_for(std::size_t{0}, frames.size(), [&](std::size_t f) {
    const Frame& fr = frames[f];
    const rc_ray* m = fr.m;
    const int ns = static_cast<int>(hemis[f].ns);
    rc_rng_key key = rc_make_key(fr.rec, 0x616d62u, 0, settings.seed);
    // The samples leave from beside the surface (as the kernels' rays: rc_leave).
    const double lv = leave_dist(m->org.x, m->org.y, m->org.z);
    const Vec3d& n = fr.n;
    const Vec3d o = {m->org.x + centre[0] + lv * n[0], m->org.y + centre[1] + lv * n[1],
                     m->org.z + centre[2] + lv * n[2]};
    RayStart s;
    s.flags = RC_RAY_AMBIENT | RC_RAY_ROOT |
              (m->flags & ~(RC_RAY_KIND_MASK | RC_RAY_MIRRORED | RC_RAY_THROUGH | RC_RAY_TILTED));
    s.depth = m->depth + 1;
    s.ambient_depth = m->ambient_depth + 1;
    s.weight = fr.sw;
    s.dist0 = m->dist0; // Radiance's samples are children of the ray that needs the value
    s.cext[0] = m->cext_r;
    s.cext[1] = m->cext_g;
    s.cext[2] = m->cext_b;
    s.medium = m->medium;
    s.gecc = m->gecc;
    s.slights = m->slights;
    std::size_t at = hemis[f].first;
    std::uint32_t id = fr.rec + 1;
    for (int i = 0; i < ns; ++i)
      for (int j = 0; j < ns; ++j) {
        const std::uint32_t dim = 2u * static_cast<std::uint32_t>(i * ns + j);
        const Vec3d dir = hemisphere_dir(n, fr.ux, fr.uy, (j + rc_random(key, dim + 1)) / ns,
                                         (i + rc_random(key, dim)) / ns);
        rays[at] = {o, dir, 0, id++};
        start[at] = s;
        ++at;
      }
  });
  return out;
}

void Renderer::Impl::sample_hemispheres(const std::vector<const rc_ray*>& chosen) {
  Timed timed(prof, Phase::Sample);
  NewHemispheres nh = hemisphere_rays(chosen);
  const std::vector<rc_amb_hemi>& hemis = nh.hemis;
  const std::vector<PrimaryRay>& rays = nh.rays;
  const std::vector<RayStart>& start = nh.start;
  if (hemis.empty()) return;
  std::vector<PrimaryResult> res(rays.size());
  timed.stop();
  {
    Nested nested(*this);
    build_render(rays, res, start);
  }
  timed.start(Phase::Sample);
  std::vector<double> nearest(res.size());
  for_rows(res.size(), [&](std::size_t i) { nearest[i] = sample_length(res[i]); });
  timed.stop();
  supersample_hemispheres(hemis, rays, start, res, nearest);
  timed.start(Phase::Sample);
  // The strata as the record kernel reads them: value over ns^2, reciprocal distance (0:
  // nothing hit, < 0: a failed sample) and the point met, clamped as Radiance clamps it.
  const double far = 10 * settings.cube_size + 1000;
  std::vector<rc_amb_sample> samples(rays.size());
  tbb::parallel_for(std::size_t{0}, hemis.size(), [&](std::size_t hi) {
    const rc_amb_hemi& h = hemis[hi];
    for (std::uint32_t k = 0; k < h.ns * h.ns; ++k) {
      const std::size_t i = h.first + k;
      const PrimaryResult& r = res[i];
      const double t = sample_length(r), near = nearest[i];
      const double c = 1.0 / (static_cast<double>(h.ns) * h.ns);
      samples[i].val = f4(r.value[0] * c, r.value[1] * c, r.value[2] * c,
                          near <= 1e-6  ? -1.0
                          : near < 1e10 ? 1 / near
                                        : 0.0);
      const double reach = std::min(t, far);
      samples[i].pnt = f4(h.pos.x + reach * rays[i].dir[0], h.pos.y + reach * rays[i].dir[1],
                          h.pos.z + reach * rays[i].dir[2], 0);
    }
  });
  timed.stop();
  if (!maker) {
    Timed t(prof, Phase::Build);
    maker = std::make_unique<RecordMaker>(ctx);
  }
  MadeRecords out = [&] {
    Timed t(prof, Phase::Records);
    return maker->make(hemis, samples);
  }();
  std::size_t added = 0;
  for (std::size_t k = 0; k < out.records.size(); ++k) {
    if (out.made[k].status != RC_AMB_RECORD) continue;
    ambient::AmbientRecord a = to_ambient_record(out.records[k], out.made[k].corral, centre);
    cache_records.push_back(a);
    cache_local.push_back(to_ambient_record(out.records[k], out.made[k].corral, {0, 0, 0}));
    made.push_back(a);
    ++added;
  }
  stats.records += added;
  if (settings.tuning.debug_cache)
    std::fprintf(stderr, "cache: nesting %d: %zu hemispheres, %zu records\n", nesting, hemis.size(),
                 added);
  if (added) upload_cache();
}

} // namespace radcl::render
