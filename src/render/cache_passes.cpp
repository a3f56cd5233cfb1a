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
  const char* lt = std::getenv("RADCL_LEAK_TEST"); // "0": no leak test (to measure it)
  const bool leak_test = !(lt && std::string(lt) == "0");
  const std::size_t n = uses_cache(settings) ? cache_local.size() : 0;
  auto marked_of = [&](std::size_t from, std::size_t to, std::vector<std::uint32_t>& src) {
    std::vector<ambient::AmbientRecord> recs;
    src.clear();
    for (std::size_t i = from; i < to; ++i)
      if (cache_local[i].corral) {
        src.push_back(static_cast<std::uint32_t>(i));
        recs.push_back(cache_local[i]);
      }
    return leak_test ? build_ambient_cache(recs, {0, 0, 0}, settings.aa) : AmbientCacheBuffers{};
  };
  if (n < base_n || n - base_n > std::max<std::size_t>(256, base_n / 2)) {
    base_on_device = false;
    base_n = n;
    cache_base = build_ambient_cache(std::span(cache_local).first(n), {0, 0, 0}, settings.aa);
    marked_base = marked_of(0, n, marked_base_src);
  }
  const std::span<const ambient::AmbientRecord> newer =
      std::span(cache_local).subspan(base_n, n - base_n);
  cache = join_ambient_caches(cache_base, build_ambient_cache(newer, {0, 0, 0}, settings.aa),
                              static_cast<std::uint32_t>(base_n));
  marked = AmbientCacheBuffers{};
  leak_tester = LeakTester();
  if (leak_test && !cache.records.empty()) {
    // The marked records' tree, its leaves named by their index in `cache`.
    std::vector<std::uint32_t> newer_src;
    AmbientCacheBuffers mn = marked_of(base_n, n, newer_src);
    std::vector<std::uint32_t> src = marked_base_src; // marked input index -> cache_local
    src.insert(src.end(), newer_src.begin(), newer_src.end());
    marked =
        join_ambient_caches(marked_base, mn, static_cast<std::uint32_t>(marked_base_src.size()));
    if (!marked.records.empty()) {
      std::vector<std::uint32_t> leaf_of(cache_local.size(), 0);
      for (std::size_t k = 0; k < cache.source.size(); ++k)
        leaf_of[cache.source[k]] = static_cast<std::uint32_t>(k);
      std::vector<std::uint32_t> to_full(marked.source.size());
      for (std::size_t j = 0; j < to_full.size(); ++j)
        to_full[j] = leaf_of[src[marked.source[j]]];
      leak_tester = LeakTester(&marked, static_cast<float>(settings.aa),
                               static_cast<float>(settings.ambient_min_radius), std::move(to_full));
    }
  }
  base.amb.z = static_cast<float>(cache.nodes.size());
  if (settings.aw > 0 && uses_cache(settings)) {
    auto v = averaged_ambient_value({settings.av[0], settings.av[1], settings.av[2]}, settings.aw,
                                    cache_records);
    base.av = f4(v[0], v[1], v[2], settings.lw);
  }
  // The joined forest starts with the large tree's nodes and records, which the device
  // already holds unless that tree was just rebuilt.
  const bool keep = base_on_device && !cache_base.nodes.empty();
  amb_records.update(ctx, cache.records, keep ? cache_base.records.size() : 0);
  amb_nodes.update(ctx, cache.nodes, keep ? cache_base.nodes.size() : 0);
  base_on_device = true;
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
    const bool saved_tree = tree;
    const std::span<const RayStart> saved_starts = starts;
    if (!last) tree = false; // nothing is super-sampled while misses are only reported
    starts = whole ? st : std::span<const RayStart>(sub_start);
    set_collect(!last);
    // A first pass whose every lookup must miss (no record is at or below its rays' ambient
    // depth) is thrown away whole: its shadow rays are not traced, and every ray goes again.
    throwaway = round == 0 && !last && will_all_miss(st);
    misses.clear();
    timed.stop();
    const auto t0 = std::chrono::steady_clock::now();
    run(sub, res);
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    timed.start(Phase::Bookkeeping);
    set_collect(false);
    const bool thrown = std::exchange(throwaway, false);
    starts = saved_starts;
    tree = saved_tree;
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
    if (std::getenv("RADCL_DEBUG_CACHE"))
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
