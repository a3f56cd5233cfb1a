// A vector allocator whose resize() leaves new elements of a trivial type uninitialised, for
// buffers every new element of which is written before it is read: value-initialising them
// first is a pass over the memory (6 GB a run for the wave pipeline's ray queues at -ab 2
// -aa 0 -ad 1024 over 10,000 sensors).
#pragma once

#include <memory>
#include <new>
#include <utility>

namespace radcl {

template <class T> struct NoInit : std::allocator<T> {
  template <class U> struct rebind { using other = NoInit<U>; };
  NoInit() = default;
  template <class U> NoInit(const NoInit<U>&) noexcept {}
  template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
  template <class U, class... A> void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};

} // namespace radcl
