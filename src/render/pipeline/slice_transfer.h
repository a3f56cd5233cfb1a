// How a shading slice's data crosses between host and device, chosen once per renderer from
// the device's memory (Renderer::Impl::transfer).
//   Shared memory (PoCL on the host's cores): rc_shade reads the host's queues in place, and the
//   host reads the kernel's slots in place and packs the children itself.
//   Discrete memory (a GPU): a generation's rays stay on the device for the next
//   (GenerationCopy); the records are packed there (rc_pack; a small slice's in the counts'
//   own wait, through rc_offsets); the children cross back while the host traces the shadow
//   rays; and the sums ride along with the shadow steps.
#pragma once

#include <cstddef>
#include <memory>

#include "radcl/render/pipeline/renderer.h"
#include "shade_slice.h"

namespace radcl::render {

class SliceTransfer {
public:
  virtual ~SliceTransfer() = default;
  // Stage 1: the slice's rays and hits where rc_shade reads them.
  virtual void send_inputs(Renderer::Impl& im, ShadeSlice& s) const = 0;
  // Stage 2, enqueued before the counts' wait: what else that wait brings back.
  virtual void read_with_counts(Renderer::Impl& im, ShadeSlice& s) const = 0;
  // Stage 3, once the counts are known: the children into the next generation, the shadow
  // requests packed on the device. `reshaded`: some rays did not fit their slots and are shaded
  // again afterwards.
  virtual void place_records(Renderer::Impl& im, ShadeSlice& s, bool reshaded) const = 0;
  // Whether a slice of n rays sums its shadow rays along with each shadow step.
  virtual bool sums_along(const Renderer::Impl& im, std::size_t n) const = 0;
};

std::unique_ptr<SliceTransfer> make_slice_transfer(const device::Context& ctx);

} // namespace radcl::render
