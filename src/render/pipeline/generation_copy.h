// The device's copy of a batch's ray generations (on a GPU): the children rc_pack leaves on the
// device are copied there beside the host's queue, so the next generation is shaded from device
// memory instead of crossing the bus again (112 bytes a ray, the largest of the shading's
// uploads). The host keeps its own queue for Embree and the tally tree; rows it writes or
// changes after the device made them are uploaded again. Where the device shares the host's
// memory (PoCL) there is nothing to save and the copy is off.
#pragma once

#include <cstddef>

#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device_types.h"

namespace radcl::render {

class GenerationCopy {
public:
  // `wanted` off: every generation is uploaded from the host.
  GenerationCopy(device::Context& ctx, bool wanted);
  // A batch begins: its first generation comes from the host.
  void start_batch();
  // Whether the current generation's rays are all on the device.
  bool current() const { return cur_ok_; }
  // Rows [first, first + n) of the current generation into `dst` (from its start); false where
  // they are not on the device (then the caller uploads them).
  bool copy_current(device::Buffer& dst, std::size_t first, std::size_t n);
  // Rows [at, at + n) of the next generation: copied from the front of `src` on the device, or
  // from the host's rows.
  void append(const device::Buffer& src, std::size_t at, std::size_t n);
  void upload(const rc_ray* rows, std::size_t at, std::size_t n);
  // The buffer of the next generation with room for rows up to at + n (those before `at`
  // kept), or nullptr where it is not kept on the device.
  device::Buffer* next_rows(std::size_t at, std::size_t n);
  // The next generation becomes the current one.
  void advance();

private:
  bool room(std::size_t rays, std::size_t keep);
  device::Context& ctx_;
  device::Buffer buf_[2];
  int cur_ = 0;
  bool on_ = false, cur_ok_ = false, next_ok_ = false;
  std::size_t max_bytes_ = 0; // of one copy
};

} // namespace radcl::render
