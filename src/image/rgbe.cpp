#include "radcl/image/rgbe.h"

#include <cmath>

namespace radcl::image {

Rgbe to_rgbe(double r, double g, double b) {
  double m = r > g ? r : g;
  if (b > m) m = b;
  if (m <= 1e-32 || std::isnan(m)) return {0, 0, 0, 0};
  if (std::isinf(m)) { // Radiance's conversion is undefined here: saturate infinite channels
    auto sat = [](double v) {
      return static_cast<std::uint8_t>(v > 0.0 && std::isinf(v) ? 255 : 0);
    };
    return {sat(r), sat(g), sat(b), 255};
  }
  int e = 0;
  // frexp puts m in [0.5, 1) * 2^e, so scaling by frac*256/m maps the largest channel to
  // [128, 256). Truncation goes through int, as the C conversion in Radiance does on the
  // machines it runs on (an out-of-range exponent wraps rather than saturates).
  const double scale = std::frexp(m, &e) * 256.0 / m;
  auto code = [scale](double v) {
    return static_cast<std::uint8_t>(v > 0.0 ? static_cast<int>(v * scale) : 0);
  };
  return {code(r), code(g), code(b), static_cast<std::uint8_t>(e + 128)};
}

Color to_color(const Rgbe& p) {
  if (p[3] == 0) return {0.0f, 0.0f, 0.0f};
  const double f = std::ldexp(1.0, static_cast<int>(p[3]) - 136);
  return {static_cast<float>((p[0] + 0.5) * f), static_cast<float>((p[1] + 0.5) * f),
          static_cast<float>((p[2] + 0.5) * f)};
}

} // namespace radcl::image
