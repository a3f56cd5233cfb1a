// Exact ray/quadric intersection in double precision. Quadratics are solved in the
// cancellation-free form (half-b, q = -(b + sign(b) sqrt(disc)), roots q/a and c/q), and the
// sphere's discriminant is taken from the ray's closest approach so that tangent and distant
// rays keep their precision.
#include <algorithm>
#include <cmath>

#include "analytic.h"

namespace radcl::geometry {
namespace {

constexpr double kParallel = 1e-6; // Radiance's FTINY for |cos| of rays parallel to a plane

// Roots of a t^2 + 2 b t + c = 0 given its discriminant b^2 - a c; ascending. Returns count.
int roots(double a, double b, double c, double disc, double r[2]) {
  if (disc < 0) return 0;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  if (q == 0) { // b = 0 and disc = 0, hence c = 0: a double root at 0
    r[0] = r[1] = 0;
    return 2;
  }
  r[0] = q / a;
  r[1] = c / q;
  // |q / a| is the larger root's size. Where q is tiny (a ray tangent to the surface at its
  // start), c / q is rounding noise over rounding noise (a ray leaving a sphere along its
  // tangent plane "hit" it at t = 1): then the direct form is the precise one.
  if (!(std::abs(r[1]) <= std::abs(r[0]))) r[1] = (std::copysign(std::sqrt(disc), b) - b) / a;
  if (r[0] > r[1]) std::swap(r[0], r[1]);
  return 2;
}

bool sphere(const AnalyticSurface& s, const Vec3& o, const Vec3& d, double tmin, double tmax,
            double& t, Vec3& n, double on) {
  const Vec3 f = sub(o, s.c);
  const double a = dot(d, d), b = dot(f, d);
  const Vec3 l = madd(f, d, -b / a); // closest approach to the centre
  double disc = a * (s.r0 - length(l)) * (s.r0 + length(l));
  double c = dot(f, f) - s.r0 * s.r0;
  if (std::abs(length(f) - s.r0) <= on) { // the origin is on the sphere: roots 0 and -2b/a
    c = 0;
    disc = b * b;
  }
  double r[2];
  const int nr = roots(a, b, c, disc, r);
  for (int i = 0; i < nr; ++i) {
    if (!(r[i] > tmin && r[i] < tmax)) continue;
    t = r[i];
    n = normalized(madd(f, d, t));
    if (s.inward) n = scale(n, -1);
    return true;
  }
  return false;
}

// Cones and cylinders: points at height h along the axis from the small end lie at distance
// r0 + k h from it, k = (r1 - r0) / length.
bool cone(const AnalyticSurface& s, const Vec3& o, const Vec3& d, double tmin, double tmax,
          double& t, Vec3& n, double on) {
  const Vec3 f = sub(o, s.c);
  const double k = (s.r1 - s.r0) / s.length;
  const double h0 = dot(f, s.axis), hd = dot(d, s.axis);
  const Vec3 q0 = madd(f, s.axis, -h0), qd = madd(d, s.axis, -hd);
  const double rr = s.r0 + k * h0;
  const double a = dot(qd, qd) - k * k * hd * hd;
  const double b = dot(q0, qd) - rr * k * hd;
  double c = dot(q0, q0) - rr * rr;
  // The origin on the side (within `on`, measured across the axis): one root is 0.
  const bool on_side = std::abs(length(q0) - rr) <= on && h0 >= -on && h0 <= s.length + on;
  if (on_side) c = 0;
  double r[2];
  int nr = 0;
  if (std::abs(a) <= 1e-12 * dot(d, d)) { // along the side (cone) or the axis (cylinder)
    if (std::abs(b) <= 1e-15 * (std::abs(c) + dot(d, d))) return false;
    r[0] = -c / (2 * b);
    nr = 1;
  } else {
    double disc = b * b - a * c;
    if (k == 0 && !on_side) { // cylinder: from the closest approach to the axis, as for spheres
      const double l = length(madd(q0, qd, -b / a));
      disc = a * (rr - l) * (rr + l);
    }
    nr = roots(a, b, c, disc, r);
  }
  for (int i = 0; i < nr; ++i) {
    if (!(r[i] > tmin && r[i] < tmax)) continue;
    const Vec3 p = madd(f, d, r[i]);
    const double h = dot(p, s.axis);
    if (h < 0 || h > s.length) continue; // open ends
    t = r[i];
    const Vec3 radial = madd(p, s.axis, -h);
    n = normalized(madd(radial, s.axis, -(s.r0 + k * h) * k));
    if (dot(n, n) == 0) n = scale(s.axis, -1); // the apex itself
    if (s.inward) n = scale(n, -1);
    return true;
  }
  return false;
}

bool ring(const AnalyticSurface& s, const Vec3& o, const Vec3& d, double tmin, double tmax,
          double& t, Vec3& n, double on) {
  const double den = dot(d, s.axis);
  if (std::abs(den) <= kParallel * length(d)) return false;
  const Vec3 f = sub(o, s.c);
  if (std::abs(dot(f, s.axis)) <= on) return false; // starts in the ring's plane
  const double tt = -dot(f, s.axis) / den;
  if (!(tt > tmin && tt < tmax)) return false;
  const Vec3 p = madd(f, d, tt);
  const Vec3 w = madd(p, s.axis, -dot(p, s.axis));
  const double rho2 = dot(w, w);
  if (rho2 < s.r0 * s.r0 || rho2 > s.r1 * s.r1) return false;
  t = tt;
  n = s.axis;
  return true;
}

} // namespace

bool intersect_analytic(const AnalyticSurface& s, const Vec3& o, const Vec3& d, double tmin,
                        double tmax, double& t, Vec3& n, double on) {
  switch (s.shape) {
  case Shape::Sphere:
    return sphere(s, o, d, tmin, tmax, t, n, on);
  case Shape::Cone:
    return cone(s, o, d, tmin, tmax, t, n, on);
  case Shape::Ring:
    return ring(s, o, d, tmin, tmax, t, n, on);
  }
  return false;
}

} // namespace radcl::geometry
