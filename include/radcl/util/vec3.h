// Double-precision 3-vectors for host code (geometry, light sources, views): the few
// operations every module needs, defined once.
#pragma once

#include <array>
#include <cmath>

namespace radcl::vec {

using Vec3 = std::array<double, 3>;

inline Vec3 add(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 scale(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
inline Vec3 madd(const Vec3& a, const Vec3& d, double t) {
  return {a[0] + d[0] * t, a[1] + d[1] * t, a[2] + d[2] * t};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
// Unit vector along a; the zero vector stays zero.
inline Vec3 normalized(const Vec3& a) {
  const double l = length(a);
  return l > 0 ? scale(a, 1 / l) : a;
}

} // namespace radcl::vec
