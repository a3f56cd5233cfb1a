// Stage: shadow rays, stepped through Embree and rc_shadow_step until each reaches its source
// or is blocked (shadow_tracer.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <string_view>

#include "pipeline_util.h"
#include "radcl/render/compile/material_traits.h"
#include "renderer_impl.h"
#include "shadow_tracer.h"

namespace radcl::render {

using namespace ambient;
using namespace pipeline;

ShadowTracer::ShadowTracer(Renderer::Impl& im) : im_(im), hits_(PinnedAlloc<rc_hit>(&im.ctx)) {}

void ShadowTracer::note_blockers(const CompiledSources& so) {
  blockers_.clear();
  misses_reach_ = false;
  if (!im_.settings.tuning.shadow_blockers_on_host)
    return; // every ray stepped on the device (the tests' reference)
  for (const rc_source& src : so.sources)
    if (src.flags & RC_SRCF_VIRTUAL) return;
  // A miss reaches a distant source unchanged where no ray travels in a medium (nothing to
  // lose on the way) and none is bent (by a dielectric) away from where it was aimed.
  const device::FeatureSet& f = im_.cs.features;
  misses_reach_ = !has_medium(im_.settings) && !f.has(RC_OBJ_MIST) && !f.has(RC_OBJ_DIELECTRIC) &&
                  !f.has(RC_OBJ_INTERFACE) &&
                  std::all_of(so.sources.begin(), so.sources.end(),
                              [](const rc_source& src) { return src.kind == RC_SRC_DISTANT; });
  // Only materials rc_shadow_at passes to its last case; emitters are left to the step (one
  // may be the source aimed at) and so is every other kind.
  blockers_.resize(im_.cs.surfaces.size());
  for (std::size_t i = 0; i < im_.cs.surfaces.size(); ++i) {
    const rc_surface& f = im_.cs.surfaces[i];
    blockers_[i] = f.material != RC_NONE && f.clip == 0 && f.source == RC_NONE &&
                   material_traits(static_cast<rc_object_type>(im_.cs.materials[f.material].type))
                       .blocks_shadows;
  }
}

const ShadowView* ShadowTracer::view_later(device::Buffer& shadows, std::size_t n) {
  // What Embree needs of each request, made on the device: 32 bytes cross, not the record.
  device::Buffer& bview = im_.scratch(kShadowView, n * sizeof(ShadowView));
  im_.shadow_view.arg(0, shadows)
      .arg(1, static_cast<std::uint32_t>(n))
      .arg(2, im_.sources)
      .arg(3, bview);
  im_.ctx.run(im_.shadow_view, n);
  return static_cast<const ShadowView*>(bview.peek_later(n * sizeof(ShadowView), view_staging_));
}

bool ShadowTracer::trace(device::Buffer& shadows, std::size_t n, std::vector<std::uint8_t>& blocked,
                         const ShadowView* view, const std::function<void()>& after_step) {
  blocked.assign(n, 1);
  if (n == 0) return false;
  im_.scratch(kBlocked, blocked); // the steps clear the reached ones' flags on the device too
  if (!view) {
    view = view_later(shadows, n);
    im_.ctx.finish();
  }
  bool done = false;
  for (std::size_t a = 0; a < n; a += kChunk) {
    const bool last = a + kChunk >= n;
    done = trace_chunk(shadows, view, a, std::min(kChunk, n - a), blocked.data(),
                       last ? after_step : std::function<void()>{});
  }
  return done;
}

bool ShadowTracer::trace_chunk(device::Buffer& shadows, const ShadowView* view, std::size_t first,
                               std::size_t n, std::uint8_t* blocked,
                               const std::function<void()>& after_step) {
  gather(view, first, n);
  std::vector<std::uint32_t>&slot = slot_, &state = state_;
  std::vector<ShadowView>& cur = cur_;
  state.assign(cur.size(), 0);
  // Radiance traces shadow rays on until their weight vanishes; a glass stack that needs
  // more steps than this contributes nothing measurable.
  constexpr int kMaxSteps = 64;
  bool done = false; // after_step ran after the last step
  for (int s = 0; s < kMaxSteps && !cur.empty(); ++s) {
    std::size_t m = cur.size();
    PhaseProfile::Scope timed(im_.prof, Phase::ShadowTrace);
    // Rays whose hit blocks them outright stay blocked with no step (blockers_); misses
    // may reach their sources with none (misses_reach_).
    const bool decide = !blockers_.empty();
    trace_hits(m, decide);
    im_.stats.shadow += m;
    if (decide) {
      m = keep_undecided(m, first, n, blocked);
      if (m == 0) break;
    }
    im_.stats.shadow_steps += m;
    timed.start(Phase::ShadowStep);
    PhaseProfile::StepClock clock(im_.prof);
    const ShadowView* next = step(shadows, m, after_step, clock);
    done = static_cast<bool>(after_step);

    std::size_t k = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const std::uint32_t status = state[i] & RC_SH_STATUS;
      if (status == RC_SH_REACHED)
        blocked[slot[i]] = 0;
      else if (status == RC_SH_CONTINUE)
        ++k;
    }
    clock.mark(PhaseProfile::StepShadowHost);
    if (k == 0) break;
    // The few that go on (through glass): their new origins and directions.
    if (!next)
      next = static_cast<const ShadowView*>(im_.scratch(kStepView, m * sizeof(ShadowView))
                                                .peek(m * sizeof(ShadowView), step_staging_));
    k = 0;
    for (std::size_t i = 0; i < m; ++i)
      if ((state[i] & RC_SH_STATUS) == RC_SH_CONTINUE) {
        cur[k] = next[i];
        state[k] = state[i];
        slot[k] = slot[i];
        ++k;
      }
    cur.resize(k);
    state.resize(k);
    slot.resize(k);
    done = false;
  }
  return done;
}

