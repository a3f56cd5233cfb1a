// Scratch memory the wave pipeline reuses from wave to wave: device buffers by slot and host
// vectors lent to a batch. Allocating them afresh every wave spends more time clearing pages
// than shading.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device_types.h"
#include "radcl/util/no_init.h"

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
  kCells,
  kTallies,
  kContrib, // rcontrib: the shadow requests' contributions
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

// A generation's rays on the host, new rows not zeroed (they are always written over).
template <class T> using HostQueue = std::vector<T, NoInit<T>>;

// The same, in the device's pinned host memory where it has some (Context::alloc_pinned): a
// chunk's hits, which Embree writes and the device reads, then cross without a copy (on a
// device sharing the host's memory the kernels read them in place). With kSharedOnly, only on
// such a device: a generation's rays, read in place there, stay pageable for a GPU.
template <class T, bool kSharedOnly = false> struct PinnedAlloc : NoInit<T> {
  template <class U> struct rebind { using other = PinnedAlloc<U, kSharedOnly>; };
  using propagate_on_container_move_assignment = std::true_type;
  using propagate_on_container_swap = std::true_type;
  using is_always_equal = std::false_type;
  device::Context* ctx = nullptr;
  PinnedAlloc() = default;
  explicit PinnedAlloc(device::Context* c) : ctx(c) {}
  template <class U> PinnedAlloc(const PinnedAlloc<U, kSharedOnly>& o) noexcept : ctx(o.ctx) {}
  T* allocate(std::size_t n) {
    if (ctx && (!kSharedOnly || ctx->zero_copy()))
      if (void* p = ctx->alloc_pinned(n * sizeof(T))) return static_cast<T*>(p);
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) {
    if (!(ctx && ctx->free_pinned(p))) std::allocator<T>().deallocate(p, n);
  }
  template <class U> bool operator==(const PinnedAlloc<U, kSharedOnly>& o) const {
    return ctx == o.ctx;
  }
};
using HitQueue = std::vector<rc_hit, PinnedAlloc<rc_hit>>;
using RayQueue = std::vector<rc_ray, PinnedAlloc<rc_ray, true>>;

// A vector lent from `pool` for a scope and given back, emptied but with its room, when the
// scope ends (a batch inside another, as a record's hemisphere inside a cache pass, takes
// others).
template <class V> struct Spare {
  std::vector<V>& pool;
  V v;
  // `fresh`: an empty vector with the allocator to use when the pool has none.
  explicit Spare(std::vector<V>& p, V fresh = V()) : pool(p), v(std::move(fresh)) {
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
