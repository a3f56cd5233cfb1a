// The renderer's wave pipeline: its state, and the stages that share it. Each stage lives in a
// file of its own:
//   wave_loop.cpp          the driver: batches of primaries, generations of rays, chunks
//   intersect_closest.cpp  Embree's nearest hits for a chunk, as the kernels' records
//   leak_test.cpp          Radiance's leak test for the cache records a chunk may use
//   shade_slice.cpp        a slice of a chunk shaded in stages: inputs, rc_shade, records
//                          placed, shadow rays, rc_accumulate (slice_transfer.h: how its
//                          data crosses, shared or discrete memory); shade_surface.cpp the
//                          kernels' launches
//   shadow_tracer.cpp      shadow rays stepped through Embree and rc_shadow_step (its own
//                          state: shadow_tracer.h)
//   cache_passes.cpp       the irradiance cache's build passes and their uploads
//   cache_hemispheres.cpp  the hemispheres of new records and their -as super-samples
//   trace_tree.cpp         -tr/-trs trees as rtrace reports them
//   renderer.cpp           set-up, light sources and the public interface
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include "cache_forest.h"
#include "generation_copy.h"
#include "radcl/ambient/cache.h"
#include "radcl/ambient/leaks.h"
#include "radcl/ambient/record_maker.h"
#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device/growing_buffer.h"
#include "radcl/device/program.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/compile/compiled_scene.h"
#include "radcl/render/pipeline/id_slots.h"
#include "radcl/render/pipeline/phase_profile.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/render/pipeline/tally_tree.h"
#include "scratch_pool.h"
#include "shade_slice.h"
#include "shadow_tracer.h"
#include "slice_transfer.h"

namespace radcl::render {

struct Renderer::Impl {
  using Timed = PhaseProfile::Scope;

  // ---- The scene on the device (renderer.cpp) ----
  const scene::LoadedScene& scene;
  RenderSettings settings;
  device::Context& ctx;
  geometry::SceneGeometry geom;
  CompiledScene cs;
  PhaseProfile prof{
      settings.tuning.profile}; // before the program: its lifetime includes building it
  device::Program program;
  device::Kernel shade, accumulate, shadow_step, pack, shadow_view, shadow_view_counted, offsets;
  device::Kernel accumulate_contrib; // rcontrib only
  device::Buffer surfaces, materials, args, sources, verts, mirror_surfaces, params, patterns;
  device::GrowingBuffer amb_records, amb_nodes, amb_blocked;
  Vec3d centre;
  RenderStats stats;
  rc_params base{};   // the uploaded parameters, amb.w aside
  double ray_eps = 0; // the least distance rays leave surfaces by (spec.z)

  Impl(const scene::LoadedScene& s, const RenderSettings& st, device::Context& c);
  ~Impl();
  void render(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results);
  void upload_sources();
  // The virtual-source pretest's shadow rays, against the sources made so far (`so` is
  // cs.sources while it grows; trace_shadows reads it there).
  std::vector<float> pretest(const CompiledSources& so, const std::vector<rc_shadow>& rays);
  // How far off a surface a ray leaving point p (re-centred) starts, as the kernels' rc_leave:
  // never less than p's float coordinates resolve.
  double leave_dist(double x, double y, double z) const {
    return std::max(ray_eps, 8e-7 * std::max({std::fabs(x), std::fabs(y), std::fabs(z)}));
  }

