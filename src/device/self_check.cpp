#include "radcl/device/self_check.h"

#include <cstddef>

#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device/program.h"
#include "radcl/device_types.h"
#include "radcl/rng.h"

namespace radcl::device {

std::vector<std::string> check_layout(Context& ctx) {
  std::vector<std::uint64_t> host;
  std::vector<std::string> what;
#define RC_SIZE(T)                                                                                 \
  host.push_back(sizeof(T));                                                                       \
  what.push_back("sizeof(" #T ")");
#define RC_FIELD(T, f)                                                                             \
  host.push_back(offsetof(T, f));                                                                  \
  what.push_back("offsetof(" #T ", " #f ")");
  RADCL_LAYOUT_STRUCTS(RC_SIZE)
  RADCL_LAYOUT_FIELDS(RC_FIELD)
#undef RC_SIZE
#undef RC_FIELD

  Program prog(ctx, ProgramSource{{"probe/layout.cl"}, "", "-cl-std=CL1.2"});
  Kernel k = prog.kernel("rc_layout");
  Buffer out = Buffer::from(ctx, std::vector<std::uint64_t>(host.size(), ~0ull));
  k.arg(0, out).arg(1, static_cast<std::uint32_t>(host.size()));
  ctx.run(k, 1);
  std::vector<std::uint64_t> dev = out.to_vector<std::uint64_t>(host.size());
  std::vector<std::string> bad;
  for (std::size_t i = 0; i < host.size(); ++i)
    if (dev[i] != host[i])
      bad.push_back(what[i] + ": host " + std::to_string(host[i]) + ", device " +
                    std::to_string(dev[i]));
  return bad;
}

std::vector<std::string> check_rng(Context& ctx, std::uint32_t n, std::uint32_t dims,
                                   std::uint32_t seed) {
  Program prog(ctx, ProgramSource{{"probe/rng.cl"}, "", "-cl-std=CL1.2"});
  Kernel k = prog.kernel("rc_rng_fill");
  Buffer bits(ctx, std::size_t{n} * dims * 4), unit(ctx, std::size_t{n} * dims * 4);
  k.arg(0, bits).arg(1, unit).arg(2, n).arg(3, dims).arg(4, seed);
  ctx.run(k, n);
  auto dbits = bits.to_vector<std::uint32_t>(std::size_t{n} * dims);
  auto dunit = unit.to_vector<float>(std::size_t{n} * dims);
  std::vector<std::string> bad;
  for (std::uint32_t i = 0; i < n; ++i) {
    rc_rng_key key = rc_make_key(i, i / 7, i % 5, seed); // as kernels/probe/rng.cl keys them
    for (std::uint32_t d = 0; d < dims; ++d) {
      rc_u32x4 b = rc_random_bits(key, d >> 2);
      std::size_t j = std::size_t{i} * dims + d;
      if ((dbits[j] != b.v[d & 3] || dunit[j] != rc_random(key, d)) && bad.size() < 10)
        bad.push_back("item " + std::to_string(i) + " dimension " + std::to_string(d) +
                      ": host and device random numbers differ");
    }
  }
  return bad;
}

} // namespace radcl::device
