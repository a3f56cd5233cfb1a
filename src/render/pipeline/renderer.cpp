#include "radcl/render/pipeline/renderer.h"

#include <cstdio>
#include <utility>

#include "pipeline_util.h"
#include "radcl/render/lights/virtual_sources.h"
#include "radcl/util/error.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

namespace {

device::ProgramSource shade_program(const CompiledScene& cs, const RenderSettings& st) {
  device::FeatureSet f = cs.features;
  if (uses_cache(st)) f.define("RADCL_HAS_AMBCACHE");
  // Rays in mist travel in a medium even where no global one is set.
  if (has_medium(st) || cs.features.has(RC_OBJ_MIST)) f.define("RADCL_HAS_MEDIUM");
  if (st.contrib) {
    f.define("RADCL_CONTRIB");
    if (!st.contrib->contributions) f.define("RADCL_CONTRIB_COEF");
  }
  return f.program({"pipeline/shade.cl"});
}

device::Program built(PhaseProfile& prof, device::Context& c, const device::ProgramSource& src) {
  PhaseProfile::Scope t(prof, Phase::Build);
  return device::Program(c, src);
}

} // namespace

Renderer::Impl::~Impl() {
  if (!prof.on()) return;
  prof.print(stderr);
  // The memory the pipeline kept for reuse (paged in once, a cost a short run pays in full).
  std::size_t dev = 0, host = 0;
  for (int k = 0; k < kScratchSlots; ++k)
    dev += scratch.bytes(static_cast<ScratchSlot>(k));
  for (const auto& v : spare_rays)
    host += v.capacity() * sizeof(rc_ray);
  for (const auto& v : spare_hits)
    host += v.capacity() * sizeof(rc_hit);
  std::fprintf(stderr, "profile: scratch      %9.1f MB device buffers, %.1f MB queues\n",
               static_cast<double>(dev) / 1e6, static_cast<double>(host) / 1e6);
  const device::Transfers t = device::transfers();
  if (t.up + t.down)
    std::fprintf(stderr, "profile: transfers    %9.1f MB to the device, %.1f MB back\n",
                 static_cast<double>(t.up) / 1e6, static_cast<double>(t.down) / 1e6);
  std::fprintf(stderr, "profile: waits        %9zu for the device\n", t.waits);
}

