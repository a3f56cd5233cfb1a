#include "slice_transfer.h"

#include <algorithm>

#include "pipeline_util.h"
#include "renderer_impl.h"

namespace radcl::render {
namespace {

using namespace pipeline;

// The counts each ray made (offsets once summed) and, for the -as tally, its hemisphere marks.
void read_counts(Renderer::Impl& im, ShadeSlice& s) {
  Renderer::Impl::ShadeScratch& x = im.shade_scratch;
  x.shadow_off.resize(s.n);
  x.spawn_off.resize(s.n);
  s.nshadow->read_later(x.shadow_off.data(), s.n * 4);
  s.nspawn->read_later(x.spawn_off.data(), s.n * 4);
  x.cells.resize(s.tally_slice ? s.n : 0); // only the -as tally reads them
  if (s.tally_slice) s.cells->read_later(x.cells.data(), s.n);
}

// The requests' offsets (as the host summed them) and room for the packed requests.
void shadow_room(Renderer::Impl& im, ShadeSlice& s, bool offsets_on_device) {
  s.shadow_offsets = offsets_on_device ? &im.scratch(kShadowOff, s.n * 4)
                                       : &im.scratch(kShadowOff, im.shade_scratch.shadow_off);
  s.shadows = &im.scratch(kShadows, std::size_t{s.total_shadows} * sizeof(rc_shadow));
}

class SharedTransfer final : public SliceTransfer {
public:
  void send_inputs(Renderer::Impl& im, ShadeSlice& s) const override {
    device::Buffer& brays = im.scratch(kRays, s.n * sizeof(rc_ray));
    s.ray_view = device::Buffer::view(im.ctx, s.rays, s.n * sizeof(rc_ray));
    if (!s.ray_view.handle()) write_rows(brays, s.rays, s.n * sizeof(rc_ray));
    s.rays_in = s.ray_view.handle() ? &s.ray_view : &brays;
    s.hit_view = device::Buffer::view(im.ctx, s.hit, s.n * sizeof(rc_hit));
    s.hits_in = s.hit_view.handle() ? &s.hit_view : &im.scratch(kHits, s.n * sizeof(rc_hit));
    if (!s.hit_view.handle()) write_rows(*s.hits_in, s.hit, s.n * sizeof(rc_hit));
  }

  // The slots are read in place (this slice's, not the pool buffers whole).
  void read_with_counts(Renderer::Impl& im, ShadeSlice& s) const override {
    read_counts(im, s);
    s.host_slots = static_cast<const rc_ray*>(
        s.slot_children->peek_later(s.n * s.cap_spawn * sizeof(rc_ray), im.peek_sp));
  }

  // rc_pack packs the requests on the device; the host copies the children out of their slots.
  void place_records(Renderer::Impl& im, ShadeSlice& s, bool reshaded) const override {
    Renderer::Impl::ShadeScratch& x = im.shade_scratch;
    shadow_room(im, s, false);
    device::Buffer& bpoff = im.scratch(kSpawnOff, 4);
    device::Buffer& bsp = im.scratch(kSpawned, sizeof(rc_ray));
    im.run_pack(*s.slot_shadows, *s.slot_children, *s.nshadow, *s.nspawn, *s.shadow_offsets, bpoff,
                s.n, false, *s.shadows, bsp);
    (*s.steps)(PhaseProfile::StepPack);
    if (im.fewer_waits && !reshaded && !im.throwaway && s.total_shadows) {
      s.view = im.shadow_tracer.view_later(*s.shadows, s.total_shadows);
      im.ctx.finish();
    }
    std::vector<char>& later = x.later; // shaded again afterwards
    later.assign(s.n, 0);
    for (std::uint32_t i : x.over)
      later[i] = 1;
    const std::uint32_t csp = s.cap_spawn;
    for_rows(s.n, [&](std::size_t i) {
      if (!later[i]) std::copy_n(s.host_slots + i * csp, x.nsp[i], s.children + x.spawn_off[i]);
    });
  }

  bool sums_along(const Renderer::Impl&, std::size_t) const override { return false; }
};

class DiscreteTransfer final : public SliceTransfer {
public:
  // The rays from the device's copy of their generation where it has one (rc_ray.tally there
  // may be stale: the tally tree changes it on the host, and it only passes to the children,
  // whose tally is set again).
  void send_inputs(Renderer::Impl& im, ShadeSlice& s) const override {
    device::Buffer& brays = im.scratch(kRays, s.n * sizeof(rc_ray));
    const std::span<const rc_ray> gen = im.batch.generation;
    s.from_device_copy =
        im.gen_copy.current() && s.rays >= gen.data() && s.rays + s.n <= gen.data() + gen.size() &&
        im.gen_copy.copy_current(brays, static_cast<std::size_t>(s.rays - gen.data()), s.n);
    if (!s.from_device_copy) write_rows(brays, s.rays, s.n * sizeof(rc_ray));
    s.rays_in = &brays;
    s.hits_in = &im.scratch(kHits, s.n * sizeof(rc_hit));
    write_rows(*s.hits_in, s.hit, s.n * sizeof(rc_hit));
  }