void ShadowTracer::gather(const ShadowView* view, std::size_t first, std::size_t n) {
  std::vector<std::uint32_t>& slot = slot_;
  std::vector<ShadowView>& cur = cur_;
  slot.clear();
  cur.clear();
  // Estimates and empty slots of the -dt selection (reach < 0) are not rays. Where there are
  // none (a hit with two source samples or fewer writes no estimate), the chunk is copied
  // whole, on every core.
  const ShadowView* v = view + first;
  const bool all_rays = std::none_of(v, v + n, [](const ShadowView& q) { return q.dir.w < 0; });
  if (all_rays) {
    cur.resize(n);
    parallel_copy(cur.data(), v, n * sizeof(ShadowView));
    slot.resize(n);
    std::iota(slot.begin(), slot.end(), static_cast<std::uint32_t>(first));
  } else {
    for (std::size_t i = 0; i < n; ++i)
      if (v[i].dir.w >= 0) {
        slot.push_back(static_cast<std::uint32_t>(first + i));
        cur.push_back(v[i]);
      }
  }
}

void ShadowTracer::trace_hits(std::size_t m, bool decide) {
  // One pass per ray: the query and its device record.
  HitQueue& hits = hits_;
  if (hits.capacity() < kChunk) hits.reserve(kChunk); // pinned room is costly to take
  hits.resize(m);
  std::vector<std::uint8_t>& decided = decided_;
  if (decide) decided.resize(m);
  const std::vector<ShadowView>& cur = cur_;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m, 256), [&](const auto& range) {
    constexpr std::size_t kBlock = 16; // to Embree in packets
    std::array<geometry::Ray, kBlock> ray;
    std::array<std::optional<geometry::Hit>, kBlock> h;
    for (std::size_t a = range.begin(); a < range.end(); a += kBlock) {
      const std::size_t b = std::min(kBlock, range.end() - a);
      for (std::size_t k = 0; k < b; ++k) {
        const ShadowView& s = cur[a + k];
        ray[k].org = {s.org.x + im_.centre[0], s.org.y + im_.centre[1], s.org.z + im_.centre[2]};
        ray[k].dir = {s.dir.x, s.dir.y, s.dir.z};
        ray[k].tmin = s.org.w;
        ray[k].free_origin = s.org.w > 0; // from an -I meter's point (rc_leave_org)
        ray[k].tmax = std::isfinite(s.dir.w) ? s.dir.w * 1.001 + 1e-3 : 1e300;
      }
      im_.geom.intersect_block(ray.data(), b, h.data());
      for (std::size_t k = 0; k < b; ++k) {
        if (decide) { // a decided ray's record is never read
          std::uint8_t& d = decided[a + k];
          if (h[k]) {
            const std::uint32_t f = im_.cs.surface_of(*h[k]);
            d = f < blockers_.size() ? blockers_[f] : 0;
          } else {
            d = misses_reach_ ? 2 : 0;
          }
          if (d) continue;
        }
        im_.to_device(ray[k], h[k], hits[a + k]);
      }
    }
  });
}

