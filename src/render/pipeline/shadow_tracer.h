// Shadow rays in steps: Embree finds each one's next hit, the kernel (rc_shadow_step) decides
// whether it reached its source, is blocked, or continues through a transmitting surface with
// its contribution reduced (then it is traced again from there). Each ray keeps its slot, so
// the result does not depend on the order of work. Rays whose hit blocks them outright, or (all
// sources distant, nothing bending or dimming a ray) that meet nothing, are decided on the host
// without a step. In chunks, so the host's per-ray scratch (Embree's answers above all) stays in
// memory that is reused rather than freshly mapped and cleared.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "radcl/device/buffer.h"
#include "radcl/render/pipeline/phase_profile.h"
#include "radcl/render/pipeline/renderer.h"
#include "scratch_pool.h"
#include "shade_slice.h"

namespace radcl::render {

struct CompiledSources;

class ShadowTracer {
public:
  explicit ShadowTracer(Renderer::Impl& im);

  // Which surfaces block every shadow ray that meets them (plastic, metal and their kin, no
  // antimatter clipping them), and whether misses reach their sources. None while a source is
  // virtual (its rays must meet the mirror), or with tuning.shadow_blockers_on_host off.
  void note_blockers(const CompiledSources& so);

  // The packed requests [0, n) of `shadows` stay on the device: the host traces them from a
  // view of their origins and directions (rc_shadow_view), the steps update them in place.
  // Survivors' final contributions are written back into `shadows`; blocked[k] says whether
  // request k was blocked (the device's kBlocked buffer holds the same flags once it returns).
  // `view`: the requests' views where the caller had them made (view_later, read in the same
  // wait as its own transfers); null: made here. `after_step`: commands enqueued after each
  // step of the last chunk, in that step's wait; true when they ran after the last step (so
  // their results stand).
  bool trace(device::Buffer& shadows, std::size_t n, std::vector<std::uint8_t>& blocked,
             const ShadowView* view = nullptr, const std::function<void()>& after_step = {});

  // rc_shadow_view over requests [0, n) of `shadows`, enqueued; the views are there once the
  // context finishes.
  const ShadowView* view_later(device::Buffer& shadows, std::size_t n);
  // Host room for views read from the device.
  std::vector<char>& view_staging() { return view_staging_; }

  static constexpr std::size_t kChunk = std::size_t{1} << 18; // requests traced at once

private:
  // Requests [first, first + n): blocked[first + i] cleared for each one that reached its
  // source.
  bool trace_chunk(device::Buffer& shadows, const ShadowView* view, std::size_t first,
                   std::size_t n, std::uint8_t* blocked, const std::function<void()>& after_step);
  // Its steps: the requests that are rays into cur_ (their slots in slot_); their hits from
  // Embree, each decided on the host where it can be (decided_); the undecided ones packed in
  // order (their count returned; the flags of those that reached written); rc_shadow_step over
  // them, whose states come back in state_ (and the next views where they came along, else
  // null).
  void gather(const ShadowView* view, std::size_t first, std::size_t n);
  void trace_hits(std::size_t m, bool decide);
  std::size_t keep_undecided(std::size_t m, std::size_t first, std::size_t n,
                             std::uint8_t* blocked);
  const ShadowView* step(device::Buffer& shadows, std::size_t m,
                         const std::function<void()>& after_step, PhaseProfile::StepClock& clock);

  Renderer::Impl& im_; // the scene on the device, the scratch pool, the kernels
  // A step's rays, their answers, states and slots, kept from step to step.
  std::vector<ShadowView> cur_;
  HitQueue hits_; // pinned: they cross without a copy
  std::vector<char> view_staging_, step_staging_;
  std::vector<std::uint32_t> state_, slot_;
  std::vector<std::uint8_t> blockers_, decided_;
  bool misses_reach_ = false;
};

} // namespace radcl::render