Renderer::Impl::Impl(const scene::LoadedScene& s, const RenderSettings& st, device::Context& c)
    : scene(s), settings(st), ctx(c), geom(s), cs(compile_scene(s, geom, true, st.contrib.get())),
      program(built(prof, c, shade_program(cs, st))), shade(program.kernel("rc_shade")),
      accumulate(program.kernel("rc_accumulate")), shadow_step(program.kernel("rc_shadow_step")),
      pack(program.kernel("rc_pack")), shadow_view(program.kernel("rc_shadow_view")),
      shadow_view_counted(program.kernel("rc_shadow_view_counted")),
      offsets(program.kernel("rc_offsets")), surfaces(upload(c, cs.surfaces)),
      materials(upload(c, cs.materials)), args(upload(c, cs.args)), params(c, sizeof(rc_params)),
      patterns(upload(c, cs.patterns)), centre(geom.centre()) {
  amb_blocked.update(c, std::vector<std::uint32_t>(4, 0u), 0);
  if (st.contrib) {
    if (st.aa > 0 || st.dt > 0 || st.trace != RenderSettings::Trace::Off || st.std_error ||
        (st.as > 0 && st.ab > 0))
      throw FatalError("contributions need -aa 0, -as 0, -dt 0 and no trace mode");
    accumulate_contrib = program.kernel("rc_accumulate_contrib");
    if (has_medium(st) || cs.features.has(RC_OBJ_MIST))
      warning("ray contribution calculation does not support participating media");
  }
  if (st.ambient_list != RenderSettings::AmbientList::None) {
    mark_ambient_list(cs, st.ambient_list == RenderSettings::AmbientList::Include,
                      st.ambient_names);
    surfaces = upload(c, cs.surfaces);
  }
  rc_params p{};
  p.av = f4(st.av[0], st.av[1], st.av[2], st.lw);
  p.direct = f4(st.ds, st.dj, st.dt, st.dc);
  // Rays leave surfaces at least this far along; the kernels widen it where a point's float
  // coordinates are coarser (rc_leave in hit_output.cl), so small detail near the centre of a
  // huge scene is not skipped.
  p.spec = f4(st.ss, st.st, geom.epsilon(), 0);
  p.seed = st.seed;
  p.lr = st.lr;
  p.flags = (st.dv ? RC_PF_DV : 0u) | (st.bv ? RC_PF_BV : 0u) |
            (st.irradiance_i ? RC_PF_IRRAD_I : 0u) | (st.low_discrepancy ? RC_PF_LOWDISC : 0u) |
            (st.std_error ? RC_PF_SPREAD : 0u);
  p.ab = static_cast<std::uint32_t>(st.ab);
  p.nsources = static_cast<std::uint32_t>(cs.sources.sources.size());
  p.irradiance_material = cs.irradiance_material;
  p.ad = static_cast<std::uint32_t>(std::max(0, st.ad));
  bool super = st.as > 0 && st.ab > 0 && st.ad > 0;
  tree = super || st.trace != RenderSettings::Trace::Off || st.std_error;
  p.as = super ? static_cast<std::uint32_t>(st.as) : 0u;
  ray_eps = p.spec.z;
  cache_records = st.ambient_records;
  for (const ambient::AmbientRecord& a : cache_records)
    cache_local.push_back(local_record(a));
  building = uses_cache(st) && st.make_records && st.trace == RenderSettings::Trace::Off;
  p.amb = f4(st.aa, st.ambient_min_radius, 0, 0);
  p.medium = f4(st.me[0], st.me[1], st.me[2], st.mg);
  p.albedo = f4(st.ma[0], st.ma[1], st.ma[2], st.ms);
  p.mist = RC_NONE;
  p.contrib = cs.contrib_table;
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
  if (cs.mist_table != RC_NONE) { // the mists' sources, now that the virtual ones exist
    const std::vector<std::uint32_t> table =
        mist_source_table(cs.mist_sources, cs.sources, cs.surface_names);
    args.write(table.data(), table.size() * sizeof(std::uint32_t), cs.mist_table * sizeof(float));
    p.mist = cs.mist_table;
  }
  params.write(&p, sizeof p);
  base = p;
  stats = RenderStats{}; // the pretest's rays are not the caller's
}

void Renderer::Impl::upload_sources() {
  shadow_tracer.note_blockers(cs.sources);
  sources = upload(ctx, cs.sources.sources);
  verts = upload(ctx, cs.sources.verts);
  mirror_surfaces = upload(ctx, cs.sources.mirrors);
}

std::vector<float> Renderer::Impl::pretest(const CompiledSources& so,
                                           const std::vector<rc_shadow>& rays) {
  shadow_tracer.note_blockers(so);
  sources = upload(ctx, so.sources);
  verts = upload(ctx, so.verts);
  mirror_surfaces = upload(ctx, so.mirrors);
  std::vector<std::uint8_t> blocked;
  device::Buffer& b = scratch(kShadows, rays);
  shadow_tracer.trace(b, rays.size(), blocked);
  std::vector<rc_shadow> sh(rays.size());
  if (!sh.empty()) read_rows(b, sh.data(), sh.size() * sizeof(rc_shadow));
  std::vector<float> out(sh.size());
  for (std::size_t i = 0; i < sh.size(); ++i)
    out[i] = blocked[i] ? 0.0f : sh[i].contrib.x;
  return out;
}

void Renderer::Impl::render(std::span<const PrimaryRay> rays, std::span<PrimaryResult> results) {
  if (results.size() != rays.size()) throw FatalError("renderer: result span size mismatch");
  if (building) {
    build_render(rays, results, {});
    return;
  }
  run(rays, results);
}

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
