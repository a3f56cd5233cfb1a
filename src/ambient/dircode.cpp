#include "radcl/ambient/dircode.h"

#include <algorithm>
#include <cmath>

namespace radcl::ambient {
namespace {

constexpr double kScale = 11584.5; // (2^13 - 0.5) * sqrt(2): the largest stored magnitude fits
constexpr std::uint32_t kNegX = 0x01, kF1X = 0x08, kF2Z = 0x10;
constexpr int kShift1 = 5, kShift2 = 18;
constexpr std::uint32_t kMask = 0x1fff;

} // namespace

std::int32_t encode_dir(const Dir& d) {
  std::uint32_t code = 0;
  int c[3];
  for (int i = 0; i < 3; ++i) {
    // A unit vector's components lie in [-1, 1]. Others (lookamb -r text, a damaged record)
    // are clamped there, and NaN taken as 0, so that the conversion to int stays defined;
    // Radiance's cast overflows for them. In-range values encode exactly as Radiance's do.
    const double m = std::isnan(d[i]) ? 0.0 : std::min(std::fabs(d[i]), 1.0);
    c[i] = static_cast<int>(m * kScale + 0.5);
    if (d[i] < 0.0) code |= kNegX << i;
  }
  if (!(c[0] | c[1] | c[2])) return 0;
  int larger_xy;
  if (c[0] <= c[1]) {
    code |= kF1X | static_cast<std::uint32_t>(c[0]) << kShift1;
    larger_xy = c[1];
  } else {
    code |= static_cast<std::uint32_t>(c[1]) << kShift1;
    larger_xy = c[0];
  }
  if (c[2] <= larger_xy)
    code |= kF2Z | static_cast<std::uint32_t>(c[2]) << kShift2;
  else
    code |= static_cast<std::uint32_t>(larger_xy) << kShift2;
  if (!code) code = kF1X;
  return static_cast<std::int32_t>(code);
}

Dir decode_dir(std::int32_t code) {
  if (!code) return {0.0, 0.0, 0.0};
  const auto u = static_cast<std::uint32_t>(code);
  // Multiply by the reciprocal, as Radiance does, so printed values match to the last digit.
  const double a = static_cast<double>(u >> kShift1 & kMask) * (1.0 / kScale);
  const double b = static_cast<double>(u >> kShift2 & kMask) * (1.0 / kScale);
  const double r = std::sqrt(1.0 - a * a - b * b);
  // Which axis each value lands on, indexed by (F2Z, F1X).
  static constexpr int kAxes[4][3] = {{1, 0, 2}, {0, 1, 2}, {1, 2, 0}, {0, 2, 1}};
  const int k = ((u & kF2Z) ? 2 : 0) | ((u & kF1X) ? 1 : 0);
  Dir d{};
  d[kAxes[k][0]] = a;
  d[kAxes[k][1]] = b;
  d[kAxes[k][2]] = r;
  for (int i = 0; i < 3; ++i)
    d[i] *= (u & (kNegX << i)) ? -1.0 : 1.0;
  return d;
}

} // namespace radcl::ambient
