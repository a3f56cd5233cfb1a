// Stage: rc_shade over a chunk of hits, its shadow requests and children packed in ray order,
// the shadow rays' answers summed by rc_accumulate into each primary.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>

#include "pipeline_util.h"
#include "renderer_impl.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

void Renderer::Impl::set_scene_args(device::Kernel& k, unsigned first) {
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

void Renderer::Impl::run_shade(const ShadeLaunch& l, std::size_t n) {
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
      .arg(kSceneArgs + 14, l.nspawn ? *l.nspawn : *l.spawn_off)
      .arg(kSceneArgs + 15, l.cells ? *l.cells : *l.spawn_off)
      .arg(kSceneArgs + 16, std::uint32_t{l.tallies ? 1u : 0u})
      .arg(kSceneArgs + 17, l.tallies ? *l.tallies : *l.spawn_off);
  ctx.run(shade, n);
}

void Renderer::Impl::run_count(device::Buffer& rays, device::Buffer& hits, device::Buffer& nshadow,
                               device::Buffer& nspawn, std::size_t n, device::Buffer* super_off,
                               device::Buffer* super_data) {
  ShadeLaunch l{&rays, &hits, &nshadow, &nspawn, &nshadow, &nshadow, &nshadow};
  l.super = super_off ? 1 : 0;
  l.super_off = super_off;
  l.super_data = super_data;
  l.cap_shadow = l.cap_spawn = 0;
  l.nshadow = &nshadow;
  l.nspawn = &nspawn;
  run_shade(l, n);
}

void Renderer::Impl::size_slots(std::span<const rc_ray> queue, const HitQueue& hits) {
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

void Renderer::Impl::reshade(const rc_ray* rays, const rc_hit* hit,
                             const std::vector<std::uint32_t>& over,
                             const std::vector<std::uint32_t>& nsp,
                             const std::vector<std::uint32_t>& shadow_off,
                             const std::vector<std::uint32_t>& spawn_off, device::Buffer& shadows,
                             rc_ray* children, device::Buffer* into, std::size_t base) {
  std::size_t m = over.size();
  std::vector<rc_ray> r(m);
  std::vector<rc_hit> h(m);
  std::vector<std::uint32_t> soff(m), poff(m);
  for (std::size_t k = 0; k < m; ++k) {
    r[k] = rays[over[k]];
    h[k] = hit[over[k]];
    soff[k] = shadow_off[over[k]]; // straight into their packed places
    // Children: where the device keeps the next generation, straight into their places there
    // (the others are there already), which is then read whole; else into room of their own.
    poff[k] = into ? static_cast<std::uint32_t>(base + spawn_off[over[k]]) : nsp[over[k]];
  }
  const std::uint32_t tsp = into ? 0 : prefix_sum(poff);
  device::Buffer& brays = scratch(kStepRays, r);
  device::Buffer& bhits = scratch(kStepHits, h);
  device::Buffer& bsoff = scratch(kSuperOff, soff);
  device::Buffer& bpoff = scratch(kSuperData, poff);
  device::Buffer& bsp = into ? *into : scratch(kSpawned, std::size_t{tsp} * sizeof(rc_ray));
  device::Buffer& bimm = scratch(kTotal, m * sizeof(rc_float4));
  run_shade(ShadeLaunch{&brays, &bhits, &bsoff, &bpoff, &shadows, &bsp, &bimm}, m);
  if (into) {
    const std::size_t total = spawn_off.back() + nsp.back();
    into->read_later(children, total * sizeof(rc_ray), base * sizeof(rc_ray));
    ctx.finish();
    return;
  }
  std::vector<rc_ray> sp(tsp);
  bsp.read_later(sp.data(), sp.size() * sizeof(rc_ray));
  ctx.finish();
  for (std::size_t k = 0; k < m; ++k)
    std::copy_n(sp.data() + poff[k], nsp[over[k]], children + spawn_off[over[k]]);
}

void Renderer::Impl::run_pack(device::Buffer& slot_sh, device::Buffer& slot_sp,
                              device::Buffer& nshadow, device::Buffer& nspawn,
                              device::Buffer& shadow_off, device::Buffer& spawn_off, std::size_t n,
                              bool with_spawn, device::Buffer& shadows, device::Buffer& spawned) {
  pack.arg(0, slot_sh)
      .arg(1, slot_sp)
      .arg(2, nshadow)
      .arg(3, nspawn)
      .arg(4, shadow_off)
      .arg(5, spawn_off)
      .arg(6, static_cast<std::uint32_t>(n))
      .arg(7, cap_shadow)
      .arg(8, cap_spawn)
      .arg(9, throwaway ? 0u : 1u)
      .arg(10, with_spawn ? 1u : 0u)
      .arg(11, shadows)
      .arg(12, spawned);
  ctx.run(pack, n);
}

void Renderer::Impl::shade_slice(const rc_ray* rays, const rc_hit* hit, std::size_t n,
                                 std::vector<Vec3d>& sums, RayQueue& next) {
  Timed timed(prof, Phase::Shade);
  std::uint32_t un = static_cast<std::uint32_t>(n);
  // RADCL_PROFILE=waves: each step waited for and timed on its own.
  auto step_at = std::chrono::steady_clock::now();
  const auto step = [&](PhaseProfile::Step s) {
    if (!prof.waves()) return;
    ctx.finish();
    const auto now = std::chrono::steady_clock::now();
    prof.add_step(s, std::chrono::duration<double>(now - step_at).count());
    step_at = now;
  };
  device::Buffer& brays = scratch(kRays, n * sizeof(rc_ray));
  // The rays from the device's copy of their generation where it has one (rc_ray.tally there
  // may be stale: the tally tree changes it on the host, and it only passes to the children,
  // whose tally is set again below).
  const bool from_mirror =
      mirror.current() && rays >= gen_queue.data() &&
      rays + n <= gen_queue.data() + gen_queue.size() &&
      mirror.copy_current(brays, static_cast<std::size_t>(rays - gen_queue.data()), n);
  // Where the device shares the host's memory, the kernel reads the queues in place.
  device::Buffer ray_view, hit_view;
  if (!from_mirror) {
    ray_view = device::Buffer::view(ctx, rays, n * sizeof(rc_ray));
    if (!ray_view.handle()) write_rows(brays, rays, n * sizeof(rc_ray));
  }
  hit_view = device::Buffer::view(ctx, hit, n * sizeof(rc_hit));
  device::Buffer& bhits = hit_view.handle() ? hit_view : scratch(kHits, n * sizeof(rc_hit));
  if (!hit_view.handle()) write_rows(bhits, hit, n * sizeof(rc_hit));
  step(PhaseProfile::StepUpload);
  const std::uint32_t csh = cap_shadow, csp = cap_spawn;
  device::Buffer& bslot_sh = scratch(kShadowSlots, n * csh * sizeof(rc_shadow));
  device::Buffer& bslot_sp = scratch(kSpawnSlots, n * csp * sizeof(rc_ray));
  device::Buffer& bimm = scratch(kImm, n * sizeof(rc_float4));
  device::Buffer& bnshadow = scratch(kNShadow, n * 4);
  device::Buffer& bnspawn = scratch(kNSpawn, n * 4);
  ShadeLaunch l{ray_view.handle() ? &ray_view : &brays,
                &bhits,
                &bnshadow,
                &bnspawn,
                &bslot_sh,
                &bslot_sp,
                &bimm};
  l.cap_shadow = csh;
  l.cap_spawn = csp;
  device::Buffer& bcells = scratch(kCells, n);
  l.cells = &bcells;
  // Rays from the device's copy carry the tallies the kernel gave them; the -as tally has
  // changed some since (its hemispheres' samples). The kernel takes the host's, so the children
  // come with the right ones and the tally need not write every child's.
  const bool tally_slice = tree && !throwaway && settings.trace == RenderSettings::Trace::Off;
  const bool retally = from_mirror && tally_slice;
  if (retally) {
    shade_scratch.tallies.resize(n);
    for_rows(n, [&](std::size_t i) { shade_scratch.tallies[i] = rays[i].tally; });
    l.tallies = &scratch(kTallies, shade_scratch.tallies);
  }
  const auto w0 = std::chrono::steady_clock::now();
  run_shade(l, n);
  std::chrono::steady_clock::time_point w1;
  if (prof.waves()) {
    step(PhaseProfile::StepKernel);
    w1 = std::chrono::steady_clock::now();
  }
  // A small slice on a GPU has its records packed before the host sees the counts (rc_offsets
  // places them), and its children and shadow views come back in the counts' wait: its time is
  // mostly the latency of its waits. Bounded by the slots' room, so it is read whole.
  ShadeScratch& x = shade_scratch;
  const bool on_device = !bslot_sp.zero_copy();
  const bool fused = fewer_waits && on_device &&
                     n * (csp * sizeof(rc_ray) + csh * sizeof(ShadowView)) <= kFusedBytes;
  const ShadowView* fused_view = nullptr;
  const device::Buffer* fused_spawned = nullptr; // its packed children
  if (fused) {
    device::Buffer& bsoff = scratch(kShadowOff, n * 4);
    device::Buffer& bpoff = scratch(kSpawnOff, n * 4);
    device::Buffer& btot = scratch(kTotals, 8);
    offsets.arg(0, bnshadow).arg(1, bnspawn).arg(2, un).arg(3, bsoff).arg(4, bpoff).arg(5, btot);
    ctx.run(offsets, kOffsetsGroup, kOffsetsGroup);
    device::Buffer& bsh = scratch(kShadows, n * csh * sizeof(rc_shadow));
    device::Buffer& bsp = scratch(kSpawned, n * csp * sizeof(rc_ray));
    run_pack(bslot_sh, bslot_sp, bnshadow, bnspawn, bsoff, bpoff, n, true, bsh, bsp);
    if (!throwaway) {
      device::Buffer& bview = scratch(kShadowView, n * csh * sizeof(ShadowView));
      shadow_view_counted.arg(0, bsh).arg(1, btot).arg(2, sources).arg(3, bview);
      ctx.run(shadow_view_counted, n * csh);
      fused_view =
          static_cast<const ShadowView*>(bview.peek_later(n * csh * sizeof(ShadowView), peek_view));
    }
    x.fused_children.resize(n * csp);
    bsp.read_later(x.fused_children.data(), n * csp * sizeof(rc_ray));
    fused_spawned = &bsp;
  }
  // The counts (and on PoCL this slice's slots, not the pool buffers whole) in one wait: a
  // small wave's time is mostly the latency of its transfers.
  std::vector<std::uint32_t>&shadow_off = x.shadow_off, &spawn_off = x.spawn_off;
  shadow_off.resize(n);
  spawn_off.resize(n);
  bnshadow.read_later(shadow_off.data(), n * 4);
  bnspawn.read_later(spawn_off.data(), n * 4);
  x.cells.resize(tally_slice ? n : 0); // only the -as tally reads them
  if (tally_slice) bcells.read_later(x.cells.data(), n);
  // Where the host reads the slots in place (PoCL) it packs them; elsewhere rc_pack packs them
  // on the device and only the records are read back (the slots are mostly room).
  const rc_ray* ssp =
      on_device
          ? nullptr
          : static_cast<const rc_ray*>(bslot_sp.peek_later(n * csp * sizeof(rc_ray), peek_sp));
  ctx.finish();
  if (prof.waves()) {
    step(PhaseProfile::StepCounts);
    const auto w2 = std::chrono::steady_clock::now();
    prof.add_wave(n, std::chrono::duration<double>(w1 - w0).count(),
                  std::chrono::duration<double>(w2 - w1).count());
  }
  std::vector<std::uint32_t>& over = x.over;
  over.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (shadow_off[i] & 0x80000000u) {
      shadow_off[i] &= 0x7FFFFFFFu;
      over.push_back(static_cast<std::uint32_t>(i));
    }
  x.nsp.assign(spawn_off.begin(), spawn_off.end());
  const std::vector<std::uint32_t>& nsp = x.nsp;
  std::uint32_t nshadow = prefix_sum(shadow_off), nspawn = prefix_sum(spawn_off);
  // The children go straight to the next generation's queue; a thrown-away pass wants only
  // them (they may miss too). The shadow requests are packed on the device and stay there.
  const std::size_t first_child = next.size();
  // The pending tally writes into children already in `next`: they must not move.
  if (first_child + nspawn > next.capacity()) wait_tally();
  next.resize(first_child + nspawn);
  rc_ray* children = next.data() + first_child;
  // Packed already (then the device's offsets are the host's: no ray was over its room)?
  const bool packed = fused && over.empty();
  device::Buffer* into = nullptr; // see below
  step(PhaseProfile::StepOffsets);
  device::Buffer& bsoff =
      packed ? scratch(kShadowOff, n * 4) : scratch(kShadowOff, shadow_off); // sums read it
  device::Buffer& bsh = scratch(kShadows, std::size_t{nshadow} * sizeof(rc_shadow));
  const ShadowView* view = nullptr;
  if (packed) {
    std::copy_n(x.fused_children.data(), nspawn, children);
    mirror.append(*fused_spawned, first_child, nspawn);
    if (nshadow) view = fused_view;
  } else {
    device::Buffer& bpoff = scratch(kSpawnOff, on_device ? spawn_off.size() * 4 : 4);
    if (on_device) bpoff.write(spawn_off.data(), spawn_off.size() * 4);
    device::Buffer& bsp = scratch(kSpawned, std::size_t{on_device ? nspawn : 1} * sizeof(rc_ray));
    run_pack(bslot_sh, bslot_sp, bnshadow, bnspawn, bsoff, bpoff, n, on_device, bsh, bsp);
    step(PhaseProfile::StepPack);
    // The shadow rays' views come back in the same wait as the children, unless requests
    // shaded again below still have to be written into their places.
    if (fewer_waits && over.empty() && !throwaway && nshadow)
      view = view_shadows_later(bsh, nshadow);
    if (on_device) {
      // Rays shaded again below write their children straight into the device's copy of the
      // next generation, read from there whole.
      into = over.empty() ? nullptr : mirror.next_rows(first_child, nspawn);
      // The children cross while the host traces the shadow rays: only what comes before them
      // (the shadow views) is waited for here, where the host reads no child before the sums'
      // wait (no ray shaded again, no tally written into them below, no record request).
      const bool children_later = children_later_on && !into && !throwaway && !collecting &&
                                  !(from_mirror && tree && !tally_slice);
      device::Context::Mark before_children;
      if (children_later) before_children = ctx.mark();
      if (nspawn && !into) bsp.read_later(children, std::size_t{nspawn} * sizeof(rc_ray));
      mirror.append(bsp, first_child, nspawn);
      if (children_later)
        ctx.wait_for(before_children);
      else
        ctx.finish();
    } else {
      if (view) ctx.finish();
      std::vector<char>& later = x.later; // shaded again below
      later.assign(n, 0);
      for (std::uint32_t i : over)
        later[i] = 1;
      for_rows(n, [&](std::size_t i) {
        if (!later[i]) std::copy_n(ssp + i * csp, nsp[i], children + spawn_off[i]);
      });
    }
  }
  step(PhaseProfile::StepChildren);
  if (!over.empty()) {
    reshade(rays, hit, over, nsp, shadow_off, spawn_off, bsh, children, into, first_child);
    if (!into) mirror.upload(children, first_child, nspawn);
  }
  if (from_mirror && tree && !tally_slice)
    for_rows(n, [&](std::size_t i) {
      for (std::uint32_t k = 0; k < nsp[i]; ++k)
        children[spawn_off[i] + k].tally = rays[i].tally;
    });
  if (throwaway) {
    set_misses_aside(next, first_child);
    return;
  }
  // -oT reports each request as made and as it arrived.
  const bool traced_shadows = settings.trace == RenderSettings::Trace::RaysAndShadows;
  std::vector<rc_shadow>&requested = x.requested, &shadows = x.shadows;
  requested.resize(traced_shadows ? nshadow : 0);
  if (!requested.empty()) read_rows(bsh, requested.data(), requested.size() * sizeof(rc_shadow));
  timed.stop();
  std::vector<std::uint8_t>& blocked = x.blocked;
  std::vector<rc_float4>& total = x.total;
  total.resize(n);
  device::Buffer& btotal = scratch(kTotal, n * sizeof(rc_float4));
  // The sums read the shadow rays' flags where the steps left them on the device.
  const auto sum_up = [&] {
    accumulate.arg(0, bimm)
        .arg(1, bsoff)
        .arg(2, bsh)
        .arg(3, scratch(kBlocked, std::size_t{nshadow}))
        .arg(4, un)
        .arg(5, nshadow)
        .arg(6, btotal);
    ctx.run(accumulate, n);
    btotal.read_later(total.data(), n * sizeof(rc_float4));
  };
  // On a GPU a small slice's time is the latency of its waits: the sums go along with every
  // shadow step, in its wait, and stand if it was the last (wasted work otherwise, which is
  // small for a slice this size).
  const bool along = fewer_waits && !ctx.zero_copy() && n <= kSumAlongRays && !traced_shadows;
  const bool summed = trace_shadows(
      bsh, nshadow, blocked, view, along ? std::function<void()>(sum_up) : std::function<void()>{});
  timed.start(Phase::Accumulate);
  PhaseProfile::StepClock clock(prof);
  shadows.resize(traced_shadows ? nshadow : 0);
  if (!shadows.empty()) bsh.read_later(shadows.data(), shadows.size() * sizeof(rc_shadow));
  if (!summed) sum_up();
  if (!summed || !shadows.empty()) ctx.finish();
  clock.mark(PhaseProfile::StepSumsWait);
  // The rest of this function feeds the sums or the tally (the clock's last part).
  struct MarkAtEnd {
    PhaseProfile::StepClock& c;
    ~MarkAtEnd() { c.mark(PhaseProfile::StepSumsTally); }
  } mark_at_end{clock};
  if (tally_slice) {
    feed_tally(rays, hit, children, n);
    set_misses_aside(next, first_child);
    return;
  }
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
      tally.shaded(rays[i], hit[i], total[i], children + spawn_off[i], end - spawn_off[i],
                   ts.data(), ts.size());
    }
    set_misses_aside(next, first_child);
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
  set_misses_aside(next, first_child);
}

} // namespace radcl::render
