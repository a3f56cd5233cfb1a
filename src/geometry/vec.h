// Small double-precision vector and affine helpers for the geometry module (row-vector
// convention throughout, as Radiance's transforms: p' = p * L + t).
#pragma once

#include <array>
#include <cmath>

#include "radcl/util/vec3.h"

namespace radcl::geometry {

using Vec3 = vec::Vec3;
using vec::add;
using vec::cross;
using vec::dot;
using vec::length;
using vec::madd;
using vec::normalized;
using vec::scale;
using vec::sub;

struct Affine {
  std::array<Vec3, 3> l{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; // rows
  Vec3 t{0, 0, 0};

  Vec3 vector(const Vec3& v) const {
    return {v[0] * l[0][0] + v[1] * l[1][0] + v[2] * l[2][0],
            v[0] * l[0][1] + v[1] * l[1][1] + v[2] * l[2][1],
            v[0] * l[0][2] + v[1] * l[1][2] + v[2] * l[2][2]};
  }
  Vec3 point(const Vec3& p) const { return add(vector(p), t); }
  // This transform followed by `next`.
  Affine then(const Affine& next) const {
    Affine r;
    for (int i = 0; i < 3; ++i)
      r.l[i] = next.vector(l[i]);
    r.t = next.point(t);
    return r;
  }
  Affine inverse() const {
    const Vec3 c0 = cross(l[1], l[2]), c1 = cross(l[2], l[0]), c2 = cross(l[0], l[1]);
    const double det = dot(l[0], c0);
    Affine r;
    // Inverse of a row-vector matrix: columns of the cofactors over the determinant.
    for (int i = 0; i < 3; ++i) {
      r.l[i][0] = c0[i] / det;
      r.l[i][1] = c1[i] / det;
      r.l[i][2] = c2[i] / det;
    }
    r.t = scale(r.vector(t), -1);
    return r;
  }
  static Affine translation(const Vec3& d) {
    Affine a;
    a.t = d;
    return a;
  }
};

} // namespace radcl::geometry
