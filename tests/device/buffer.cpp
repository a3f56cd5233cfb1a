// Buffers round-trip data; on a host-memory device (PoCL) they are zero-copy: the mapped
// pointer is the buffer's own host allocation.
#include <cstdlib>
#include <gtest/gtest.h>
#include <numeric>
#include <vector>

#include "device_fixture.h"
#include "radcl/device/buffer.h"
#include "radcl/device/growing_buffer.h"
#include "radcl/device/program.h"
#include "radcl/util/error.h"

using namespace radcl::device;

TEST(Buffer, RoundTripWithOffsets) {
  Context& ctx = test_context();
  std::vector<int> v(1000);
  std::iota(v.begin(), v.end(), -500);
  Buffer b = Buffer::from(ctx, v);
  EXPECT_EQ(b.to_vector<int>(1000), v);
  int patch[3] = {7, 8, 9};
  b.write(patch, sizeof patch, 10 * sizeof(int));
  std::vector<int> w = b.to_vector<int>(1000);
  EXPECT_EQ(w[9], v[9]);
  EXPECT_EQ(w[10], 7);
  EXPECT_EQ(w[12], 9);
  EXPECT_EQ(w[13], v[13]);
  EXPECT_THROW(b.write(patch, sizeof patch, 999 * sizeof(int)), radcl::FatalError);
  EXPECT_THROW(Buffer(ctx, 0), radcl::FatalError);
}

TEST(Buffer, ZeroCopyOnHostMemoryDevices) {
  Context& ctx = test_context();
  Buffer b(ctx, 1 << 20);
  EXPECT_EQ(b.zero_copy(), ctx.info().host_unified_memory);
  if (!b.zero_copy()) GTEST_SKIP() << ctx.info().name << " has its own memory";
  void* p = b.map();
  EXPECT_EQ(p, b.host_allocation());
  b.unmap(p);
}

TEST(Buffer, MoveTransfersOwnership) {
  Context& ctx = test_context();
  Buffer a(ctx, 64);
  auto* h = a.handle();
  Buffer b(std::move(a));
  EXPECT_EQ(b.handle(), h);
  EXPECT_EQ(a.handle(), nullptr);
}

// Reads right after a launch see the kernel's output, and a host write before a launch does
// not overtake it: on PoCL these copies bypass map/unmap (Context::direct_host), so they must
// wait for the pending kernel themselves.
TEST(Buffer, CopiesAroundLaunchesStayInOrder) {
  Context& ctx = test_context();
  Program prog(ctx, ProgramSource{{"probe/rng.cl"}, "", "-cl-std=CL1.2"});
  Kernel k = prog.kernel("rc_rng_fill");
  const std::uint32_t n = 1 << 16, dims = 1;
  Buffer out(ctx, n * 4), u(ctx, n * 4), ref(ctx, n * 4);
  std::vector<std::vector<std::uint32_t>> seen;
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    std::vector<std::uint32_t> junk(n, 0xDEADBEEFu);
    out.write(junk.data(), n * 4); // overwritten by the launch that follows
    k.arg(0, out).arg(1, u).arg(2, n).arg(3, dims).arg(4, seed);
    ctx.run(k, n);
    seen.push_back(out.to_vector<std::uint32_t>(n));
  }
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    k.arg(0, ref).arg(1, u).arg(2, n).arg(3, dims).arg(4, seed);
    ctx.run(k, n);
    ctx.finish();
    EXPECT_EQ(seen[seed - 1], ref.to_vector<std::uint32_t>(n)) << "seed " << seed;
  }
  EXPECT_NE(seen[0], seen[1]);
}

