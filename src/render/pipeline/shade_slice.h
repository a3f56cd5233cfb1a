// One slice of a chunk on its way through shading (Renderer::Impl::shade_slice): what each
// stage leaves for the next, and how the slice's data crosses between host and device.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>

#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device_types.h"
#include "radcl/render/pipeline/phase_profile.h"

namespace radcl::render {

struct ShadowView {
  rc_float4 org, dir; // dir.w: reach (kernels' rc_shadow_view)
};

// RADCL_PROFILE=waves: each step of a slice waited for and timed on its own (nothing
// otherwise).
class SliceSteps {
public:
  SliceSteps(PhaseProfile& prof, device::Context& ctx) : prof_(prof), ctx_(ctx) {}
  void operator()(PhaseProfile::Step s) {
    if (!prof_.waves()) return;
    ctx_.finish();
    const auto now = std::chrono::steady_clock::now();
    prof_.add_step(s, std::chrono::duration<double>(now - at_).count());
    at_ = now;
  }
  bool timed() const { return prof_.waves(); }

private:
  PhaseProfile& prof_;
  device::Context& ctx_;
  std::chrono::steady_clock::time_point at_ = std::chrono::steady_clock::now();
};

struct ShadeSlice {
  // The rays [rays, rays + n) and their hits; the room per ray in the kernel's slots.
  const rc_ray* rays = nullptr;
  const rc_hit* hit = nullptr;
  std::size_t n = 0;
  std::uint32_t cap_shadow = 0, cap_spawn = 0;
  SliceSteps* steps = nullptr;
  // Inputs (stage 1): what rc_shade reads, and whether the rays came from the device's copy
  // of their generation.
  device::Buffer ray_view, hit_view; // the host's queues in place, where the device shares them
  device::Buffer *rays_in = nullptr, *hits_in = nullptr;
  bool from_device_copy = false;
  bool tally_slice = false; // the -as tally takes this slice's totals
  // rc_shade's outputs (stage 2): the slots, immediate values, counts and hemisphere marks.
  device::Buffer *slot_shadows = nullptr, *slot_children = nullptr, *immediate = nullptr;
  device::Buffer *nshadow = nullptr, *nspawn = nullptr, *cells = nullptr;
  // Read with the counts: the slots in place (shared memory), or a small slice packed whole
  // on the device in the same wait (discrete memory: `fused`).
  const rc_ray* host_slots = nullptr;
  bool fused = false;
  const ShadowView* fused_view = nullptr;
  const device::Buffer* fused_children = nullptr;
  // Placed (stage 3): the packed requests on the device, their offsets, their views where
  // they were read along, and the children in the next generation.
  std::uint32_t total_shadows = 0, total_children = 0;
  device::Buffer *shadow_offsets = nullptr, *shadows = nullptr;
  const ShadowView* view = nullptr;
  std::size_t first_child = 0;
  rc_ray* children = nullptr;
  device::Buffer* children_on_device = nullptr; // rays shaded again write their children there
};

} // namespace radcl::render
