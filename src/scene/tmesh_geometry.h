// The geometry of obj2mesh's steps that mesh_writer.cpp follows: vector helpers, Radiance's
// direction code for vertex normals, a triangle as cvtri leaves it and o_face's test of a
// triangle against an octree cube.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace radcl::scene::tmesh {

using V3 = std::array<double, 3>;
constexpr double kFtiny = 1e-6;

inline V3 sub(const V3& a, const V3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline bool normalize(V3& v) {
  const double len = std::sqrt(dot(v, v));
  if (len == 0) return false;
  for (double& c : v)
    c /= len;
  return true;
}

// Radiance's 4-byte direction code (dircode.c): the two smaller components as 13-bit
// magnitudes with flags naming their axes, signs in the low bits; never 0 ("no normal").
inline std::int32_t encode_direction(const V3& d) {
  constexpr double kScale = 11584.5; // ((1 << 13) - .5) * sqrt(2)
  std::uint32_t dc = 0;
  int cd[3];
  for (int i = 0; i < 3; ++i) {
    cd[i] = static_cast<int>(std::abs(d[i]) * kScale + .5);
    if (d[i] < 0) dc |= 1u << i;
  }
  if (!(cd[0] | cd[1] | cd[2])) return 0;
  int largest;
  if (cd[0] <= cd[1]) {
    dc |= 010u | static_cast<std::uint32_t>(cd[0]) << 5;
    largest = cd[1];
  } else {
    dc |= static_cast<std::uint32_t>(cd[1]) << 5;
    largest = cd[0];
  }
  if (cd[2] <= largest)
    dc |= 020u | static_cast<std::uint32_t>(cd[2]) << 18;
  else
    dc |= static_cast<std::uint32_t>(largest) << 18;
  return static_cast<std::int32_t>(dc ? dc : 010u);
}

// A triangle as obj2mesh's cvtri leaves it: corners possibly turned over, flags decided.
struct Tri {
  std::uint32_t source;
  std::array<std::uint32_t, 3> vertex;
  std::array<V3, 3> normal;
  int flags;
  std::int32_t material;
  V3 unit_normal;
  double offset; // plane: dot(unit_normal, x) == offset
};

// Does the triangle touch the cube grown by FTINY (obj2mesh's o_face)? A separating-axis
// test; the plane axis keeps o_face's extra FTINY of tolerance.
inline bool touches_cube(const std::array<V3, 3>& p, const Tri& t, const V3& org, double size) {
  V3 c, v[3];
  const double h = size * 0.5 + kFtiny;
  for (int k = 0; k < 3; ++k)
    c[k] = org[k] + size * 0.5;
  for (int i = 0; i < 3; ++i)
    v[i] = sub(p[i], c);
  for (int k = 0; k < 3; ++k) {
    const double lo = std::min({v[0][k], v[1][k], v[2][k]});
    const double hi = std::max({v[0][k], v[1][k], v[2][k]});
    if (lo > h || hi < -h) return false;
  }
  const V3& n = t.unit_normal;
  const double r = h * (std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]));
  if (std::abs(dot(n, c) - t.offset) > r + kFtiny) return false;
  for (int e = 0; e < 3; ++e) {
    const V3 edge = sub(v[(e + 1) % 3], v[e]);
    for (int k = 0; k < 3; ++k) {
      V3 axis{0, 0, 0};
      axis[k] = 1;
      const V3 a = cross(edge, axis);
      const double ra = h * (std::abs(a[0]) + std::abs(a[1]) + std::abs(a[2]));
      const double d0 = dot(a, v[0]), d1 = dot(a, v[1]), d2 = dot(a, v[2]);
      if (std::min({d0, d1, d2}) > ra || std::max({d0, d1, d2}) < -ra) return false;
    }
  }
  return true;
}

} // namespace radcl::scene::tmesh