// The discrete GPU's path on any device (RADCL_DEVICE_MEMORY=separate): buffers in device
// memory, writes enqueued without waiting from a staged copy of the source (so the source may
// change or vanish at once), peek reading just the bytes asked for.
TEST(Buffer, SeparateMemoryStagesWritesAndPeeks) {
  setenv("RADCL_DEVICE_MEMORY", "separate", 1);
  Context ctx(select_device());
  unsetenv("RADCL_DEVICE_MEMORY");
  EXPECT_FALSE(ctx.zero_copy());
  EXPECT_FALSE(ctx.direct_host());
  Program prog(ctx, ProgramSource{{"probe/rng.cl"}, "", "-cl-std=CL1.2"});
  Kernel k = prog.kernel("rc_rng_fill");
  const std::uint32_t n = 4096;
  Buffer a(ctx, n * 4), b(ctx, n * 4);
  EXPECT_FALSE(a.zero_copy());
  {
    std::vector<std::uint32_t> src(n);
    std::iota(src.begin(), src.end(), 0u);
    a.write(src.data(), n * 4);
    std::fill(src.begin(), src.end(), 7u); // after the enqueue: must not reach the buffer
    b.write(src.data(), n * 4);
  } // the sources are gone before any transfer is waited for
  std::vector<char> staging;
  const auto* pa = static_cast<const std::uint32_t*>(a.peek(16 * 4, staging));
  EXPECT_GE(staging.size(), 16u * 4);
  for (std::uint32_t i = 0; i < 16; ++i)
    ASSERT_EQ(pa[i], i);
  std::vector<std::uint32_t> vb = b.to_vector<std::uint32_t>(n);
  for (std::uint32_t v : vb)
    ASSERT_EQ(v, 7u);
  // A kernel between a write and a read: the in-order queue keeps them in order.
  Buffer out(ctx, n * 4), u(ctx, n * 4);
  std::vector<std::uint32_t> zeros(n, 0);
  out.write(zeros.data(), n * 4);
  k.arg(0, out).arg(1, u).arg(2, n).arg(3, 1u).arg(4, 5u);
  ctx.run(k, n);
  std::vector<std::uint32_t> got = out.to_vector<std::uint32_t>(n);
  std::size_t nonzero = 0;
  for (std::uint32_t v : got)
    nonzero += v != 0;
  EXPECT_GT(nonzero, n / 2);
  EXPECT_THROW(a.peek(n * 4 + 1, staging), radcl::FatalError);
}

// Reads queued with read_later/peek_later hold the data once the context finishes, after a
// kernel that wrote it; a GrowingBuffer writes only past the elements it is told are
// unchanged and keeps them across growth. Both memory modes: host (PoCL's zero-copy) and the
// discrete GPU's separate memory.
static void check_later_reads_and_growth(Context& ctx) {
  Program prog(ctx, ProgramSource{{"probe/rng.cl"}, "", "-cl-std=CL1.2"});
  Kernel k = prog.kernel("rc_rng_fill");
  const std::uint32_t n = 4096;
  Buffer out(ctx, n * 4), u(ctx, n * 4), ref(ctx, n * 4);
  k.arg(0, ref).arg(1, u).arg(2, n).arg(3, 1u).arg(4, 9u);
  ctx.run(k, n);
  const std::vector<std::uint32_t> want = ref.to_vector<std::uint32_t>(n);
  k.arg(0, out);
  ctx.run(k, n);
  std::vector<std::uint32_t> head(16), tail(n - 16);
  out.read_later(head.data(), 16 * 4);
  out.read_later(tail.data(), (n - 16) * 4, 16 * 4);
  out.read_later(nullptr, 0); // nothing to read: no transfer
  std::vector<char> staging;
  const auto* p = static_cast<const std::uint32_t*>(out.peek_later(n * 4, staging));
  ctx.finish();
  for (std::uint32_t i = 0; i < n; ++i) {
    ASSERT_EQ(i < 16 ? head[i] : tail[i - 16], want[i]) << i;
    ASSERT_EQ(p[i], want[i]) << i;
  }
  EXPECT_THROW(out.read_later(head.data(), 8, n * 4 - 4), radcl::FatalError);

  GrowingBuffer g;
  std::vector<int> v(10);
  std::iota(v.begin(), v.end(), 0);
  g.update(ctx, v, 0);
  EXPECT_EQ(g.buffer().to_vector<int>(10), v);
  v[3] = -3; // the caller says only the first 2 are unchanged: 3.. are rewritten
  v.push_back(10);
  g.update(ctx, v, 2);
  EXPECT_EQ(g.buffer().to_vector<int>(11), v);
  const auto* before = g.buffer().handle();
  v.push_back(11); // fits the spare room: same buffer
  g.update(ctx, v, v.size() - 1);
  EXPECT_EQ(g.buffer().handle(), before);
  EXPECT_EQ(g.buffer().to_vector<int>(12), v);
  for (int i = 0; i < 100; ++i)
    v.push_back(100 + i); // past the room: a new buffer holding everything
  g.update(ctx, v, 12);
  EXPECT_GE(g.buffer().size(), v.size() * sizeof(int));
  EXPECT_EQ(g.buffer().to_vector<int>(v.size()), v);
  v.clear();
  g.update(ctx, v, 0); // empty: a buffer is still there to bind
  EXPECT_GE(g.buffer().size(), sizeof(int));
}