  // ---- The driver (wave_loop.cpp) ----
  // The next chunk's trace, beside the shading, runs in an arena of low priority: the host
  // cores it holds go to the shading thread's own parallel steps (shadow rays, the tally,
  // copies: the path every chunk waits on) whenever those have work, and back to tracing ahead
  // when they have none. Made once: a cache build runs hundreds of batches.
  tbb::task_arena ahead_arena{tbb::task_arena::automatic, 1,
                              settings.tuning.ahead_normal_priority
                                  ? tbb::task_arena::priority::normal
                                  : tbb::task_arena::priority::low};
  // Per-wave device buffers and host queues, kept between waves and batches.
  ScratchPool scratch{ctx};
  std::vector<RayQueue> spare_rays;
  std::vector<HitQueue> spare_hits;
  // The current generation's rays on the device (GPU); batch.generation is its host copy, whose
  // rows shade_slice names by address.
  GenerationCopy gen_copy{ctx, settings.tuning.keep_generations_on_device};
  // Rays of a generation traced and shaded together (tuning.chunk_rays sets it, for tests and
  // tuning): large enough that launches and transfers are a small part of a chunk's time,
  // small enough that its scratch stays in the caches and in reused pages. On a device that
  // shares the host's memory (PoCL) 2^16 was fastest (office, -ab 2 -ad 1024 on 2 cores:
  // 1.96 s, 2.41 s with 2^14, 3.64 s with 2^18 whose scratch is paged in afresh).
  std::size_t chunk_rays() const;
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
  std::size_t generation_rays() const;
  void run(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results);
  // One batch: its primaries, then each generation of their children, in chunks.
  void render_batch(std::span<const PrimaryRay> prim, std::span<PrimaryResult> res,
                    std::size_t first_index);
  // Its steps: each primary's result slot, its first rays in `queue`, the -I meters' hits that
  // stand in for the first generation's trace (none without -I), then every generation.
  void assign_slots(std::span<const PrimaryRay> prim, std::size_t first_index);
  void start_primaries(std::span<const PrimaryRay> prim, std::span<PrimaryResult> res,
                       RayQueue& queue, std::size_t first_index);
  std::vector<rc_hit> meter_hits(std::span<const PrimaryRay> prim, RayQueue& queue) const;
  void trace_generations(RayQueue& queue, RayQueue& next, HitQueue& hits,
                         const std::vector<rc_hit>& meters, std::span<PrimaryResult> res);
  // A wave's children join the next wave; while the cache is built, its record requests (they
  // are not rays) go to `misses` instead, in the same order.
  void append_children(const std::vector<rc_ray>& children, RayQueue& next);
  // The same for children already written to next[first...]: the record requests among them
  // move to `misses`, the rest close up in order.
  void set_misses_aside(RayQueue& next, std::size_t first);
  // The second pass of -as: the hemispheres' rays are shaded again and write only the
  // super-samples the tally tree asked for.
  void supersample(const std::vector<TallyTree::SuperRequest>& req, RayQueue& next);

  // The current batch (render_batch sets it up): where each primary's result goes, its sums
  // and the generation being traced.
  struct Batch {
    std::size_t first = 0; // its first primary's index in the caller's rays
    IdSlots ids;           // the caller's own ids, looked up (empty: ids are indices)
    std::vector<Vec3d> sums, mirrored_sums; // per primary
    std::vector<double> contrib;            // rcontrib: per primary, its bins (rgb)
    std::span<PrimaryResult> results;       // the caller's
    std::vector<std::uint32_t> root_depth;  // reflection depth of its first rays
    std::span<const rc_ray> generation;     // the host's queue being traced
    // A primary's result slot.
    std::size_t slot(std::uint32_t primary) const {
      return ids.empty() ? primary - first : ids.at(primary);
    }
  } batch;
  std::size_t slot(std::uint32_t primary) const { return batch.slot(primary); }
  // -as: hemisphere samples tally per division until the super-samples are decided (and -tr
  // keeps the ray trees there).
  bool tree = false;
  TallyTree tally;

  // ---- Nearest hits (intersect_closest.cpp) ----
  // Embree over a chunk; depth-0 hits also fill the primaries' geometric results.
  void trace(std::span<const rc_ray> queue, HitQueue& hits, std::span<PrimaryResult> res,
             bool primaries);
  // The device record of a geometry answer; a miss may still hit a distant source.
  void to_device(const geometry::Ray& ray, const std::optional<geometry::Hit>& h,
                 rc_hit& out) const;
  // A queued ray as the geometry's query takes it (world origin, tmin, tmax, meter origin).
  geometry::Ray query_ray(const rc_ray& r, bool primary) const;
  void trace_raw(std::span<const rc_ray> queue, bool primaries); // RADCL_PROFILE=raw
  // Embree's answers for a chunk (where they are read), kept from chunk to chunk.
  std::vector<std::optional<geometry::Hit>> trace_answers;
  std::vector<std::uint8_t> trace_kept; // which 256-ray ranges of a traced chunk hold kept rays

  // ---- The leak test (leak_test.cpp) ----
  // Radiance's leak test for the cache records a chunk's lookups may use (ambient/leaks.h):
  // per hit on a surface that may look the cache up, the corral-marked records the kernel could
  // accept there are tested by a short ray; the blocked ones are listed for the kernel.
  void test_leaks(std::span<const rc_ray> queue, HitQueue& hits);
  // The current render_batch's lists of records whose leak test failed, per hit: [count,
  // index...]; a hit names its list in nrm.w (docs/cache-internals.md).
  std::vector<std::uint32_t> leak_lists{0};
  std::size_t leak_uploaded = 0;

