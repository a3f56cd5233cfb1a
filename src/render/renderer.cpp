#include "radcl/render/renderer.h"
#include "radcl/render/irradiance_meter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "radcl/ambient/cache.h"
#include "radcl/ambient/dircode.h"
#include "radcl/ambient/leaks.h"
#include "radcl/ambient/record_maker.h"
#include "radcl/ambient/spread_choice.h"
#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device/growing_buffer.h"
#include "radcl/device/program.h"
#include "radcl/render/id_slots.h"
#include "radcl/render/phase_profile.h"
#include "radcl/render/tally_tree.h"
#include "radcl/render/virtual_sources.h"
#include "radcl/rng.h"
#include "radcl/scene/object_type.h"
#include "radcl/util/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace radcl::render {

// The irradiance cache's parts (trees, leak test, record kernel, spread choice) live in ambient/.
using namespace ambient;

namespace {

// Radiance's bright() as the host's ambient code weighs samples.
double bright(const Vec3d& c) {
  return 0.2651 * c[0] + 0.6701 * c[1] + 0.0648 * c[2];
}

rc_float4 f4(double x, double y, double z, double w) {
  return rc_float4{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z),
                   static_cast<float>(w)};
}

Vec3d unit(const Vec3d& v) {
  double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return l > 0 ? Vec3d{v[0] / l, v[1] / l, v[2] / l} : Vec3d{0, 0, 0};
}

// Exclusive prefix sum; returns the total.
std::uint32_t prefix_sum(std::vector<std::uint32_t>& v) {
  std::uint32_t sum = 0;
  for (std::uint32_t& x : v) {
    std::uint32_t c = x;
    x = sum;
    sum += c;
  }
  return sum;
}

template <class T> device::Buffer upload(device::Context& ctx, const std::vector<T>& v) {
  return v.empty() ? device::Buffer(ctx, sizeof(T)) : device::Buffer::from(ctx, v);
}

