// The irradiance cache's build passes: rendering while records are made, and uploading the
// cache for the kernels' lookups and the host's leak tests.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pipeline_util.h"
#include "radcl/ambient/spread_choice.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

void Renderer::Impl::upload_cache() {
  Timed timed(prof, Phase::Upload);
  for (; level_seen < cache_local.size(); ++level_seen)
    min_level = std::min<int>(min_level, cache_local[level_seen].lvl);
  const bool leak_test = settings.tuning.leak_test; // off: to measure it
  const std::size_t n = uses_cache(settings) ? cache_local.size() : 0;
  const CacheForest::Change c = forest.update(cache_local, n, settings.aa, leak_test);
  if (c.any) { // the device keeps what comes before the change
    amb_records.update(ctx, forest.lookup().records, c.records);
    amb_nodes.update(ctx, forest.lookup().nodes, c.nodes);
  }
  leak_tester = LeakTester();
  if (leak_test && !forest.marked().records.empty())
    leak_tester = LeakTester(&forest.marked(), static_cast<float>(settings.aa),
                             static_cast<float>(settings.ambient_min_radius), &forest.to_full());
  base.amb.z = static_cast<float>(forest.lookup().nodes.size());
  if (settings.aw > 0 && uses_cache(settings)) {
    auto v = averaged_ambient_value({settings.av[0], settings.av[1], settings.av[2]}, settings.aw,
                                    cache_records);
    base.av = f4(v[0], v[1], v[2], settings.lw);
  }
  rc_params p = base;
  p.amb.w = collecting ? 1.0f : 0.0f;
  params.write(&p, sizeof p);
}

void Renderer::Impl::set_collect(bool on) {
  collecting = on;
  rc_params p = base;
  p.amb.w = on ? 1.0f : 0.0f;
  params.write(&p, sizeof p);
}

Renderer::Impl::CachePass::CachePass(Impl& im, std::span<const RayStart> st, bool last)
    : im_(im), tree_(im.tree), starts_(im.starts) {
  if (!last) im.tree = false; // nothing is super-sampled while misses are only reported
  im.starts = st;
  im.set_collect(!last);
  im.misses.clear();
}

bool Renderer::Impl::CachePass::end() {
  ended_ = true;
  im_.set_collect(false);
  const bool thrown = std::exchange(im_.throwaway, false);
  im_.starts = starts_;
  im_.tree = tree_;
  return thrown;
}

Renderer::Impl::CachePass::~CachePass() {
  if (ended_) return;
  // The render failed: the renderer's fields as they were (the device's may be lost).
  im_.collecting = false;
  im_.throwaway = false;
  im_.starts = starts_;
  im_.tree = tree_;
}

bool Renderer::Impl::will_all_miss(std::span<const RayStart> st) const {
  if (st.empty()) return settings.ab > 0 && min_level > 0;
  return std::all_of(st.begin(), st.end(), [&](const RayStart& r) {
    const int d = static_cast<int>(r.ambient_depth);
    return d < settings.ab && d < min_level;
  });
}

void Renderer::Impl::build_render(std::span<const PrimaryRay> rays,
                                  std::span<PrimaryResult> results, std::span<const RayStart> st) {
  std::vector<std::uint32_t> todo(rays.size());
  for (std::size_t i = 0; i < todo.size(); ++i)
    todo[i] = static_cast<std::uint32_t>(i);
  const bool have_ids =
      std::none_of(rays.begin(), rays.end(), [](const PrimaryRay& r) { return r.id == RC_NONE; });
  for (int round = 0; !todo.empty(); ++round) {
    Timed timed(prof, Phase::Bookkeeping);
    const bool last = round >= kRounds;
    // The first pass renders every ray in place; later ones the copies of those that missed.
    const bool whole = round == 0 && have_ids;
    std::vector<PrimaryRay> sub_rays;
    std::vector<RayStart> sub_start;
    std::vector<PrimaryResult> sub_res;
    std::vector<std::uint32_t> ids;
    if (!whole) {
      sub_rays.resize(todo.size());
      if (!st.empty()) sub_start.resize(todo.size());
      for_rows(todo.size(), [&](std::size_t k) {
        const std::uint32_t i = todo[k];
        PrimaryRay& r = sub_rays[k] = rays[i];
        if (r.id == RC_NONE) r.id = i; // the same random numbers in every pass
        if (!st.empty()) sub_start[k] = st[i];
      });
    }
    const std::span<const PrimaryRay> sub = whole ? rays : std::span<const PrimaryRay>(sub_rays);
    if (!whole) sub_res.resize(sub.size());
    const std::span<PrimaryResult> res = whole ? results : std::span<PrimaryResult>(sub_res);
    ids.resize(sub.size());
    for_rows(sub.size(), [&](std::size_t k) { ids[k] = sub[k].id; });
    IdSlots at;
    at.assign(ids);
    CachePass pass(*this, whole ? st : std::span<const RayStart>(sub_start), last);
    // A first pass whose every lookup must miss (no record is at or below its rays' ambient
    // depth) is thrown away whole: its shadow rays are not traced, and every ray goes again.
    throwaway = round == 0 && !last && will_all_miss(st);
    timed.stop();
    const auto t0 = std::chrono::steady_clock::now();
    run(sub, res);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    timed.start(Phase::Bookkeeping);
    const bool thrown = pass.end();
    std::vector<rc_ray> miss = std::move(misses);
    misses.clear();
    std::vector<char> missed(sub.size(), 0);
    for (const rc_ray& m : miss)
      missed[at.at(m.primary)] = 1;
    std::vector<std::uint32_t> again;
    for (std::size_t k = 0; k < sub.size(); ++k)
      if (missed[k] || thrown) again.push_back(todo[k]);
    if (!whole && !thrown)
      for_rows(sub.size(), [&](std::size_t k) {
        if (!missed[k]) results[todo[k]] = std::move(res[k]);
      });
    if (settings.tuning.debug_cache)
      std::fprintf(stderr,
                   "cache: nesting %d round %d: %zu primaries, %zu missed, %zu misses %.6f\n",
                   nesting, round, sub.size(), again.size(), miss.size(), dt);
    timed.stop();
    if (!miss.empty()) make_records(miss, round);
    todo = std::move(again);
  }
}

void Renderer::Impl::make_records(const std::vector<rc_ray>& miss, int round) {
  const double aa = settings.aa;
  const double floor_sep = aa * std::max(settings.ambient_min_radius, 1e-6 * settings.cube_size);
  const double sep = std::max(floor_sep, aa * settings.ambient_max_radius / std::ldexp(1.0, round));
  Timed timed(prof, Phase::Choose);
  std::vector<const rc_ray*> chosen;
  for (std::uint32_t i : choose_spread(miss, sep))
    chosen.push_back(&miss[i]);
  timed.stop();
  sample_hemispheres(chosen);
}

} // namespace radcl::render
