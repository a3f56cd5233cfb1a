// Stage: rc_shade over a slice of a chunk's hits, in steps: the inputs sent (SliceTransfer),
// the kernel into fixed slots, the counts read, the records placed (the children into the next
// generation, the shadow requests packed on the device) with rays that did not fit shaded again,
// the shadow rays traced, and each ray's total added to its primary's sum or to the -as tally.
#include <algorithm>
#include <chrono>
#include <functional>

#include "pipeline_util.h"
#include "renderer_impl.h"
#include "slice_transfer.h"

namespace radcl::render {

using namespace pipeline;

void Renderer::Impl::shade_slice(const rc_ray* rays, const rc_hit* hit, std::size_t n,
                                 RayQueue& next) {
  Timed timed(prof, Phase::Shade);
  SliceSteps steps(prof, ctx);
  ShadeSlice s;
  s.rays = rays;
  s.hit = hit;
  s.n = n;
  s.cap_shadow = cap_shadow;
  s.cap_spawn = cap_spawn;
  s.steps = &steps;
  transfer->send_inputs(*this, s);
  steps(PhaseProfile::StepUpload);
  launch_slice(s);
  place_slice(s, next);
  if (throwaway) {
    set_misses_aside(next, s.first_child);
    return;
  }
  timed.stop();
  finish_slice(s, next);
}

void Renderer::Impl::launch_slice(ShadeSlice& s) {
  const std::size_t n = s.n;
  const std::uint32_t csh = s.cap_shadow, csp = s.cap_spawn;
  s.slot_shadows = &scratch(kShadowSlots, n * csh * sizeof(rc_shadow));
  s.slot_children = &scratch(kSpawnSlots, n * csp * sizeof(rc_ray));
  s.immediate = &scratch(kImm, n * sizeof(rc_float4));
  s.nshadow = &scratch(kNShadow, n * 4);
  s.nspawn = &scratch(kNSpawn, n * 4);
  ShadeLaunch l{s.rays_in,      s.hits_in,       s.nshadow,  s.nspawn,
                s.slot_shadows, s.slot_children, s.immediate};
  l.cap_shadow = csh;
  l.cap_spawn = csp;
  s.cells = &scratch(kCells, n);
  l.cells = s.cells;
  // Rays from the device's copy carry the tallies the kernel gave them; the -as tally has
  // changed some since (its hemispheres' samples). The kernel takes the host's, so the children
  // come with the right ones and the tally need not write every child's.
  s.tally_slice = tree && !throwaway && settings.trace == RenderSettings::Trace::Off;
  if (s.from_device_copy && s.tally_slice) {
    shade_scratch.tallies.resize(n);
    for_rows(n, [&](std::size_t i) { shade_scratch.tallies[i] = s.rays[i].tally; });
    l.tallies = &scratch(kTallies, shade_scratch.tallies);
  }
  const auto w0 = std::chrono::steady_clock::now();
  run_shade(l, n);
  std::chrono::steady_clock::time_point w1;
  if (s.steps->timed()) {
    (*s.steps)(PhaseProfile::StepKernel);
    w1 = std::chrono::steady_clock::now();
  }
  // The counts and whatever the transfer reads with them, in one wait: a small slice's time is
  // mostly the latency of its transfers.
  transfer->read_with_counts(*this, s);
  if (settings.contrib) { // rcontrib: the rays' own contributions come back in the same wait
    shade_scratch.total.resize(n);
    s.immediate->read_later(shade_scratch.total.data(), n * sizeof(rc_float4));
  }
  ctx.finish();
  if (s.steps->timed()) {
    (*s.steps)(PhaseProfile::StepCounts);
    const auto w2 = std::chrono::steady_clock::now();
    prof.add_wave(n, std::chrono::duration<double>(w1 - w0).count(),
                  std::chrono::duration<double>(w2 - w1).count());
  }
}

void Renderer::Impl::place_slice(ShadeSlice& s, RayQueue& next) {
  ShadeScratch& x = shade_scratch;
  // A count with the top bit set: the ray did not fit its slots.
  std::vector<std::uint32_t>&shadow_off = x.shadow_off, &spawn_off = x.spawn_off;
  x.over.clear();
  for (std::size_t i = 0; i < s.n; ++i)
    if (shadow_off[i] & 0x80000000u) {
      shadow_off[i] &= 0x7FFFFFFFu;
      x.over.push_back(static_cast<std::uint32_t>(i));
    }
  x.nsp.assign(spawn_off.begin(), spawn_off.end());
  s.total_shadows = prefix_sum(shadow_off);
  s.total_children = prefix_sum(spawn_off);
  // The children go straight to the next generation's queue; a thrown-away pass wants only
  // them (they may miss too). The shadow requests are packed on the device and stay there.
  s.first_child = next.size();
  // The pending tally writes into children already in `next`: they must not move.
  if (s.first_child + s.total_children > next.capacity()) wait_tally();
  next.resize(s.first_child + s.total_children);
  s.children = next.data() + s.first_child;
  (*s.steps)(PhaseProfile::StepOffsets);
  const bool reshaded = !x.over.empty();
  transfer->place_records(*this, s, reshaded);
  (*s.steps)(PhaseProfile::StepChildren);
  if (reshaded) {
    reshade(s.rays, s.hit, x.over, x.nsp, shadow_off, spawn_off, *s.shadows, s.children,
            s.children_on_device, s.first_child);
    if (!s.children_on_device) gen_copy.upload(s.children, s.first_child, s.total_children);
  }
  if (s.from_device_copy && tree && !s.tally_slice)
    for_rows(s.n, [&](std::size_t i) {
      for (std::uint32_t k = 0; k < x.nsp[i]; ++k)
        s.children[spawn_off[i] + k].tally = s.rays[i].tally;
    });
}

void Renderer::Impl::finish_slice(ShadeSlice& s, RayQueue& next) {
  ShadeScratch& x = shade_scratch;
  const std::size_t n = s.n;
  const std::uint32_t nshadow = s.total_shadows;
  // -oT reports each request as made and as it arrived.
  const bool traced_shadows = settings.trace == RenderSettings::Trace::RaysAndShadows;
  x.requested.resize(traced_shadows ? nshadow : 0);
  if (!x.requested.empty())
    read_rows(*s.shadows, x.requested.data(), x.requested.size() * sizeof(rc_shadow));
  x.total.resize(n);
  device::Buffer& btotal = scratch(kTotal, n * sizeof(rc_float4));
  // The sums read the shadow rays' flags where the steps left them on the device.
  const auto sum_up = [&] {
    accumulate.arg(0, *s.immediate)
        .arg(1, *s.shadow_offsets)
        .arg(2, *s.shadows)
        .arg(3, scratch(kBlocked, std::size_t{nshadow}))
        .arg(4, static_cast<std::uint32_t>(n))
        .arg(5, nshadow)
        .arg(6, btotal);
    ctx.run(accumulate, n);
    btotal.read_later(x.total.data(), n * sizeof(rc_float4));
  };
  // On a GPU a small slice's time is the latency of its waits: the sums go along with every
  // shadow step, in its wait, and stand if it was the last (wasted work otherwise, which is
  // small for a slice this size).
  const bool along = transfer->sums_along(*this, n) && !traced_shadows && !settings.contrib;
  const bool summed =
      shadow_tracer.trace(*s.shadows, nshadow, x.blocked, s.view,
                          along ? std::function<void()>(sum_up) : std::function<void()>{});
  Timed timed(prof, Phase::Accumulate);
  PhaseProfile::StepClock clock(prof);
  x.shadows.resize(traced_shadows ? nshadow : 0);
  if (!x.shadows.empty())
    s.shadows->read_later(x.shadows.data(), x.shadows.size() * sizeof(rc_shadow));
  if (settings.contrib) {
    clock.mark(PhaseProfile::StepSumsWait);
    add_slice_contrib(s);
    set_misses_aside(next, s.first_child);
    clock.mark(PhaseProfile::StepSumsTally);
    return;
  }
  if (!summed) sum_up();
  if (!summed || !x.shadows.empty()) ctx.finish();
  clock.mark(PhaseProfile::StepSumsWait);
  add_slice(s);
  set_misses_aside(next, s.first_child);
  clock.mark(PhaseProfile::StepSumsTally);
}

void Renderer::Impl::add_slice(const ShadeSlice& s) {
  const ShadeScratch& x = shade_scratch;
  const std::size_t n = s.n;
  if (s.tally_slice) {
    feed_tally(s.rays, s.hit, s.children, n);
    return;
  }
  if (tree) {
    std::vector<TallyTree::TracedShadow> ts;
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t end = i + 1 < n ? x.spawn_off[i + 1] : s.total_children;
      ts.clear();
      if (!x.requested.empty()) {
        std::size_t send = i + 1 < n ? x.shadow_off[i + 1] : s.total_shadows;
        for (std::size_t k = x.shadow_off[i]; k < send; ++k)
          if (x.requested[k].source != RC_NONE) // not a -dt estimate
            ts.push_back({x.requested[k], x.shadows[k].contrib, x.blocked[k] != 0});
      }
      tally.shaded(s.rays[i], s.hit[i], x.total[i], s.children + x.spawn_off[i],
                   end - x.spawn_off[i], ts.data(), ts.size());
    }
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    Vec3d& sum = batch.sums[s.rays[i].tally];
    const rc_float4& t = x.total[i];
    sum[0] += t.x;
    sum[1] += t.y;
    sum[2] += t.z;
    if (s.rays[i].flags & RC_RAY_MIRRORED) {
      Vec3d& m = batch.mirrored_sums[slot(s.rays[i].primary)];
      m[0] += t.x;
      m[1] += t.y;
      m[2] += t.z;
    }
  }
}

} // namespace radcl::render