  // ---- Shading (shade_surface.cpp) ----
  // Kernel arguments set_scene_args() fills; a kernel's next argument follows them.
  static constexpr unsigned kSceneArgs = 11;
  void set_scene_args(device::Kernel& k, unsigned first);
  // One launch of rc_shade over `n` rays: per ray, its output offsets (or, with caps, where the
  // counts go back), the record buffers, its immediate value, the -as pass's requests (super
  // = 0: none) and the per-ray slot capacities (~0u: exact room at the given offsets).
  struct ShadeLaunch {
    device::Buffer *rays, *hits, *shadow_off, *spawn_off, *shadows, *spawned, *immediate;
    std::uint32_t super = 0;
    device::Buffer *super_off = nullptr, *super_data = nullptr;
    std::uint32_t cap_shadow = ~0u, cap_spawn = ~0u;
    device::Buffer *nshadow = nullptr, *nspawn = nullptr; // counts out (default: the offsets)
    device::Buffer* cells = nullptr;   // slot mode: which rays marked -as hemisphere samples
    device::Buffer* tallies = nullptr; // each ray's tally, where the rays' own are stale
  };
  void run_shade(const ShadeLaunch& l, std::size_t n);
  // rc_shade in count mode (caps of 0): each ray's shadow and child counts only; with super
  // offsets and data, those of its -as pass. Nothing else is written.
  void run_count(device::Buffer& rays, device::Buffer& hits, device::Buffer& nshadow,
                 device::Buffer& nspawn, std::size_t n, device::Buffer* super_off = nullptr,
                 device::Buffer* super_data = nullptr);
  // Room per ray in the shading pass's slots, set per chunk by size_slots (any value gives the
  // same records; a good one makes re-shading rare and keeps the slots small).
  std::uint32_t cap_shadow = 16, cap_spawn = 2;
  static constexpr std::size_t kUncountedWave = 2048;
  // Slices up to this many rays sum their shadow rays speculatively with each step (a GPU).
  static constexpr std::size_t kSumAlongRays = std::size_t{1} << 16;
  // Slices whose slots' children and shadow views fit this are packed on the device before
  // the host reads their counts (rc_offsets), in one work-group of kOffsetsGroup items.
  static constexpr std::size_t kFusedBytes = std::size_t{1} << 20;
  static constexpr std::size_t kOffsetsGroup = 256; // RC_OFFSETS_GROUP in shade.cl
  // rc_pack over a slice's slots into the packed places at the given offsets.
  void run_pack(device::Buffer& slot_sh, device::Buffer& slot_sp, device::Buffer& nshadow,
                device::Buffer& nspawn, device::Buffer& shadow_off, device::Buffer& spawn_off,
                std::size_t n, bool with_spawn, device::Buffer& shadows, device::Buffer& spawned);
  // The shadow views read with the children and the sums with the shadow steps, in one wait
  // each (tuning.fewer_waits off: each in a wait of its own, to measure what they save).
  const bool fewer_waits = settings.tuning.fewer_waits;
  // On a GPU a slice's children are read back while the host traces its shadow rays
  // (tuning.children_later off: in the same wait as the shadow views, before the tracing).
  const bool children_later_on = settings.tuning.children_later;
  std::vector<char> peek_sh, peek_sp; // host copies of the slots where the device is not the host
  // Slot sizes for a chunk: the counts of an even spread of its rays (at most 512 of them,
  // counted by rc_shade's count mode), enough room for about 98% of them.
  // A small chunk keeps the last sizes: counting would cost it a launch and a second shading of
  // each ray, more than re-shading its few rays that do not fit.
  void size_slots(std::span<const rc_ray> queue, const HitQueue& hits);
  // Shades rays [rays, rays + n): writes their shadow requests and children, tests the
  // shadows, adds each ray's total into its primary's sum, appends the children to `next`.
  // One pass writes every ray's records into fixed slots; rays that did not fit are shaded
  // again into exactly sized room. The records are packed in ray order either way.
  void shade_slice(const rc_ray* rays, const rc_hit* hit, std::size_t n, RayQueue& next);
  // Its stages (shade_slice.cpp): rc_shade into the slots and the counts read; the records
  // placed and rays that did not fit shaded again; the shadow rays traced and summed; the
  // totals added to the sums or the tally.
  void launch_slice(ShadeSlice& s);
  void place_slice(ShadeSlice& s, RayQueue& next);
  void finish_slice(ShadeSlice& s, RayQueue& next);
  void add_slice(const ShadeSlice& s);
  // rcontrib: the slice's contributions into its primaries' bins (contrib_slice.cpp).
  void add_slice_contrib(const ShadeSlice& s);
  // How a slice's data crosses between host and device (slice_transfer.h), chosen once.
  const std::unique_ptr<SliceTransfer> transfer = make_slice_transfer(ctx);
  // Shades the rays `over` (slice indices) again, their records written into exact room, and
  // puts them in their places in the slice's packed records.
  void reshade(const rc_ray* rays, const rc_hit* hit, const std::vector<std::uint32_t>& over,
               const std::vector<std::uint32_t>& nsp, const std::vector<std::uint32_t>& shadow_off,
               const std::vector<std::uint32_t>& spawn_off, device::Buffer& shadows,
               rc_ray* children, device::Buffer* into = nullptr, std::size_t base = 0);
  // shade_slice's host-side vectors, kept from slice to slice: fresh ones of this size were
  // paged in and cleared by the kernel every time (8% of a run's CPU time on 2 cores).
  struct ShadeScratch {
    std::vector<std::uint32_t> shadow_off, spawn_off, nsp, over;
    std::vector<char> later;
    std::vector<rc_shadow> shadows, requested;
    std::vector<std::uint8_t> blocked, cells;
    std::vector<std::uint32_t> tallies;
    std::vector<rc_float4> total;
    HostQueue<rc_ray> fused_children; // a fused slice's packed children, read whole
  } shade_scratch;
  std::vector<rc_float4> contrib_requests; // rcontrib: a slice's shadow requests' contributions
  // The -as tally tree fed beside the shading: a slice's tally is a task (in ahead_arena) that
  // runs while the next slice is shaded, one at a time and in slice order, so the sums are
  // those of the serial order. It reads the slice's rays (the generation's queue, unchanged
  // until the generation ends), its hits (the wave loop keeps them from being traced over),
  // and its children in `next` (not moved while it runs); the per-ray vectors it reads are
  // swapped out of shade_scratch into tally_in. Only on a device apart from the host: PoCL's
  // kernels keep every core busy, and there the task only slowed the shading (office, 2,000
  // sensors at -aa 0 -ad 1024 on 2 cores: 2.93 s against 2.77 s). tuning.tally_beside says
  // otherwise; RADCL_PROFILE=waves, which times the tally's steps, feeds it in line.
  struct TallyInputs {
    std::vector<std::uint32_t> spawn_off, nsp;
    std::vector<std::uint8_t> cells;
    std::vector<rc_float4> total;
  } tally_in;
  tbb::task_group tally_task;
  bool tally_pending = false;
  std::span<const rc_hit> tally_hits;                        // what the pending tally reads
  const int tally_beside_env = settings.tuning.tally_beside; // -1: the device decides
  // The slice [rays, rays + n) shaded: its totals, children counts and offsets, and hemisphere
  // marks are those in shade_scratch.
  void feed_tally(const rc_ray* rays, const rc_hit* hit, rc_ray* children, std::size_t n);
  void wait_tally();
  // Whether the pending tally reads hits in `h`'s room.
  bool tally_reads(const HitQueue& h) const;