// Shirley and Chiu's concentric map of the unit square onto the unit disc (as the kernels'
// rc_square_to_disk), for the hemispheres of new records.
std::array<double, 2> square_to_disk(double sx, double sy) {
  const double a = 2 * sx - 1, b = 2 * sy - 1;
  if (a == 0 && b == 0) return {0, 0};
  const double q = 3.14159265358979323846 / 4;
  double r, phi;
  if (a * a > b * b) {
    r = a;
    phi = q * (b / a);
  } else {
    r = b;
    phi = 2 * q - q * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Runs f(i) for every i in [0, n): in parallel where there are enough to pay for it (the
// per-ray host loops of a wave of millions of hemisphere samples).
template <class F> void for_rows(std::size_t n, const F& f) {
  constexpr std::size_t kGrain = 4096;
  if (n < 2 * kGrain) {
    for (std::size_t i = 0; i < n; ++i)
      f(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      f(i);
  });
}

// Whether lookups in an irradiance cache run: records to look up, -aa > 0 and a bounce.
bool uses_cache(const RenderSettings& st) {
  return st.ab > 0 && st.aa > 0 && (st.make_records || !st.ambient_records.empty());
}

device::ProgramSource shade_program(const CompiledScene& cs, const RenderSettings& st) {
  device::FeatureSet f = cs.features;
  if (uses_cache(st)) f.define("RADCL_HAS_AMBCACHE");
  return f.program({"render/shade.cl"});
}

device::Program built(PhaseProfile& prof, device::Context& c, const device::ProgramSource& src) {
  PhaseProfile::Scope t(prof, Phase::Build);
  return device::Program(c, src);
}

} // namespace

struct Renderer::Impl {
  const scene::LoadedScene& scene;
  RenderSettings settings;
  device::Context& ctx;
  geometry::SceneGeometry geom;
  CompiledScene cs;
  PhaseProfile prof; // before the program: its lifetime includes building it
  device::Program program;
  device::Kernel shade, accumulate, shadow_step;
  device::Buffer surfaces, materials, args, sources, verts, mirrors, params, patterns;
  device::GrowingBuffer amb_records, amb_nodes, amb_blocked;
  // Kernel arguments set_scene_args() fills; a kernel's next argument follows them.
  static constexpr unsigned kSceneArgs = 11;
  Vec3d centre;
  RenderStats stats;
  using Timed = PhaseProfile::Scope;
  // -as: hemisphere samples tally per division until the super-samples are decided.
  bool tree = false;
  TallyTree tally;

  // Per-wave buffers, kept between waves and grown when a wave needs more: allocating them
  // afresh every wave spends more time clearing pages than shading.
  enum Slot {
    kRays,
    kHits,
    kNShadow,
    kNSpawn,
    kShadowOff,
    kSpawnOff,
    kShadows,
    kSpawned,
    kImm,
    kBlocked,
    kTotal,
    kStepRays,
    kStepHits,
    kStepState,
    kSuperOff,
    kSuperData,
    kShadowSlots,
    kSpawnSlots,
    kSlots
  };
  // Room per ray in the shading pass's slots, set per wave by size_slots (any value gives the
  // same records; a good one makes re-shading rare and keeps the slots small).
  std::uint32_t cap_shadow = 16, cap_spawn = 2;
  static constexpr std::size_t kUncountedWave = 2048;
  // Rays of a generation traced and shaded together (RADCL_CHUNK_RAYS sets it, for tests and
  // tuning): large enough that launches and transfers are a small part of a chunk's time,
  // small enough that its scratch stays in the caches and in reused pages. On a device that
  // shares the host's memory (PoCL) 2^16 was fastest (office, -ab 2 -ad 1024 on 2 cores:
  // 1.96 s, 2.41 s with 2^14, 3.64 s with 2^18 whose scratch is paged in afresh).
  std::size_t chunk_rays() const {
    if (const char* e = std::getenv("RADCL_CHUNK_RAYS"); e && *e)
      return std::max<std::size_t>(1, std::strtoull(e, nullptr, 10));
    return ctx.zero_copy() ? std::size_t{1} << 16 : std::size_t{1} << 18;
  }
  std::vector<device::Buffer> pool = std::vector<device::Buffer>(kSlots);
  std::vector<char> peek_sh, peek_sp; // host copies of the slots where the device is not the host
  device::Buffer& scratch(Slot slot, std::size_t bytes) {
    bytes = std::max<std::size_t>(bytes, 16);
    if (pool[slot].size() < bytes) pool[slot] = device::Buffer(ctx, bytes + bytes / 2);
    return pool[slot];
  }
  template <class T> device::Buffer& scratch(Slot slot, const std::vector<T>& v) {
    device::Buffer& b = scratch(slot, v.size() * sizeof(T));
    if (!v.empty()) b.write(v.data(), v.size() * sizeof(T));
    return b;
  }

  ~Impl() {
    if (prof.on()) prof.print(stderr);
  }
  Impl(const scene::LoadedScene& s, const RenderSettings& st, device::Context& c)
      : scene(s), settings(st), ctx(c), geom(s), cs(compile_scene(s, geom)),
        program(built(prof, c, shade_program(cs, st))), shade(program.kernel("rc_shade")),
        accumulate(program.kernel("rc_accumulate")), shadow_step(program.kernel("rc_shadow_step")),
        surfaces(upload(c, cs.surfaces)), materials(upload(c, cs.materials)),
        args(upload(c, cs.args)), params(c, sizeof(rc_params)), patterns(upload(c, cs.patterns)),
        centre(geom.centre()) {
    amb_blocked.update(c, std::vector<std::uint32_t>(4, 0u), 0);
    if (st.ambient_list != RenderSettings::AmbientList::None) {
      mark_ambient_list(cs, st.ambient_list == RenderSettings::AmbientList::Include,
                        st.ambient_names);
      surfaces = upload(c, cs.surfaces);
    }
    rc_params p{};
    p.av = f4(st.av[0], st.av[1], st.av[2], st.lw);
    p.direct = f4(st.ds, st.dj, st.dt, st.dc);
    // Rays leave surfaces at least this far along; the kernels widen it where a point's float
    // coordinates are coarser (rc_leave in shade.cl), so small detail near the centre of a
    // huge scene is not skipped.
    p.spec = f4(st.ss, st.st, geom.epsilon(), 0);
    p.seed = st.seed;
    p.lr = st.lr;
    p.flags = (st.dv ? RC_PF_DV : 0u) | (st.bv ? RC_PF_BV : 0u) |
              (st.irradiance_i ? RC_PF_IRRAD_I : 0u) | (st.low_discrepancy ? RC_PF_LOWDISC : 0u);
    p.ab = static_cast<std::uint32_t>(st.ab);
    p.nsources = static_cast<std::uint32_t>(cs.sources.sources.size());
    p.irradiance_material = cs.irradiance_material;
    p.ad = static_cast<std::uint32_t>(std::max(0, st.ad));
    bool super = st.as > 0 && st.ab > 0 && st.ad > 0;
    tree = super || st.trace != RenderSettings::Trace::Off;
    p.as = super ? static_cast<std::uint32_t>(st.as) : 0u;
    ray_eps = p.spec.z;
    cache_records = st.ambient_records;
    for (const ambient::AmbientRecord& a : cache_records)
      cache_local.push_back(local_record(a));
    building = uses_cache(st) && st.make_records && st.trace == RenderSettings::Trace::Off;
    p.amb = f4(st.aa, st.ambient_min_radius, 0, 0);
    base = p;
    upload_cache();
    p = base;
    params.write(&p, sizeof p);
    upload_sources();
    add_virtual_sources(
        s.main, geom,
        [&](std::int32_t obj) { return cs.placement_base[0] + static_cast<std::uint32_t>(obj); },
        st.dr, st.dp,
        [&](const CompiledSources& so, const std::vector<rc_shadow>& rays) {
          return pretest(so, rays);
        },
        cs.sources);
    upload_sources();
    p.nsources = static_cast<std::uint32_t>(cs.sources.sources.size());
    params.write(&p, sizeof p);
    base = p;
    stats = RenderStats{}; // the pretest's rays are not the caller's
  }

  // ---- The irradiance cache (docs/cache-internals.md) ----
  // How a primary starts when it is a hemisphere sample of a record being made.
  struct RayStart {
    std::uint32_t flags = RC_RAY_PRIMARY, depth = 0, ambient_depth = 0;
    float weight = 1;
    float dist0 = 0; // the ray tree's length before it: the record's point is its parent's hit
  };
  rc_params base{};   // the uploaded parameters, amb.w aside
  double ray_eps = 0; // the least distance rays leave surfaces by (spec.z)
  // How far off a surface a ray leaving point p (re-centred) starts, as the kernels' rc_leave:
  // never less than p's float coordinates resolve.
  double leave_dist(double x, double y, double z) const {
    return std::max(ray_eps, 8e-7 * std::max({std::fabs(x), std::fabs(y), std::fabs(z)}));
  }
  bool building = false;            // misses become records
  bool collecting = false;          // this pass reports misses (amb.w = 1)
  int nesting = 0;                  // > 0 while a record's samples are rendered
  std::span<const RayStart> starts; // per primary of the current run(); empty: the caller's
  std::vector<rc_ray> misses;       // record requests of the current pass
  std::vector<ambient::AmbientRecord> cache_records; // all, world coordinates
  // The same records with positions relative to the scene's centre: the lookup's copy. A
  // record made here keeps its position as the kernel computed it (float world coordinates
  // far from the origin would move it by their rounding: 4 mm at 1e5 m, 3 cm at 1e6 m).
  std::vector<ambient::AmbientRecord> cache_local;
  std::vector<ambient::AmbientRecord> made; // made since take_new_records()
  std::uint32_t next_sample_id = 0x40000000u;
  std::unique_ptr<RecordMaker> maker; // the record kernel, built when first needed

  // The cache as uploaded, the same over its corral-marked records only (the leak tests walk
  // that on the host) and the leak tester.
  AmbientCacheBuffers cache, marked;
  LeakTester leak_tester;
  // The current render_batch's lists of records whose leak test failed, per hit: [count,
  // index...]; a hit names its list in nrm.w (docs/cache-internals.md).
  std::vector<std::uint32_t> leak_lists{0};
  std::size_t leak_uploaded = 0;

  // The lookup tree (and the leak test's tree of marked records) as a large tree over the
  // records up to base_n joined to a small one over those added since: the large one is rebuilt
  // only when the newer records reach half its size (at least 256), so adding records to a
  // big loaded cache costs what the new ones cost. The floor was 2,048 until session 12: a
  // cache build uploads a hundred times or more, and below the floor every upload rebuilt the
  // whole tree (rpict office_view 256^2: 0.16 s of uploads on 2 cores, now 0.04 s).
  AmbientCacheBuffers cache_base, marked_base;
  std::size_t base_n = 0;
  bool base_on_device = false;                // the device's lookup buffers begin with cache_base's
  std::vector<std::uint32_t> marked_base_src; // cache_local index of each marked_base input
  // The lowest level of any record (INT_MAX: none), counted up to level_seen: a lookup at
  // ambient depth d accepts records of level d or lower only.
  int min_level = std::numeric_limits<int>::max();
  std::size_t level_seen = 0;

  void upload_cache() {
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
        leak_tester =
            LeakTester(&marked, static_cast<float>(settings.aa),
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

  // A record read from a file or shared by another process, re-centred (in double).
  ambient::AmbientRecord local_record(ambient::AmbientRecord a) const {
    for (int i = 0; i < 3; ++i)
      a.pos[i] = static_cast<float>(static_cast<double>(a.pos[i]) - centre[i]);
    return a;
  }

  void set_collect(bool on) {
    collecting = on;
    rc_params p = base;
    p.amb.w = on ? 1.0f : 0.0f;
    params.write(&p, sizeof p);
  }

  // Renders `rays` while the cache grows: a pass reports the misses of its primaries, records
  // are made for a well-spread choice of them, and the primaries that missed are shaded again;
  // after kRounds passes what still misses is sampled as with -aa 0. A primary's value is the
  // one of its first pass without a miss, so it is computed as Radiance computes it once the
  // records it needs exist.
  static constexpr int kRounds = 12;
  bool throwaway = false; // this pass's values are thrown away: no shadow rays, no sums

  // Whether every ray of a cache-build pass looks records up and none can be accepted: rays at
  // ambient depth d (starts', else 0) below -ab, and no record of level d or lower.
  bool will_all_miss(std::span<const RayStart> st) const {
    if (st.empty()) return settings.ab > 0 && min_level > 0;
    return std::all_of(st.begin(), st.end(), [&](const RayStart& r) {
      const int d = static_cast<int>(r.ambient_depth);
      return d < settings.ab && d < min_level;
    });
  }
  void build_render(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results,
                    std::span<const RayStart> st) {
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
      const double dt =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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

  // Makes records for a well-spread subset of `miss`: in order, a miss is chosen unless a
  // chosen one of its level, facing within 60 degrees, lies within aa x maxarad / 2^round (not
  // below aa x minarad) of it. Round 0 spaces records by the largest region a record can
  // cover; each later round sees only the points earlier records left uncovered and halves the
  // spacing, so records go where Radiance's sequential order would put them (a miss no record
  // covers) and the cache keeps its -aa/-ar adaptivity.
  void make_records(const std::vector<rc_ray>& miss, int round) {
    const double aa = settings.aa;
    const double floor_sep = aa * std::max(settings.ambient_min_radius, 1e-6 * settings.cube_size);
    const double sep =
        std::max(floor_sep, aa * settings.ambient_max_radius / std::ldexp(1.0, round));
    Timed timed(prof, Phase::Choose);
    std::vector<const rc_ray*> chosen;
    for (std::uint32_t i : choose_spread(miss, sep))
      chosen.push_back(&miss[i]);
    timed.stop();
    sample_hemispheres(chosen);
  }

  // Radiance's samp_hemi for each chosen miss (ns x ns stratified cosine-weighted directions,
  // ns = sqrt(-ad x record weight), at least 7), the samples rendered as primaries one
  // ambient level deeper (their own misses make records first), then the record kernel
  // (ambient/record_maker.h) turns each complete hemisphere into a record.
  // -as for a record (Radiance's ambsupersamp): where the squared brightness differences of a
  // division's neighbours say the hemisphere varies most, more samples of that division are
  // rendered, as many as its share of the budget -as x weight (when that exceeds 8 and every
  // sample of more than 7 x 7 divisions succeeded); a division's value becomes the mean of its
  // samples and its distance the nearest (its point stays the first sample's).
  void supersample_hemispheres(const std::vector<rc_amb_hemi>& hemis,
                               const std::vector<PrimaryRay>& rays,
                               const std::vector<RayStart>& start, std::vector<PrimaryResult>& res,
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
          const auto d =
              square_to_disk((j + rc_random(key, dim + 1)) / ns, (i + rc_random(key, dim)) / ns);
          dim += 2;
          const double z = std::sqrt(std::max(0.0, 1 - d[0] * d[0] - d[1] * d[1]));
          Vec3d dir;
          for (int c = 0; c < 3; ++c)
            dir[c] = d[0] * ux[c] + d[1] * uy[c] + z * n[c];
          extra.push_back({first.org, unit(dir), 0, next_sample_id++});
          extra_start.push_back(start[h.first]);
          division.push_back(h.first + k);
        }
        rem -= e[k];
      }
    }
    if (extra.empty()) return;
    std::vector<PrimaryResult> more(extra.size());
    timed.stop();
    ++nesting;
    build_render(extra, more, extra_start);
    --nesting;
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

  // A hemisphere sample's length as Radiance's raydistance(): through glass and other clear
  // transmission the effective length goes on to what lies beyond (the sky seen through a
  // window is far, not at the pane), along the mirror reflection where that carries more than
  // half the value; 1e10 where nothing was met.
  static double sample_length(const PrimaryResult& r) {
    if (!r.hit) return 1e10;
    const double beyond = bright(r.mirrored) > 0.5 * bright(r.value) ? r.mirror_t : r.through_t;
    return std::min(1e10, r.t + std::max(beyond, 0.0));
  }

  void sample_hemispheres(const std::vector<const rc_ray*>& chosen) {
    std::vector<rc_amb_hemi> hemis;
    std::vector<PrimaryRay> rays;
    std::vector<RayStart> start;
    Timed timed(prof, Phase::Sample);
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
      std::size_t at = hemis[f].first;
      std::uint32_t id = fr.rec + 1;
      for (int i = 0; i < ns; ++i)
        for (int j = 0; j < ns; ++j) {
          const std::uint32_t dim = 2u * static_cast<std::uint32_t>(i * ns + j);
          const auto d =
              square_to_disk((j + rc_random(key, dim + 1)) / ns, (i + rc_random(key, dim)) / ns);
          const double z = std::sqrt(std::max(0.0, 1 - d[0] * d[0] - d[1] * d[1]));
          Vec3d dir;
          for (int k = 0; k < 3; ++k)
            dir[k] = d[0] * fr.ux[k] + d[1] * fr.uy[k] + z * n[k];
          rays[at] = {o, unit(dir), 0, id++};
          start[at] = s;
          ++at;
        }
    });
    if (hemis.empty()) return;
    std::vector<PrimaryResult> res(rays.size());
    timed.stop();
    ++nesting;
    build_render(rays, res, start);
    --nesting;
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
    if (std::getenv("RADCL_DEBUG_CACHE"))
      std::fprintf(stderr, "cache: nesting %d: %zu hemispheres, %zu records\n", nesting,
                   hemis.size(), added);
    if (added) upload_cache();
  }

  void upload_sources() {
    sources = upload(ctx, cs.sources.sources);
    verts = upload(ctx, cs.sources.verts);
    mirrors = upload(ctx, cs.sources.mirrors);
  }

  // The virtual-source pretest's shadow rays, against the sources made so far (`so` is
  // cs.sources while it grows; trace_shadows reads it there).
  std::vector<float> pretest(const CompiledSources& so, const std::vector<rc_shadow>& rays) {
    sources = upload(ctx, so.sources);
    verts = upload(ctx, so.verts);
    mirrors = upload(ctx, so.mirrors);
    std::vector<rc_shadow> sh = rays;
    std::vector<std::uint8_t> blocked = trace_shadows(sh);
    std::vector<float> out(sh.size());
    for (std::size_t i = 0; i < sh.size(); ++i)
      out[i] = blocked[i] ? 0.0f : sh[i].contrib.x;
    return out;
  }

  void set_scene_args(device::Kernel& k, unsigned first) {
    k.arg(first, surfaces)
        .arg(first + 1, materials)
        .arg(first + 2, args)
        .arg(first + 3, sources)
        .arg(first + 4, verts)
        .arg(first + 5, mirrors)
        .arg(first + 6, params)
        .arg(first + 7, patterns)
        .arg(first + 8, amb_records.buffer())
        .arg(first + 9, amb_nodes.buffer())
        .arg(first + 10, amb_blocked.buffer());
  }

  // One launch of rc_shade over `n` rays: per ray, its output offsets (or, with caps, where the
  // counts go back), the record buffers, its immediate value, the -as pass's requests (super
  // = 0: none) and the per-ray slot capacities (~0u: exact room at the given offsets).
  struct ShadeLaunch {
    device::Buffer *rays, *hits, *shadow_off, *spawn_off, *shadows, *spawned, *immediate;
    std::uint32_t super = 0;
    device::Buffer *super_off = nullptr, *super_data = nullptr;
    std::uint32_t cap_shadow = ~0u, cap_spawn = ~0u;
    device::Buffer *nshadow = nullptr, *nspawn = nullptr; // counts out (default: the offsets)
  };
  void run_shade(const ShadeLaunch& l, std::size_t n) {
    shade.arg(0, *l.rays).arg(1, *l.hits).arg(2, static_cast<std::uint32_t>(n));
    set_scene_args(shade, 3);
    shade.arg(kSceneArgs + 3, *l.shadow_off)
        .arg(kSceneArgs + 4, *l.spawn_off)
        .arg(kSceneArgs + 5, *l.shadows)
        .arg(kSceneArgs + 6, *l.spawned)
        .arg(kSceneArgs + 7, *l.immediate)
        .arg(kSceneArgs + 8, l.super)
        .arg(kSceneArgs + 9, l.super_off ? *l.super_off : *l.shadow_off)
        .arg(kSceneArgs + 10, l.super_data ? *l.super_data : *l.shadow_off)
        .arg(kSceneArgs + 11, l.cap_shadow)
        .arg(kSceneArgs + 12, l.cap_spawn)
        .arg(kSceneArgs + 13, l.nshadow ? *l.nshadow : *l.shadow_off)
        .arg(kSceneArgs + 14, l.nspawn ? *l.nspawn : *l.spawn_off);
    ctx.run(shade, n);
  }

  // rc_shade in count mode (caps of 0): each ray's shadow and child counts only; with super
  // offsets and data, those of its -as pass. Nothing else is written.
  void run_count(device::Buffer& rays, device::Buffer& hits, device::Buffer& nshadow,
                 device::Buffer& nspawn, std::size_t n, device::Buffer* super_off = nullptr,
                 device::Buffer* super_data = nullptr) {
    ShadeLaunch l{&rays, &hits, &nshadow, &nspawn, &nshadow, &nshadow, &nshadow};
    l.super = super_off ? 1 : 0;
    l.super_off = super_off;
    l.super_data = super_data;
    l.cap_shadow = l.cap_spawn = 0;
    l.nshadow = &nshadow;
    l.nspawn = &nspawn;
    run_shade(l, n);
  }

  // The device record of a geometry answer; a miss may still hit a distant source.
  rc_hit to_device(const geometry::Ray& ray, const std::optional<geometry::Hit>& h) const {
    rc_hit out{};
    out.surface = RC_NONE;
    out.source = RC_NONE;
    if (h) {
      out.pos = f4(h->point[0] - centre[0], h->point[1] - centre[1], h->point[2] - centre[2], h->t);
      out.nrm = f4(h->normal[0], h->normal[1], h->normal[2], 0);
      out.uv = f4(h->u, h->v, 0, 0);
      out.surface = cs.surface_of(*h);
      out.prim = h->prim;
      out.front = h->front ? 1 : 0;
    } else {
      out.pos = f4(0, 0, 0, -1);
      out.front = 1;
      out.surface = distant_surface(cs, geom, ray.dir);
    }
    if (out.surface < cs.surfaces.size()) out.source = cs.surfaces[out.surface].source;
    return out;
  }

  void render(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results) {
    if (results.size() != rays.size()) throw FatalError("renderer: result span size mismatch");
    if (building) {
      build_render(rays, results, {});
      return;
    }
    run(rays, results);
  }

  // Renders in batches of at most -wave_size primaries; without the cache, fewer where each
  // primary's rays multiply (-aa 0 -ad 1024 -ab 2 gives about 5,000 rays a sensor): a batch
  // is sized from the largest generation of rays per primary seen so far, so no generation
  // outgrows generation_rays() and the queues stay in memory that is reused from batch to
  // batch. Primaries are independent, so the batching changes no result. With the cache,
  // lookups keep generations small, and a cache pass keeps whole waves (the order of its
  // misses chooses the records; sized like this, the integrating sphere's -ab 8 build ran in
  // many tiny batches and took a quarter longer).
  std::size_t peak_generation = 0; // the largest generation of the last batch
  double rays_per_primary = 0;     // the most seen in a batch's largest generation
  std::size_t generation_rays() const {
    if (const char* e = std::getenv("RADCL_GENERATION_RAYS"); e && *e)
      return std::max<std::size_t>(1, std::strtoull(e, nullptr, 10));
    return ctx.zero_copy() ? std::size_t{1} << 19 : std::size_t{1} << 22;
  }
  void run(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results) {
    const std::size_t wave = std::max<std::size_t>(1, settings.wave_size);
    const std::size_t cap = generation_rays();
    for (std::size_t first = 0; first < rays.size();) {
      std::size_t n = std::min(wave, rays.size() - first);
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

  // Result slot of a primary id in the current batch: ids are input indices unless the
  // caller gave its own (then they are looked up).
  std::size_t batch_first = 0;
  IdSlots id_slot;
  std::vector<Vec3d>* mirrored = nullptr; // the batch's mirrored sums, per primary
  std::span<PrimaryResult> results;       // the batch's results
  std::vector<std::uint32_t> root_depth;  // reflection depth of the batch's first rays
  std::size_t slot(std::uint32_t primary) const {
    return id_slot.empty() ? primary - batch_first : id_slot.at(primary);
  }

  // Vectors lent to a batch and given back, emptied but with their room, when it ends (a
  // batch inside another, as a record's hemisphere inside a cache pass, takes others).
  template <class T> struct Spare {
    std::vector<std::vector<T>>& pool;
    std::vector<T> v;
    explicit Spare(std::vector<std::vector<T>>& p) : pool(p) {
      if (!pool.empty()) {
        v = std::move(pool.back());
        pool.pop_back();
      }
    }
    ~Spare() {
      v.clear();
      pool.push_back(std::move(v));
    }
  };
  std::vector<std::vector<rc_ray>> spare_rays;
  std::vector<std::vector<rc_hit>> spare_hits;

  void render_batch(std::span<const PrimaryRay> prim, std::span<PrimaryResult> res,
                    std::size_t first_index) {
    Timed timed(prof, Phase::Batch);
    batch_first = first_index;
    id_slot.clear();
    if (std::any_of(prim.begin(), prim.end(),
                    [](const PrimaryRay& r) { return r.id != RC_NONE; })) {
      std::vector<std::uint32_t> ids(prim.size());
      for (std::size_t k = 0; k < prim.size(); ++k)
        ids[k] = prim[k].id != RC_NONE ? prim[k].id : static_cast<std::uint32_t>(first_index + k);
      id_slot.assign(ids);
    }
    // The generation queues come from a pool that outlives the batch: growing fresh ones to
    // millions of rays in every batch paged in (and cleared) new memory each time.
    Spare<rc_ray> queue_hold(spare_rays), next_hold(spare_rays);
    Spare<rc_hit> hits_hold(spare_hits);
    std::vector<rc_ray>& queue = queue_hold.v;
    std::vector<rc_hit>& hits = hits_hold.v;
    queue.resize(prim.size());
    leak_lists.assign(1, 0u);
    leak_uploaded = 0;
    std::vector<Vec3d> sums(prim.size(), Vec3d{0, 0, 0});
    std::vector<Vec3d> mirror_sums(prim.size(), Vec3d{0, 0, 0});
    mirrored = &mirror_sums;
    results = res;
    root_depth.assign(prim.size(), 0);
    if (tree) tally.reset(prim.size(), settings.seed, settings.trace != RenderSettings::Trace::Off);
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
      r.dist0 = 0;           // patterns' T counts from the primary's start
      if (!starts.empty()) { // a hemisphere sample of a record being made
        const RayStart& st = starts[first_index + i];
        r.flags = st.flags;
        r.depth = st.depth;
        r.ambient_depth = st.ambient_depth;
        r.coef.w = st.weight;
        r.dist0 = st.dist0;
        r.org.w = RC_TMIN_OFF; // its origin is already beside the surface
      }
      root_depth[i] = r.depth;
    });
    if (settings.irradiance_I && nesting == 0) {
      // The measurement point is a diffuse meter facing the given direction, meter_offset()
      // along it (where Radiance's reversed primary ray meets it).
      hits.resize(prim.size());
      for (std::size_t i = 0; i < prim.size(); ++i) {
        Vec3d d = unit(prim[i].dir);
        const Vec3d p = meter_point(geom, prim[i].org, d);
        rc_hit& h = hits[i];
        h = rc_hit{};
        h.pos = f4(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2], 1e-5);
        h.nrm = f4(d[0], d[1], d[2], 0);
        h.surface = RC_SURF_IRRADIANCE;
        h.source = RC_NONE;
        h.front = 1;
        queue[i].dir = f4(-d[0], -d[1], -d[2], INFINITY);
      }
    }

    timed.stop();
    // Each generation of rays goes through in chunks: trace, leak tests and shading of one
    // chunk before the next, so the per-ray scratch (Embree's answers, slots, shadow requests)
    // is bounded by the chunk and reused, not freshly mapped and cleared for a generation of
    // millions. Chunks keep queue order, so sums and records do not depend on their size.
    const std::vector<rc_hit> meters =
        (settings.irradiance_I && nesting == 0) ? std::move(hits) : std::vector<rc_hit>{};
    bool first_wave = true;
    std::vector<rc_ray>& next = next_hold.v;
    const std::size_t chunk = chunk_rays();
    while (!queue.empty()) {
      const std::size_t n = queue.size();
      peak_generation = std::max(peak_generation, n);
      for (std::size_t a = 0; a < n; a += chunk) {
        const std::size_t b = std::min(n, a + chunk);
        const std::span<const rc_ray> part(queue.data() + a, b - a);
        if (first_wave && !meters.empty())
          hits.assign(meters.begin() + static_cast<std::ptrdiff_t>(a),
                      meters.begin() + static_cast<std::ptrdiff_t>(b));
        else
          trace(part, hits, res, first_wave);
        test_leaks(part, hits);
        // Shade in slices whose slots fit a modest allocation (a slice keeps queue order, so
        // sums stay in order).
        std::size_t limit = std::size_t{1} << 26;
        if (const char* e = std::getenv("RADCL_WAVE_BYTES")) limit = std::strtoull(e, nullptr, 10);
        size_slots(part, hits);
        for (std::size_t sa = 0; sa < part.size();) {
          std::size_t per_ray = cap_shadow * sizeof(rc_shadow) + cap_spawn * sizeof(rc_ray);
          std::size_t sb = std::min(part.size(), sa + std::max<std::size_t>(256, limit / per_ray));
          shade_slice(part.data() + sa, hits.data() + sa, sb - sa, sums, next);
          sa = sb;
        }
      }
      first_wave = false;
      if (tree)
        for (auto req = tally.take_requests(); !req.empty(); req = tally.take_requests())
          supersample(req, next);
      std::swap(queue, next);
      next.clear();
    }
    timed.start(Phase::Batch);
    const auto finish = [&](std::size_t i) {
      res[i].value = tree ? tally.sum(i) : sums[i];
      res[i].mirrored = tree ? tally.mirrored(i) : mirror_sums[i];
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

  // Trace mode: the primary's tree as rtrace reports it (-I meters are not traced themselves,
  // as Radiance's rayirrad does not call the trace hook).
  std::vector<TracedRay> traced(std::size_t primary) const {
    std::vector<TracedRay> out;
    for (const auto& [t, depth] : tally.traced(primary)) {
      if (depth == 0 && settings.irradiance_I) continue;
      TracedRay r;
      r.depth = depth;
      if (t->is_shadow) {
        const rc_shadow& s = t->shadow.request;
        r.shadow = true;
        r.org = {s.org.x + centre[0], s.org.y + centre[1], s.org.z + centre[2]};
        r.dir = {s.dir.x, s.dir.y, s.dir.z};
        // The source's radiance as the shadow ray brought it back, and the factor that made
        // its contribution.
        const rc_source& src = cs.sources.sources[s.source];
        const float e[3] = {src.emit.x, src.emit.y, src.emit.z};
        const float c0[3] = {s.contrib.x, s.contrib.y, s.contrib.z};
        const float c1[3] = {t->shadow.arrived.x, t->shadow.arrived.y, t->shadow.arrived.z};
        for (int i = 0; i < 3; ++i) {
          double pass = !t->shadow.blocked && c0[i] > 0 ? c1[i] / c0[i] : 0.0;
          r.value[i] = e[i] * pass;
          r.coef[i] = e[i] > 0 ? c0[i] / e[i] : 0.0;
          r.contribution[i] = t->shadow.blocked ? 0.0 : c1[i];
        }
        r.weight = 1;
        if (!t->shadow.blocked) { // it met its source
          if (src.kind == RC_SRC_DISTANT) {
            r.surface = distant_surface(cs, geom, r.dir);
          } else {
            r.surface = src.surface;
            r.hit = true;
            r.t = s.dir.w;
            for (int i = 0; i < 3; ++i)
              r.point[i] = r.org[i] + r.t * r.dir[i];
          }
        }
        if (!r.hit) r.point = r.org;
        out.push_back(r);
        continue;
      }
      const rc_ray& q = t->ray;
      const rc_hit& h = t->hit;
      r.org = {q.org.x + centre[0], q.org.y + centre[1], q.org.z + centre[2]};
      r.dir = {q.dir.x, q.dir.y, q.dir.z};
      r.weight = q.coef.w;
      const Vec3d& sum = tally.node_sum(t->node);
      const float c[3] = {q.coef.x, q.coef.y, q.coef.z};
      for (int i = 0; i < 3; ++i) {
        r.coef[i] = c[i];
        r.contribution[i] = sum[i];
        r.value[i] = c[i] > 0 ? sum[i] / c[i] : 0.0;
      }
      r.surface = h.surface < cs.surfaces.size() ? h.surface : RC_NONE;
      r.point = r.org;
      if (h.surface != RC_NONE && h.pos.w >= 0) {
        r.hit = true;
        r.t = h.pos.w;
        r.point = {h.pos.x + centre[0], h.pos.y + centre[1], h.pos.z + centre[2]};
        r.normal = {h.nrm.x, h.nrm.y, h.nrm.z};
      }
      out.push_back(r);
    }
    return out;
  }

  // The second pass of -as: the hemispheres' rays are shaded again and write only the
  // super-samples the tally tree asked for.
  void supersample(const std::vector<TallyTree::SuperRequest>& req, std::vector<rc_ray>& next) {
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
    append_children(children, next);
  }

  // Slot sizes for a wave: the counts of an even spread of its rays (at most 512 of them,
  // counted by rc_shade's count mode), enough room for about 98% of them.
  // A small wave keeps the last sizes: counting would cost it a launch and a second shading of
  // each ray, more than re-shading its few rays that do not fit.
  void size_slots(std::span<const rc_ray> queue, const std::vector<rc_hit>& hits) {
    if (queue.size() <= kUncountedWave) return;
    Timed timed(prof, Phase::Slots);
    std::size_t n = queue.size(), stride = std::max<std::size_t>(1, n / 512);
    std::vector<rc_ray> r;
    std::vector<rc_hit> h;
    for (std::size_t i = stride / 2; i < n; i += stride) {
      r.push_back(queue[i]);
      h.push_back(hits[i]);
    }
    std::size_t m = r.size();
    device::Buffer& brays = scratch(kStepRays, r);
    device::Buffer& bhits = scratch(kStepHits, h);
    device::Buffer& bnshadow = scratch(kNShadow, m * 4);
    device::Buffer& bnspawn = scratch(kNSpawn, m * 4);
    run_count(brays, bhits, bnshadow, bnspawn, m);
    auto quantile = [m](std::vector<std::uint32_t> v) {
      std::size_t k = m * 98 / 100;
      std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
      return std::max<std::uint32_t>(1, v[k]);
    };
    std::vector<std::uint32_t> csh(m), csp(m);
    bnshadow.read_later(csh.data(), m * 4);
    bnspawn.read_later(csp.data(), m * 4);
    ctx.finish();
    cap_shadow = quantile(std::move(csh));
    cap_spawn = quantile(std::move(csp));
  }

  // A wave's children join the next wave; while the cache is built, its record requests (they
  // are not rays) go to `misses` instead, in the same order.
  void append_children(const std::vector<rc_ray>& children, std::vector<rc_ray>& next) {
    if (!collecting) {
      next.insert(next.end(), children.begin(), children.end());
      return;
    }
    for (const rc_ray& r : children)
      ((r.flags & RC_RAY_KIND_MASK) == RC_RAY_AMBMISS ? misses : next).push_back(r);
  }

  // Shades the rays `over` (slice indices) again, their records written into exact room, and
  // puts them in their places in the slice's packed records.
  void reshade(const rc_ray* rays, const rc_hit* hit, const std::vector<std::uint32_t>& over,
               const std::vector<std::uint32_t>& nsh, const std::vector<std::uint32_t>& nsp,
               const std::vector<std::uint32_t>& shadow_off,
               const std::vector<std::uint32_t>& spawn_off, std::vector<rc_shadow>& shadows,
               std::vector<rc_ray>& children) {
    std::size_t m = over.size();
    std::vector<rc_ray> r(m);
    std::vector<rc_hit> h(m);
    std::vector<std::uint32_t> soff(m), poff(m);
    for (std::size_t k = 0; k < m; ++k) {
      r[k] = rays[over[k]];
      h[k] = hit[over[k]];
      soff[k] = nsh[over[k]];
      poff[k] = nsp[over[k]];
    }
    std::uint32_t tsh = prefix_sum(soff), tsp = prefix_sum(poff);
    device::Buffer& brays = scratch(kStepRays, r);
    device::Buffer& bhits = scratch(kStepHits, h);
    device::Buffer& bsoff = scratch(kSuperOff, soff);
    device::Buffer& bpoff = scratch(kSuperData, poff);
    device::Buffer& bsh = scratch(kShadows, std::size_t{tsh} * sizeof(rc_shadow));
    device::Buffer& bsp = scratch(kSpawned, std::size_t{tsp} * sizeof(rc_ray));
    device::Buffer& bimm = scratch(kTotal, m * sizeof(rc_float4));
    run_shade(ShadeLaunch{&brays, &bhits, &bsoff, &bpoff, &bsh, &bsp, &bimm}, m);
    std::vector<rc_shadow> sh(tsh);
    std::vector<rc_ray> sp(tsp);
    bsh.read_later(sh.data(), sh.size() * sizeof(rc_shadow));
    bsp.read_later(sp.data(), sp.size() * sizeof(rc_ray));
    ctx.finish();
    for (std::size_t k = 0; k < m; ++k) {
      if (!shadows.empty()) // empty: a thrown-away pass
        std::copy_n(sh.data() + soff[k], nsh[over[k]], shadows.data() + shadow_off[over[k]]);
      std::copy_n(sp.data() + poff[k], nsp[over[k]], children.data() + spawn_off[over[k]]);
    }
  }

  // Shades rays [a, b) of the wave: writes their shadow requests and children, tests the
  // shadows, adds each ray's total into its primary's sum, appends the children to `next`.
  // One pass writes every ray's records into fixed slots; rays that did not fit are shaded
  // again into exactly sized room. The records are packed in ray order either way.
  void shade_slice(const rc_ray* rays, const rc_hit* hit, std::size_t n, std::vector<Vec3d>& sums,
                   std::vector<rc_ray>& next) {
    Timed timed(prof, Phase::Shade);
    std::uint32_t un = static_cast<std::uint32_t>(n);
    device::Buffer& brays = scratch(kRays, n * sizeof(rc_ray));
    brays.write(rays, n * sizeof(rc_ray));
    device::Buffer& bhits = scratch(kHits, n * sizeof(rc_hit));
    bhits.write(hit, n * sizeof(rc_hit));
    const std::uint32_t csh = cap_shadow, csp = cap_spawn;
    device::Buffer& bslot_sh = scratch(kShadowSlots, n * csh * sizeof(rc_shadow));
    device::Buffer& bslot_sp = scratch(kSpawnSlots, n * csp * sizeof(rc_ray));
    device::Buffer& bimm = scratch(kImm, n * sizeof(rc_float4));
    device::Buffer& bnshadow = scratch(kNShadow, n * 4);
    device::Buffer& bnspawn = scratch(kNSpawn, n * 4);
    ShadeLaunch l{&brays, &bhits, &bnshadow, &bnspawn, &bslot_sh, &bslot_sp, &bimm};
    l.cap_shadow = csh;
    l.cap_spawn = csp;
    const auto w0 = std::chrono::steady_clock::now();
    run_shade(l, n);
    std::chrono::steady_clock::time_point w1;
    if (prof.waves()) {
      ctx.finish();
      w1 = std::chrono::steady_clock::now();
    }
    // The counts and this slice's slots (not the pool buffers whole, both ways), read in one
    // wait: a small wave's time is mostly the latency of its transfers.
    std::vector<std::uint32_t> shadow_off(n), spawn_off(n);
    bnshadow.read_later(shadow_off.data(), n * 4);
    bnspawn.read_later(spawn_off.data(), n * 4);
    const auto* ssh = throwaway ? nullptr
                                : static_cast<const rc_shadow*>(
                                      bslot_sh.peek_later(n * csh * sizeof(rc_shadow), peek_sh));
    const auto* ssp =
        static_cast<const rc_ray*>(bslot_sp.peek_later(n * csp * sizeof(rc_ray), peek_sp));
    ctx.finish();
    if (prof.waves()) {
      const auto w2 = std::chrono::steady_clock::now();
      prof.add_wave(n, std::chrono::duration<double>(w1 - w0).count(),
                    std::chrono::duration<double>(w2 - w1).count());
    }
    std::vector<std::uint32_t> over;
    for (std::size_t i = 0; i < n; ++i)
      if (shadow_off[i] & 0x80000000u) {
        shadow_off[i] &= 0x7FFFFFFFu;
        over.push_back(static_cast<std::uint32_t>(i));
      }
    std::vector<std::uint32_t> nsh = shadow_off, nsp = spawn_off;
    std::uint32_t nshadow = prefix_sum(shadow_off), nspawn = prefix_sum(spawn_off);
    // A thrown-away pass wants only the children (they may miss too).
    std::vector<rc_shadow> shadows(throwaway ? 0 : nshadow);
    std::vector<rc_ray> children(nspawn);
    {
      std::vector<char> later(n, 0); // shaded again below
      for (std::uint32_t i : over)
        later[i] = 1;
      for_rows(n, [&](std::size_t i) {
        if (later[i]) return;
        if (ssh) std::copy_n(ssh + i * csh, nsh[i], shadows.data() + shadow_off[i]);
        std::copy_n(ssp + i * csp, nsp[i], children.data() + spawn_off[i]);
      });
    }
    if (!over.empty()) reshade(rays, hit, over, nsh, nsp, shadow_off, spawn_off, shadows, children);
    if (throwaway) {
      append_children(children, next);
      return;
    }
    device::Buffer& bsoff = scratch(kShadowOff, shadow_off);

    std::vector<rc_shadow> requested;
    if (settings.trace == RenderSettings::Trace::RaysAndShadows) requested = shadows;
    timed.stop();
    std::vector<std::uint8_t> blocked = trace_shadows(shadows);
    timed.start(Phase::Accumulate);
    // rc_accumulate's view of a request: its contribution, w < 0 for a traced ray, else the
    // -dt estimate's count of tested requests before it.
    std::vector<rc_float4> contrib(nshadow);
    for_rows(nshadow, [&](std::size_t k) {
      const rc_shadow& q = shadows[k];
      contrib[k] = q.contrib;
      contrib[k].w = q.source != RC_NONE ? -1.0f : static_cast<float>(q.pad0);
    });
    device::Buffer& bcontrib = scratch(kShadows, contrib);
    device::Buffer& bblocked = scratch(kBlocked, blocked);
    device::Buffer& btotal = scratch(kTotal, n * sizeof(rc_float4));
    accumulate.arg(0, bimm)
        .arg(1, bsoff)
        .arg(2, bcontrib)
        .arg(3, bblocked)
        .arg(4, un)
        .arg(5, nshadow)
        .arg(6, btotal);
    ctx.run(accumulate, n);
    std::vector<rc_float4> total = btotal.to_vector<rc_float4>(n);
    if (tree) {
      std::vector<TallyTree::TracedShadow> ts;
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t end = i + 1 < n ? spawn_off[i + 1] : nspawn;
        ts.clear();
        if (!requested.empty()) {
          std::size_t send = i + 1 < n ? shadow_off[i + 1] : nshadow;
          for (std::size_t k = shadow_off[i]; k < send; ++k)
            if (requested[k].source != RC_NONE) // not a -dt estimate
              ts.push_back({requested[k], shadows[k].contrib, blocked[k] != 0});
        }
        tally.shaded(rays[i], hit[i], total[i], children.data() + spawn_off[i], end - spawn_off[i],
                     ts.data(), ts.size());
      }
      append_children(children, next);
      return;
    }
    for (std::size_t i = 0; i < n; ++i) {
      Vec3d& s = sums[rays[i].tally];
      s[0] += total[i].x;
      s[1] += total[i].y;
      s[2] += total[i].z;
      if (rays[i].flags & RC_RAY_MIRRORED) {
        Vec3d& m = (*mirrored)[slot(rays[i].primary)];
        m[0] += total[i].x;
        m[1] += total[i].y;
        m[2] += total[i].z;
      }
    }
    append_children(children, next);
  }

  // Embree over the wave; depth-0 hits also fill the primaries' geometric results.
  // Radiance's leak test for the cache records a wave's lookups may use (ambient/leaks.h):
  // per hit on a surface that may look the cache up, the corral-marked records the kernel could
  // accept there are tested by a short ray; the blocked ones are listed for the kernel.
  void test_leaks(std::span<const rc_ray> queue, std::vector<rc_hit>& hits) {
    if (!leak_tester.active()) return;
    Timed timed(prof, Phase::Leaks);
    const std::size_t n = queue.size();
    const double eps = ray_eps;
    auto segment_blocked = [&](const std::array<double, 3>& o, const std::array<double, 3>& d,
                               double tmax, const std::array<double, 3>& n) {
      // From beside the surface, as the kernels' rays leave it (rc_leave).
      const double lv = leave_dist(o[0], o[1], o[2]);
      Vec3d org = {o[0] + centre[0] + lv * n[0], o[1] + centre[1] + lv * n[1],
                   o[2] + centre[2] + lv * n[2]};
      const Vec3d dir = {d[0], d[1], d[2]};
      double t0 = RC_TMIN_OFF;
      for (int k = 0; k < 64; ++k) { // void surfaces are passed, as Radiance passes them
        std::optional<geometry::Hit> h = geom.intersect(org, dir, t0, tmax);
        if (!h) return false;
        const std::uint32_t s = cs.surface_of(*h);
        if (s < cs.surfaces.size() && cs.surfaces[s].material != RC_NONE) return true;
        t0 = h->t + eps;
      }
      return true;
    };
    constexpr std::size_t kGrain = 256;
    const std::size_t nchunks = (n + kGrain - 1) / kGrain;
    std::vector<std::vector<std::uint32_t>> lists(nchunks);
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> at(nchunks);
    std::vector<std::size_t> traced(nchunks, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nchunks), [&](const auto& range) {
      std::vector<std::uint32_t> found;
      for (std::size_t c = range.begin(); c != range.end(); ++c)
        for (std::size_t i = c * kGrain; i < std::min(n, (c + 1) * kGrain); ++i) {
          const rc_ray& r = queue[i];
          const rc_hit& h = hits[i];
          if (static_cast<int>(r.ambient_depth) >= settings.ab) continue;
          if (h.surface != RC_SURF_IRRADIANCE) {
            if (h.surface >= cs.surfaces.size() || h.pos.w < 0) continue;
            const rc_surface& sf = cs.surfaces[h.surface];
            if (sf.material == RC_NONE || sf.source != RC_NONE || (sf.flags & RC_SURFF_NO_AMBIENT))
              continue;
          }
          LeakLookup q;
          q.point = {h.pos.x, h.pos.y, h.pos.z};
          if (h.surface == RC_SURF_IRRADIANCE) {
            q.exact_normal = true;
          } else {
            const rc_material& m = cs.materials[cs.surfaces[h.surface].material];
            q.exact_normal =
                m.npatterns == 0 && !scene::is_mixture(static_cast<scene::ObjectType>(m.type));
          }
          // The normal facing the ray (a -I meter faces its given direction).
          const double f = h.surface == RC_SURF_IRRADIANCE || h.front ? 1.0 : -1.0;
          q.normal = {f * h.nrm.x, f * h.nrm.y, f * h.nrm.z};
          q.level = r.ambient_depth;
          q.weight = r.coef.w;
          found.clear();
          traced[c] += leak_tester.find(q, segment_blocked, found);
          if (found.empty()) continue;
          at[c].push_back(
              {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(lists[c].size())});
          lists[c].push_back(static_cast<std::uint32_t>(found.size()));
          lists[c].insert(lists[c].end(), found.begin(), found.end());
        }
    });
    for (std::size_t c = 0; c < nchunks; ++c) {
      stats.leak_tests += traced[c];
      const std::uint32_t base_off = static_cast<std::uint32_t>(leak_lists.size());
      for (const auto& [i, off] : at[c]) {
        const std::uint32_t code = base_off + off + 1; // 0: no list
        std::memcpy(&hits[i].nrm.w, &code, sizeof code);
        ++stats.leaks;
      }
      leak_lists.insert(leak_lists.end(), lists[c].begin(), lists[c].end());
    }
    if (leak_lists.size() != leak_uploaded) {
      amb_blocked.update(ctx, leak_lists, leak_uploaded);
      leak_uploaded = leak_lists.size();
    }
  }

  // Embree's answers for a chunk (where they are read), kept from chunk to chunk.
  std::vector<std::optional<geometry::Hit>> trace_answers;
  void trace(std::span<const rc_ray> queue, std::vector<rc_hit>& hits, std::span<PrimaryResult> res,
             bool primaries) {
    Timed timed(prof, Phase::Trace);
    std::size_t n = queue.size();
    // One pass per ray: the query, then its device record. Embree's double answer is kept
    // only where the loops below read it (the primaries, mirror reflections, straight
    // transmissions); the rest would be memory written and never read.
    std::vector<std::optional<geometry::Hit>>& gh = trace_answers;
    gh.resize(n);
    hits.resize(n);
    constexpr std::uint32_t kKept = RC_RAY_MIRRORED | RC_RAY_THROUGH;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const rc_ray& r = queue[i];
        geometry::Ray ray;
        ray.org = {r.org.x + centre[0], r.org.y + centre[1], r.org.z + centre[2]};
        ray.dir = {r.dir.x, r.dir.y, r.dir.z};
        ray.tmin = r.org.w;
        // The kernels send a positive tmin only from an -I meter's point (rc_leave_org).
        ray.free_origin = r.org.w > 0 && !primaries;
        ray.tmax = std::isfinite(r.dir.w) ? r.dir.w : 1e300;
        std::optional<geometry::Hit> h =
            geom.intersect(ray.org, ray.dir, ray.tmin, ray.tmax, ray.free_origin);
        hits[i] = to_device(ray, h);
        if (primaries || (r.flags & kKept)) gh[i] = std::move(h);
      }
    });
    (primaries ? stats.primary : stats.secondary) += n;
    // The first hit's mirror reflection: how far it went, for rtrace's R and l. Measured from
    // the surface point it left (its ray starts just beside it: rc_leave).
    auto dist = [](const Vec3d& a, const Vec3d& b) {
      return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                       (a[2] - b[2]) * (a[2] - b[2]));
    };
    for (std::size_t i = 0; i < n; ++i)
      if ((queue[i].flags & RC_RAY_MIRRORED) &&
          (queue[i].flags & RC_RAY_KIND_MASK) == RC_RAY_REFLECTED &&
          queue[i].depth == root_depth[slot(queue[i].primary)] + 1) {
        PrimaryResult& pr = results[slot(queue[i].primary)];
        pr.mirror_t = (queue[i].flags & RC_RAY_TILTED) ? 0.0
                      : gh[i]                          ? dist(gh[i]->point, pr.point)
                                                       : 1e10;
      }
    // The straight continuation through transmitting surfaces: its lengths add up (X), each
    // from the surface point the last one met.
    for (std::size_t i = 0; i < n; ++i)
      if ((queue[i].flags & RC_RAY_THROUGH) &&
          (queue[i].flags & RC_RAY_KIND_MASK) == RC_RAY_TRANSMITTED) {
        PrimaryResult& pr = results[slot(queue[i].primary)];
        const Vec3d& from = pr.through_t < 0 ? pr.point : pr.through_at;
        pr.through_t = std::max(pr.through_t, 0.0) + (gh[i] ? dist(gh[i]->point, from) : 1e10);
        if (gh[i]) pr.through_at = gh[i]->point;
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
      r.surface = hits[i].surface;
    }
  }

  // Shadow rays in steps: Embree finds each one's next hit, the kernel decides whether it
  // reached its source, is blocked, or continues through a transmitting surface with its
  // contribution reduced (then it is traced again from there). Each ray keeps its slot, so the
  // result does not depend on the order of work. Survivors' final contributions are written
  // back into `shadows`; the return value marks the blocked ones.
  // In chunks, so the host's per-ray scratch (Embree answers above all) stays in memory that is
  // reused rather than freshly mapped and cleared.
  std::vector<std::uint8_t> trace_shadows(std::vector<rc_shadow>& shadows) {
    constexpr std::size_t kChunk = 1u << 18;
    std::vector<std::uint8_t> blocked(shadows.size(), 1);
    for (std::size_t a = 0; a < shadows.size(); a += kChunk)
      trace_shadow_chunk(shadows.data() + a, std::min(kChunk, shadows.size() - a),
                         blocked.data() + a);
    return blocked;
  }

  // Rays [shadows, shadows + n): contributions written back in place, blocked[i] cleared for
  // each one that reached its source.
  std::vector<rc_hit> shadow_hits; // a step's answers, kept from step to step
  void trace_shadow_chunk(rc_shadow* shadows, std::size_t n, std::uint8_t* blocked) {
    std::vector<std::uint32_t> slot;
    std::vector<rc_shadow> cur;
    // Estimates and empty slots of the -dt selection (source RC_NONE) are not rays.
    for (std::size_t i = 0; i < n; ++i)
      if (shadows[i].source != RC_NONE) {
        slot.push_back(static_cast<std::uint32_t>(i));
        cur.push_back(shadows[i]);
      }
    std::vector<std::uint32_t> state(cur.size(), 0);
    // Radiance traces shadow rays on until their weight vanishes; a glass stack that needs
    // more steps than this contributes nothing measurable.
    constexpr int kMaxSteps = 64;
    for (int step = 0; step < kMaxSteps && !cur.empty(); ++step) {
      std::size_t m = cur.size();
      Timed timed(prof, Phase::ShadowTrace);
      // One pass per ray: the query and its device record.
      std::vector<rc_hit>& hits = shadow_hits;
      hits.resize(m);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 256), [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const rc_shadow& s = cur[i];
          const rc_source& src = cs.sources.sources[s.source];
          geometry::Ray ray;
          ray.org = {s.org.x + centre[0], s.org.y + centre[1], s.org.z + centre[2]};
          ray.dir = {s.dir.x, s.dir.y, s.dir.z};
          ray.tmin = s.org.w;
          ray.free_origin = s.org.w > 0; // from an -I meter's point (rc_leave_org)
          ray.tmax = src.kind == RC_SRC_DISTANT || !std::isfinite(s.dir.w) ? 1e300
                                                                           : s.dir.w * 1.001 + 1e-3;
          hits[i] =
              to_device(ray, geom.intersect(ray.org, ray.dir, ray.tmin, ray.tmax, ray.free_origin));
        }
      });
      stats.shadow += m;
      timed.start(Phase::ShadowStep);

      device::Buffer& bcur = scratch(kStepRays, cur);
      device::Buffer& bhits = scratch(kStepHits, hits);
      device::Buffer& bstate = scratch(kStepState, state);
      std::uint32_t um = static_cast<std::uint32_t>(m);
      shadow_step.arg(0, bcur).arg(1, bhits).arg(2, bstate).arg(3, um);
      set_scene_args(shadow_step, 4);
      ctx.run(shadow_step, m);
      bcur.read_later(cur.data(), m * sizeof(rc_shadow)); // into place: no fresh, zeroed vectors
      bstate.read_later(state.data(), m * sizeof(std::uint32_t));
      ctx.finish();

      std::size_t k = 0;
      for (std::size_t i = 0; i < m; ++i) {
        std::uint32_t status = state[i] & 3u;
        if (status == 1u) { // reached its source
          shadows[slot[i]].contrib = cur[i].contrib;
          blocked[slot[i]] = 0;
        } else if (status == 2u) { // goes on
          cur[k] = cur[i];
          state[k] = state[i];
          slot[k] = slot[i];
          ++k;
        }
      }
      cur.resize(k);
      state.resize(k);
      slot.resize(k);
    }
  }
};

Renderer::Renderer(const scene::LoadedScene& scene, const RenderSettings& settings,
                   device::Context& ctx)
    : impl_(std::make_unique<Impl>(scene, settings, ctx)) {}
Renderer::~Renderer() = default;
void Renderer::render(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results) {
  impl_->render(rays, results);
}
bool Renderer::builds_cache() const {
  return impl_->building;
}
std::vector<ambient::AmbientRecord> Renderer::take_new_records() {
  return std::exchange(impl_->made, {});
}
void Renderer::add_records(std::span<const ambient::AmbientRecord> records) {
  if (records.empty()) return;
  impl_->cache_records.insert(impl_->cache_records.end(), records.begin(), records.end());
  for (const ambient::AmbientRecord& a : records)
    impl_->cache_local.push_back(impl_->local_record(a));
  impl_->upload_cache();
}
const CompiledScene& Renderer::compiled() const {
  return impl_->cs;
}
const RenderStats& Renderer::stats() const {
  return impl_->stats;
}
const geometry::SceneGeometry& Renderer::geometry() const {
  return impl_->geom;
}

} // namespace radcl::render