TEST(Buffer, LaterReadsAndGrowingBuffersHostMemory) {
  check_later_reads_and_growth(test_context());
}

TEST(Buffer, LaterReadsAndGrowingBuffersSeparateMemory) {
  setenv("RADCL_DEVICE_MEMORY", "separate", 1);
  Context ctx(select_device());
  unsetenv("RADCL_DEVICE_MEMORY");
  check_later_reads_and_growth(ctx);
}

// Separate memory goes through pinned host memory for transfers up to 1 MiB (staged writes and
// reads queued for later, copied out when the queue drains). Enough small transfers between
// two waits to fill more than one 8 MiB block, reads of both sizes, and a blocking read that
// delivers the reads queued before it; RADCL_PINNED=0 (pageable only) must agree.
static void check_pinned_transfers(bool pinned) {
  setenv("RADCL_DEVICE_MEMORY", "separate", 1);
  if (!pinned) setenv("RADCL_PINNED", "0", 1);
  Context ctx(select_device());
  unsetenv("RADCL_DEVICE_MEMORY");
  unsetenv("RADCL_PINNED");
  EXPECT_EQ(ctx.pins(), pinned);
  const std::size_t n = 40, words = 64 * 1024; // 256 KiB each, 10 MiB in all
  std::vector<Buffer> bufs;
  for (std::size_t i = 0; i < n; ++i) {
    bufs.emplace_back(ctx, words * 4);
    std::vector<std::uint32_t> v(words);
    std::iota(v.begin(), v.end(), static_cast<std::uint32_t>(i * 1000));
    bufs.back().write(v.data(), words * 4);
  }
  std::vector<std::vector<std::uint32_t>> got(n, std::vector<std::uint32_t>(words));
  for (std::size_t i = 0; i + 1 < n; ++i)
    bufs[i].read_later(got[i].data(), words * 4);
  // A blocking read: everything queued before it is done and delivered too.
  got[n - 1] = bufs[n - 1].to_vector<std::uint32_t>(words);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < words; k += 997)
      ASSERT_EQ(got[i][k], i * 1000 + k) << i << " " << k;
  // Over 1 MiB: a pageable transfer either way.
  const std::size_t big = 600 * 1024;
  Buffer b(ctx, big * 4);
  std::vector<std::uint32_t> v(big), w(big, 0);
  std::iota(v.begin(), v.end(), 5u);
  b.write(v.data(), big * 4);
  b.read_later(w.data(), big * 4);
  ctx.finish();
  EXPECT_EQ(w, v);
}

TEST(Buffer, SeparateMemoryPinnedTransfers) {
  check_pinned_transfers(true);
}

TEST(Buffer, SeparateMemoryPageableTransfers) {
  check_pinned_transfers(false);
}

