// Transform arguments with xform's semantics (../shared/docs/radiance/scene-format.md §1.3).
#include "radcl/scene/transform.h"

#include <cmath>
#include <numbers>

#include "radcl/util/error.h"
#include "words.h"

namespace radcl::scene {
namespace {

using Mat4 = std::array<std::array<double, 4>, 4>;

constexpr Mat4 kIdentity{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        r[i][j] += a[i][k] * b[k][j];
  return r;
}

// Rotation by `deg` about axis a (0 x, 1 y, 2 z), counter-clockwise seen from +axis, for row
// vectors: the (b, c) = the other two axes in cyclic order get b' = b cos - c sin,
// c' = b sin + c cos.
Mat4 rotation(int a, double deg) {
  double t = deg * (std::numbers::pi / 180.0);
  int b = (a + 1) % 3, c = (a + 2) % 3;
  Mat4 m = kIdentity;
  m[b][b] = m[c][c] = std::cos(t);
  m[b][c] = std::sin(t);
  m[c][b] = -std::sin(t);
  return m;
}

// An option word must be exactly its letters (xform rejects "-tx", "-rxy").
bool option_is(const std::string& w, const char* name) {
  return w == name;
}

} // namespace

std::size_t transform_prefix(const std::vector<std::string>& args, std::size_t first,
                             Transform& out) {
  out = Transform{};
  Mat4 group = kIdentity; // options since the last -i
  double group_scale = 1;
  long long repeat = 1; // times `group` is applied (everything before the first -i: once)

  // `n` following words must exist and be reals (or an integer for -i).
  auto have = [&](std::size_t i, std::size_t n, bool integer = false) {
    if (i + n >= args.size()) return false;
    for (std::size_t k = 1; k <= n; ++k) {
      const std::string& w = args[i + k];
      if (integer ? !detail::is_int_word(w, true) : !detail::is_real_word(w, true)) return false;
      // A real that overflows ("1e999") would put Inf into the matrix, as xform's atof does.
      if (!integer && !std::isfinite(detail::real_value(w))) return false;
    }
    return true;
  };
  auto flush = [&] {
    // Repeated products as xform does them; a huge count (which would make xform spin) is
    // done by squaring instead.
    Mat4 g = group;
    double gs = group_scale;
    if (repeat > 4096) {
      for (; repeat > 0; repeat >>= 1, g = multiply(g, g), gs *= gs)
        if (repeat & 1) out.m = multiply(out.m, g), out.scale *= gs;
    }
    for (; repeat > 0; --repeat) {
      out.m = multiply(out.m, g);
      out.scale *= gs;
    }
  };
  auto real = [&](std::size_t i) { return detail::real_value(args[i]); };

  std::size_t i = first;
  for (; i < args.size() && !args[i].empty() && args[i][0] == '-'; ++i) {
    const std::string& w = args[i];
    Mat4 m = kIdentity;
    if (option_is(w, "-t")) {
      if (!have(i, 3)) break;
      m[3] = {real(i + 1), real(i + 2), real(i + 3), 1};
      i += 3;
    } else if (option_is(w, "-rx") || option_is(w, "-ry") || option_is(w, "-rz")) {
      if (!have(i, 1)) break;
      m = rotation(w[2] - 'x', real(i + 1));
      i += 1;
    } else if (option_is(w, "-s")) {
      if (!have(i, 1)) break;
      double s = real(i + 1);
      if (s == 0.0) break; // ends the transform, "-s" not consumed
      m[0][0] = m[1][1] = m[2][2] = s;
      group_scale *= s;
      i += 1;
    } else if (option_is(w, "-mx") || option_is(w, "-my") || option_is(w, "-mz")) {
      int a = w[2] - 'x';
      m[a][a] = -1;
      group_scale *= -1;
    } else if (option_is(w, "-i")) {
      if (!have(i, 1, true)) break;
      flush();
      repeat = detail::int_value(args[i + 1]);
      group = kIdentity;
      group_scale = 1;
      i += 1;
      continue;
    } else {
      break;
    }
    group = multiply(group, m); // later options apply after earlier ones (row vectors)
  }
  flush();
  out.scale = std::fabs(out.scale);
  // Products that overflow or underflow (-s 1e300 -s 1e300, a huge -i count) make no transform:
  // nothing is consumed, so the caller reports a bad transform.
  bool finite = std::isfinite(out.scale) && out.scale > 0;
  for (const auto& row : out.m)
    for (double x : row)
      finite = finite && std::isfinite(x);
  if (!finite) {
    out = Transform{};
    return first;
  }
  return i;
}

Transform parse_transform(const std::vector<std::string>& args, std::size_t first) {
  Transform t;
  if (first >= args.size()) return t;
  if (transform_prefix(args, first, t) != args.size()) throw FatalError("bad transform");
  return t;
}

std::array<double, 3> Transform::point(const std::array<double, 3>& p) const {
  std::array<double, 3> r{};
  for (int j = 0; j < 3; ++j)
    r[j] = p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j];
  return r;
}

std::array<double, 3> Transform::vector(const std::array<double, 3>& v) const {
  std::array<double, 3> r{};
  for (int j = 0; j < 3; ++j)
    r[j] = v[0] * m[0][j] + v[1] * m[1][j] + v[2] * m[2][j];
  return r;
}

Transform Transform::inverse() const {
  // The matrices are affine (last column 0 0 0 1): invert the 3x3 part by cofactors, then
  // the translation row becomes -t * A^-1.
  const auto& a = m;
  double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  if (det == 0.0) throw FatalError("singular transform");
  double d = 1.0 / det;
  Transform r;
  r.m[0] = {c00 * d, (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * d,
            (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * d, 0};
  r.m[1] = {c01 * d, (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * d,
            (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * d, 0};
  r.m[2] = {c02 * d, (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * d,
            (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * d, 0};
  for (int j = 0; j < 3; ++j)
    r.m[3][j] = -(a[3][0] * r.m[0][j] + a[3][1] * r.m[1][j] + a[3][2] * r.m[2][j]);
  r.m[3][3] = 1;
  r.scale = 1.0 / scale;
  return r;
}

bool Transform::is_identity() const {
  return m == kIdentity && scale == 1.0;
}

} // namespace radcl::scene