  // A small slice has its records packed before the host sees the counts (rc_offsets places
  // them), and its children and shadow views come back in the counts' wait: its time is mostly
  // the latency of its waits. Bounded by the slots' room, so it is read whole.
  void read_with_counts(Renderer::Impl& im, ShadeSlice& s) const override {
    const std::size_t n = s.n, csh = s.cap_shadow, csp = s.cap_spawn;
    s.fused = im.fewer_waits &&
              n * (csp * sizeof(rc_ray) + csh * sizeof(ShadowView)) <= Renderer::Impl::kFusedBytes;
    if (s.fused) {
      const std::uint32_t un = static_cast<std::uint32_t>(n);
      device::Buffer& bsoff = im.scratch(kShadowOff, n * 4);
      device::Buffer& bpoff = im.scratch(kSpawnOff, n * 4);
      device::Buffer& btot = im.scratch(kTotals, 8);
      im.offsets.arg(0, *s.nshadow).arg(1, *s.nspawn).arg(2, un).arg(3, bsoff).arg(4, bpoff);
      im.offsets.arg(5, btot);
      im.ctx.run(im.offsets, Renderer::Impl::kOffsetsGroup, Renderer::Impl::kOffsetsGroup);
      device::Buffer& bsh = im.scratch(kShadows, n * csh * sizeof(rc_shadow));
      device::Buffer& bsp = im.scratch(kSpawned, n * csp * sizeof(rc_ray));
      im.run_pack(*s.slot_shadows, *s.slot_children, *s.nshadow, *s.nspawn, bsoff, bpoff, n, true,
                  bsh, bsp);
      if (!im.throwaway) {
        device::Buffer& bview = im.scratch(kShadowView, n * csh * sizeof(ShadowView));
        im.shadow_view_counted.arg(0, bsh).arg(1, btot).arg(2, im.sources).arg(3, bview);
        im.ctx.run(im.shadow_view_counted, n * csh);
        s.fused_view = static_cast<const ShadowView*>(
            bview.peek_later(n * csh * sizeof(ShadowView), im.shadow_tracer.view_staging()));
      }
      im.shade_scratch.fused_children.resize(n * csp);
      bsp.read_later(im.shade_scratch.fused_children.data(), n * csp * sizeof(rc_ray));
      s.fused_children = &bsp;
    }
    read_counts(im, s);
  }

  // Packed on the device; only the records are read back (the slots are mostly room).
  void place_records(Renderer::Impl& im, ShadeSlice& s, bool reshaded) const override {
    Renderer::Impl::ShadeScratch& x = im.shade_scratch;
    const std::uint32_t nspawn = s.total_children;
    if (s.fused && !reshaded) { // packed already: the device's offsets are the host's
      shadow_room(im, s, true);
      std::copy_n(x.fused_children.data(), nspawn, s.children);
      im.gen_copy.append(*s.fused_children, s.first_child, nspawn);
      if (s.total_shadows) s.view = s.fused_view;
      return;
    }
    shadow_room(im, s, false);
    device::Buffer& bpoff = im.scratch(kSpawnOff, x.spawn_off.size() * 4);
    bpoff.write(x.spawn_off.data(), x.spawn_off.size() * 4);
    device::Buffer& bsp = im.scratch(kSpawned, std::size_t{nspawn} * sizeof(rc_ray));
    im.run_pack(*s.slot_shadows, *s.slot_children, *s.nshadow, *s.nspawn, *s.shadow_offsets, bpoff,
                s.n, true, *s.shadows, bsp);
    (*s.steps)(PhaseProfile::StepPack);
    // The shadow rays' views come back in the same wait as the children, unless requests
    // shaded again still have to be written into their places.
    if (im.fewer_waits && !reshaded && !im.throwaway && s.total_shadows)
      s.view = im.shadow_tracer.view_later(*s.shadows, s.total_shadows);
    // Rays shaded again write their children straight into the device's copy of the next
    // generation, read from there whole.
    s.children_on_device = reshaded ? im.gen_copy.next_rows(s.first_child, nspawn) : nullptr;
    // The children cross while the host traces the shadow rays: only what comes before them
    // (the shadow views) is waited for here, where the host reads no child before the sums'
    // wait (no ray shaded again, no tally written into them, no record request).
    const bool children_later = im.children_later_on && !s.children_on_device && !im.throwaway &&
                                !im.collecting &&
                                !(s.from_device_copy && im.tree && !s.tally_slice);
    device::Context::Mark before_children;
    if (children_later) before_children = im.ctx.mark();
    if (nspawn && !s.children_on_device)
      bsp.read_later(s.children, std::size_t{nspawn} * sizeof(rc_ray));
    im.gen_copy.append(bsp, s.first_child, nspawn);
    if (children_later)
      im.ctx.wait_for(before_children);
    else
      im.ctx.finish();
  }

  bool sums_along(const Renderer::Impl& im, std::size_t n) const override {
    return im.fewer_waits && n <= Renderer::Impl::kSumAlongRays;
  }
};

} // namespace

std::unique_ptr<SliceTransfer> make_slice_transfer(const device::Context& ctx) {
  if (ctx.zero_copy()) return std::make_unique<SharedTransfer>();
  return std::make_unique<DiscreteTransfer>();
}

} // namespace radcl::render