// Copies between buffers on the device keep queue order with the writes around them, in
// separate and in shared memory; a copy out of range is an error, not a stray write.
TEST(Buffer, CopiesOnTheDevice) {
  for (const bool separate : {true, false}) {
    if (separate) setenv("RADCL_DEVICE_MEMORY", "separate", 1);
    Context ctx(select_device());
    unsetenv("RADCL_DEVICE_MEMORY");
    EXPECT_EQ(ctx.zero_copy(), !separate && ctx.info().host_unified_memory);
    const std::uint32_t n = 1000;
    std::vector<std::uint32_t> v(n);
    std::iota(v.begin(), v.end(), 0u);
    Buffer a(ctx, n * 4), b(ctx, 2 * n * 4);
    a.write(v.data(), n * 4);
    b.write(std::vector<std::uint32_t>(2 * n, 9u).data(), 2 * n * 4);
    b.copy_from(a, 600 * 4, 100 * 4, 1000 * 4); // a[100..700) to b[1000..1600)
    std::fill(v.begin(), v.end(), 5u);
    a.write(v.data(), n * 4); // after the copy: must not reach b
    std::vector<std::uint32_t> got = b.to_vector<std::uint32_t>(2 * n);
    for (std::uint32_t i = 0; i < 2 * n; ++i)
      ASSERT_EQ(got[i], i >= 1000 && i < 1600 ? i - 900 : 9u) << i;
    EXPECT_THROW(b.copy_from(a, 8, n * 4 - 4), radcl::FatalError);
    EXPECT_THROW(a.copy_from(b, 8, 0, n * 4 - 4), radcl::FatalError);
  }
}

// Where the device shares the host's memory, alloc_pinned gives a zero-copy buffer's own
// allocation and a view of part of it is that memory in place: a kernel's output through the
// view lands in the host's array, with nothing copied. Elsewhere, and for memory not from
// alloc_pinned or at a start a sub-buffer may not have, there is no view (the caller copies).
TEST(Buffer, ViewsOfSharedMemoryAreThatMemory) {
  Context& ctx = test_context();
  const std::uint32_t n = 4096, dims = 1, seed = 7;
  std::vector<std::uint32_t> ordinary(n);
  EXPECT_EQ(Buffer::view(ctx, ordinary.data(), n * 4).handle(), nullptr);
  auto* p = static_cast<std::uint32_t*>(ctx.alloc_pinned(2 * n * 4));
  if (!p) GTEST_SKIP() << "no pinned memory here (RADCL_PINNED=0)";
  if (!ctx.zero_copy()) {
    EXPECT_EQ(Buffer::view(ctx, p, n * 4).handle(), nullptr);
    EXPECT_TRUE(ctx.free_pinned(p));
    GTEST_SKIP() << ctx.info().name << " has its own memory";
  }
  EXPECT_EQ(Buffer::view(ctx, p + 1, n * 4).handle(), nullptr);     // not a sub-buffer's start
  EXPECT_EQ(Buffer::view(ctx, p + n, n * 4 + 4).handle(), nullptr); // past its end
  std::fill(p, p + 2 * n, 0xDEADBEEFu);
  Program prog(ctx, ProgramSource{{"probe/rng.cl"}, "", "-cl-std=CL1.2"});
  Kernel k = prog.kernel("rc_rng_fill");
  Buffer u(ctx, n * 4), ref(ctx, n * 4);
  {
    Buffer v = Buffer::view(ctx, p + n, n * 4); // the second half, in place
    ASSERT_NE(v.handle(), nullptr);
    EXPECT_TRUE(v.zero_copy());
    k.arg(0, v).arg(1, u).arg(2, n).arg(3, dims).arg(4, seed);
    ctx.run(k, n);
    ctx.finish();
  }
  k.arg(0, ref).arg(1, u).arg(2, n).arg(3, dims).arg(4, seed);
  ctx.run(k, n);
  const std::vector<std::uint32_t> want = ref.to_vector<std::uint32_t>(n);
  EXPECT_EQ(std::vector<std::uint32_t>(p + n, p + 2 * n), want);
  EXPECT_EQ(std::vector<std::uint32_t>(p, p + n), std::vector<std::uint32_t>(n, 0xDEADBEEFu));
  EXPECT_TRUE(ctx.free_pinned(p)); // the view is gone; the memory was never its own
}
