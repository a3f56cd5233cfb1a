// Small helpers the wave pipeline's files share.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device/host_copy.h"
#include "radcl/device_types.h"
#include "radcl/luminance.h"
#include "radcl/render/pipeline/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace radcl::render::pipeline {

inline rc_float4 f4(double x, double y, double z, double w) {
  return rc_float4{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z),
                   static_cast<float>(w)};
}

inline Vec3d unit(const Vec3d& v) {
  double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return l > 0 ? Vec3d{v[0] / l, v[1] / l, v[2] / l} : Vec3d{0, 0, 0};
}

// Exclusive prefix sum; returns the total.
inline std::uint32_t prefix_sum(std::vector<std::uint32_t>& v) {
  std::uint32_t sum = 0;
  for (std::uint32_t& x : v) {
    std::uint32_t c = x;
    x = sum;
    sum += c;
  }
  return sum;
}

template <class T> device::Buffer upload(device::Context& ctx, const std::vector<T>& v) {
  return v.empty() ? device::Buffer(ctx, sizeof(T)) : device::Buffer::from(ctx, v);
}

// Shirley and Chiu's concentric map of the unit square onto the unit disc (as the kernels'
// rc_square_to_disk), for the hemispheres of new records.
inline std::array<double, 2> square_to_disk(double sx, double sy) {
  const double a = 2 * sx - 1, b = 2 * sy - 1;
  if (a == 0 && b == 0) return {0, 0};
  const double q = 3.14159265358979323846 / 4;
  double r, phi;
  if (a * a > b * b) {
    r = a;
    phi = q * (b / a);
  } else {
    r = b;
    phi = 2 * q - q * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

// The cosine-weighted direction about n (tangents ux, uy) of the point (sx, sy) of the unit
// square, by the concentric map: a record's hemisphere samples and their -as super-samples.
inline Vec3d hemisphere_dir(const Vec3d& n, const Vec3d& ux, const Vec3d& uy, double sx,
                            double sy) {
  const auto d = square_to_disk(sx, sy);
  const double z = std::sqrt(std::max(0.0, 1 - d[0] * d[0] - d[1] * d[1]));
  Vec3d dir;
  for (int k = 0; k < 3; ++k)
    dir[k] = d[0] * ux[k] + d[1] * uy[k] + z * n[k];
  return unit(dir);
}

// Runs f(i) for every i in [0, n): in parallel where there are enough to pay for it (the
// per-ray host loops of a wave of millions of hemisphere samples).
template <class F> void for_rows(std::size_t n, const F& f) {
  constexpr std::size_t kGrain = 4096;
  if (n < 2 * kGrain) {
    for (std::size_t i = 0; i < n; ++i)
      f(i);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      f(i);
  });
}

using device::parallel_copy;

// `bytes` from src into the start of `b`; where the device shares the host's memory, straight
// into its allocation with every core.
inline void write_rows(device::Buffer& b, const void* src, std::size_t bytes) {
  if (!b.zero_copy()) {
    b.write_pinned(src, bytes); // from a HitQueue's pinned memory without a copy
    return;
  }
  void* p = b.map();
  parallel_copy(p, src, bytes);
  b.unmap(p);
}

// The first `bytes` of `b` into dst, now (after every command before); with every core where
// the device shares the host's memory.
inline void read_rows(device::Buffer& b, void* dst, std::size_t bytes) {
  if (!b.zero_copy()) {
    b.read(dst, bytes);
    return;
  }
  void* p = b.map();
  parallel_copy(dst, p, bytes);
  b.unmap(p);
}

// Whether lookups in an irradiance cache run: records to look up, -aa > 0 and a bounce.
inline bool uses_cache(const RenderSettings& st) {
  return st.ab > 0 && st.aa > 0 && (st.make_records || !st.ambient_records.empty());
}

// Whether the rays travel in a global medium (-me above zero in some channel, as Radiance
// tests it).
inline bool has_medium(const RenderSettings& st) {
  return std::max({st.me[0], st.me[1], st.me[2]}) > 1e-30;
}

} // namespace radcl::render::pipeline