  // ---- Shadow rays (shadow_tracer.h) ----
  using ShadowView = render::ShadowView;
  ShadowTracer shadow_tracer{*this};

  // ---- The irradiance cache's passes (cache_passes.cpp; docs/cache-internals.md) ----
  // How a primary starts when it is a hemisphere sample of a record being made.
  struct RayStart {
    std::uint32_t flags = RC_RAY_PRIMARY, depth = 0, ambient_depth = 0;
    float weight = 1;
    float dist0 = 0; // the ray tree's length before it: the record's point is its parent's hit
    float cext[3] = {0, 0, 0};               // the medium it starts in (its parent's): extinction,
    std::uint32_t medium = RC_MEDIUM_GLOBAL; // albedo's source,
    float gecc = 0;                          // eccentricity
    std::uint32_t slights = 0;               // and mist sources
  };
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
  std::unique_ptr<ambient::RecordMaker> maker; // the record kernel, built when first needed

  // The records as the lookups and the leak tests read them (cache_forest.h), and the leak
  // tester over the marked ones.
  CacheForest forest;
  ambient::LeakTester leak_tester;
  // The lowest level of any record (INT_MAX: none), counted up to level_seen: a lookup at
  // ambient depth d accepts records of level d or lower only.
  int min_level = std::numeric_limits<int>::max();
  std::size_t level_seen = 0;