std::size_t ShadowTracer::keep_undecided(std::size_t m, std::size_t first, std::size_t n,
                                         std::uint8_t* blocked) {
  // The rest, packed in order.
  HitQueue& hits = hits_;
  const std::vector<std::uint8_t>& decided = decided_;
  std::vector<std::uint32_t>&slot = slot_, &state = state_;
  std::size_t k = 0;
  bool reached = false;
  for (std::size_t i = 0; i < m; ++i) {
    if (decided[i] == 2) {
      blocked[slot[i]] = 0;
      reached = true;
    }
    if (decided[i]) continue;
    if (k != i) {
      hits[k] = hits[i];
      slot[k] = slot[i];
      state[k] = state[i];
    }
    ++k;
  }
  m = k;
  hits.resize(m);
  slot.resize(m);
  state.resize(m);
  // In queue order before the step and the sums that read them.
  if (reached) im_.scratch(kBlocked, std::size_t{0}).write(blocked + first, n, first);
  return m;
}

const ShadowView* ShadowTracer::step(device::Buffer& shadows, std::size_t m,
                                     const std::function<void()>& after_step,
                                     PhaseProfile::StepClock& clock) {
  HitQueue& hits = hits_;
  std::vector<std::uint32_t>&slot = slot_, &state = state_;
  // The step works on the requests in place: only the hits, the slots and the states cross.
  device::Buffer& bslot = im_.scratch(kStepSlots, slot);
  device::Buffer hit_view = device::Buffer::view(im_.ctx, hits.data(), m * sizeof(rc_hit));
  device::Buffer& bhits = hit_view.handle() ? hit_view : im_.scratch(kStepHits, m * sizeof(rc_hit));
  if (!hit_view.handle()) write_rows(bhits, hits.data(), m * sizeof(rc_hit));
  device::Buffer& bstate = im_.scratch(kStepState, state);
  device::Buffer& bnext = im_.scratch(kStepView, m * sizeof(ShadowView));
  std::uint32_t um = static_cast<std::uint32_t>(m);
  im_.shadow_step.arg(0, shadows)
      .arg(1, bslot)
      .arg(2, bhits)
      .arg(3, bstate)
      .arg(4, bnext)
      .arg(5, im_.scratch(kBlocked, std::size_t{0}))
      .arg(6, um);
  im_.set_scene_args(im_.shadow_step, 7);
  im_.ctx.run(im_.shadow_step, m);
  bstate.read_later(state.data(), m * sizeof(std::uint32_t));
  // The caller's next commands go in the same wait, in case this step is the last; so do
  // the new views of a step this small, in case some go on (each wait is a round trip on a
  // GPU, where reading them after it would be another).
  if (after_step) after_step();
  const bool views_along = after_step && m <= im_.kSumAlongRays;
  const ShadowView* next = nullptr;
  if (views_along)
    next = static_cast<const ShadowView*>(bnext.peek_later(m * sizeof(ShadowView), step_staging_));
  clock.mark(PhaseProfile::StepShadowSend);
  im_.ctx.finish();
  clock.mark(PhaseProfile::StepShadowWait);
  return next;
}

} // namespace radcl::render
