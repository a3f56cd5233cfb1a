// Scratch memory the wave pipeline reuses from wave to wave: device buffers by slot and host
// vectors lent to a batch. Allocating them afresh every wave spends more time clearing pages
// than shading.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "radcl/device/buffer.h"
#include "radcl/device/context.h"

namespace radcl::render {

// The pipeline's device buffers, one per use.
enum ScratchSlot {
  kRays,
  kHits,
  kNShadow,
  kNSpawn,
  kShadowOff,
  kSpawnOff,
  kShadows,
  kSpawned,
  kImm,
  kBlocked,
  kTotal,
  kStepRays,
  kStepHits,
  kStepState,
  kStepSlots,
  kStepView,
  kShadowView,
  kSuperOff,
  kSuperData,
  kShadowSlots,
  kSpawnSlots,
  kTotals,
  kScratchSlots
};

// Device buffers by slot, grown by half again when a wave needs more and otherwise kept.
class ScratchPool {
public:
  explicit ScratchPool(device::Context& ctx) : ctx_(ctx), pool_(kScratchSlots) {}
  // The slot's buffer, at least `bytes` long.
  device::Buffer& operator()(ScratchSlot slot, std::size_t bytes) {
    bytes = std::max<std::size_t>(bytes, 16);
    if (pool_[slot].size() < bytes) pool_[slot] = device::Buffer(ctx_, bytes + bytes / 2);
    return pool_[slot];
  }
  // The slot's buffer holding a copy of `v`.
  template <class T> device::Buffer& operator()(ScratchSlot slot, const std::vector<T>& v) {
    device::Buffer& b = (*this)(slot, v.size() * sizeof(T));
    if (!v.empty()) b.write(v.data(), v.size() * sizeof(T));
    return b;
  }

  // Bytes held, by slot.
  std::size_t bytes(ScratchSlot slot) const { return pool_[slot].size(); }

private:
  device::Context& ctx_;
  std::vector<device::Buffer> pool_;
};

// An allocator whose resize() leaves new elements of a trivial type uninitialised: the queues'
// new rows are always written over (children read back from the device, hits from Embree), and
// zeroing them first cost a pass over every ray of every generation (6 GB in 10,000 sensors at
// -ab 2 -aa 0 -ad 1024).
template <class T> struct NoInit : std::allocator<T> {
  template <class U> struct rebind { using other = NoInit<U>; };
  NoInit() = default;
  template <class U> NoInit(const NoInit<U>&) noexcept {}
  template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
  template <class U, class... A> void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};
// A generation's rays or hits on the host.
template <class T> using HostQueue = std::vector<T, NoInit<T>>;

// A vector lent from `pool` for a scope and given back, emptied but with its room, when the
// scope ends (a batch inside another, as a record's hemisphere inside a cache pass, takes
// others).
template <class T> struct Spare {
  std::vector<HostQueue<T>>& pool;
  HostQueue<T> v;
  explicit Spare(std::vector<HostQueue<T>>& p) : pool(p) {
    if (!pool.empty()) {
      v = std::move(pool.back());
      pool.pop_back();
    }
  }
  ~Spare() {
    v.clear();
    pool.push_back(std::move(v));
  }
  Spare(const Spare&) = delete;
  Spare& operator=(const Spare&) = delete;
};

} // namespace radcl::render