  void upload_cache();
  // A record read from a file or shared by another process, re-centred (in double).
  ambient::AmbientRecord local_record(ambient::AmbientRecord a) const {
    for (int i = 0; i < 3; ++i)
      a.pos[i] = static_cast<float>(static_cast<double>(a.pos[i]) - centre[i]);
    return a;
  }
  void set_collect(bool on);

  // Renders `rays` while the cache grows: a pass reports the misses of its primaries, records
  // are made for a well-spread choice of them, and the primaries that missed are shaded again;
  // after kRounds passes what still misses is sampled as with -aa 0. A primary's value is the
  // one of its first pass without a miss, so it is computed as Radiance computes it once the
  // records it needs exist.
  static constexpr int kRounds = 12;
  // One pass of build_render over some primaries. While it lives they start as `st` says and
  // their misses are reported as record requests, unless it is the last pass (which alone keeps
  // the -as tally and samples what still misses); end() restores the renderer's state and says
  // whether the pass's values were thrown away.
  class CachePass {
  public:
    CachePass(Impl& im, std::span<const RayStart> st, bool last);
    ~CachePass();
    CachePass(const CachePass&) = delete;
    CachePass& operator=(const CachePass&) = delete;
    bool end();

  private:
    Impl& im_;
    const bool tree_;
    const std::span<const RayStart> starts_;
    bool ended_ = false;
  };
  bool throwaway = false; // this pass's values are thrown away: no shadow rays, no sums
  void build_render(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results,
                    std::span<const RayStart> st);
  // Whether every ray of a cache-build pass looks records up and none can be accepted: rays at
  // ambient depth d (starts', else 0) below -ab, and no record of level d or lower.
  bool will_all_miss(std::span<const RayStart> st) const;
  // Makes records for a well-spread subset of `miss`: in order, a miss is chosen unless a
  // chosen one of its level, facing within 60 degrees, lies within aa x maxarad / 2^round (not
  // below aa x minarad) of it. Round 0 spaces records by the largest region a record can
  // cover; each later round sees only the points earlier records left uncovered and halves the
  // spacing, so records go where Radiance's sequential order would put them (a miss no record
  // covers) and the cache keeps its -aa/-ar adaptivity.
  void make_records(const std::vector<rc_ray>& miss, int round);

  // ---- New records' hemispheres (cache_hemispheres.cpp) ----
  // Radiance's samp_hemi for each chosen miss (ns x ns stratified cosine-weighted directions,
  // ns = sqrt(-ad x record weight), at least 7), the samples rendered as primaries one
  // ambient level deeper (their own misses make records first), then the record kernel
  // (ambient/record_maker.h) turns each complete hemisphere into a record.
  void sample_hemispheres(const std::vector<const rc_ray*>& chosen);
  // The hemispheres of the chosen misses that can have samples (their weight and depth allow
  // any), each one's samples as primaries and how they start.
  struct NewHemispheres {
    std::vector<rc_amb_hemi> hemis;
    std::vector<PrimaryRay> rays;
    std::vector<RayStart> start;
  };
  NewHemispheres hemisphere_rays(const std::vector<const rc_ray*>& chosen);
  // While it lives, renders are a record's samples, one ambient level deeper.
  struct Nested {
    Impl& im;
    explicit Nested(Impl& i) : im(i) { ++im.nesting; }
    ~Nested() { --im.nesting; }
    Nested(const Nested&) = delete;
    Nested& operator=(const Nested&) = delete;
  };
  // -as for a record (Radiance's ambsupersamp): where the squared brightness differences of a
  // division's neighbours say the hemisphere varies most, more samples of that division are
  // rendered, as many as its share of the budget -as x weight (when that exceeds 8 and every
  // sample of more than 7 x 7 divisions succeeded); a division's value becomes the mean of its
  // samples and its distance the nearest (its point stays the first sample's).
  void supersample_hemispheres(const std::vector<rc_amb_hemi>& hemis,
                               const std::vector<PrimaryRay>& rays,
                               const std::vector<RayStart>& start, std::vector<PrimaryResult>& res,
                               std::vector<double>& nearest);
  // A hemisphere sample's length as Radiance's raydistance(): through glass and other clear
  // transmission the effective length goes on to what lies beyond (the sky seen through a
  // window is far, not at the pane), along the mirror reflection where that carries more than
  // half the value; 1e10 where nothing was met.
  static double sample_length(const PrimaryResult& r);

  // ---- Trace mode (trace_tree.cpp) ----
  // The primary's tree as rtrace reports it (-I meters are not traced themselves, as
  // Radiance's rayirrad does not call the trace hook).
  std::vector<TracedRay> traced(std::size_t primary) const;
};

} // namespace radcl::render
