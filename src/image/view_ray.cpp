#include "radcl/image/view_ray.h"

#include <cmath>
#include <numbers>

namespace radcl::image {
namespace {

Vec3 add(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3 scale(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
double length(const Vec3& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}
Vec3 unit(const Vec3& a) {
  double l = length(a);
  return l > 0 ? scale(a, 1 / l) : a;
}
Vec3 combine(double a, const Vec3& A, double b, const Vec3& B, double c, const Vec3& C) {
  return {a * A[0] + b * B[0] + c * C[0], a * A[1] + b * B[1] + c * C[1],
          a * A[2] + b * B[2] + c * C[2]};
}

} // namespace

std::optional<ViewRay> view_ray(const options::View& v, double x, double y) {
  constexpr double pi = std::numbers::pi;
  const double xp = x + v.shift - 0.5, yp = y + v.lift - 0.5;
  const Vec3& D = v.direction;
  ViewRay r;
  switch (v.type) {
  case 'l': { // parallel: origins move across the image plane
    r.org = add(v.point, combine(v.fore, D, xp, v.hvec, yp, v.vvec));
    r.dir = D;
    if (v.aft > 0) r.maxlen = v.aft - v.fore;
    return r;
  }
  case 'v': { // perspective
    Vec3 d = combine(1, D, xp, v.hvec, yp, v.vvec);
    r.org = add(v.point, scale(d, v.fore));
    double len = length(d);
    r.dir = scale(d, 1 / len);
    if (v.aft > 0) r.maxlen = (v.aft - v.fore) * len;
    return r;
  }
  case 'h': { // hemispherical fisheye
    double z = 1 - xp * xp * v.hn2 - yp * yp * v.vn2;
    if (z < 0) return std::nullopt;
    r.dir = combine(std::sqrt(z), D, xp, v.hvec, yp, v.vvec);
    r.org = add(v.point, scale(r.dir, v.fore));
    if (v.aft > 0) r.maxlen = v.aft - v.fore;
    return r;
  }
  case 'c': { // cylindrical panorama: hvec is the unit horizontal axis here
    double theta = xp * v.horiz * pi / 180;
    Vec3 d = combine(std::cos(theta), D, std::sin(theta), v.hvec, yp, v.vvec);
    r.org = add(v.point, scale(d, v.fore));
    double len = length(d);
    r.dir = scale(d, 1 / len);
    if (v.aft > 0) r.maxlen = (v.aft - v.fore) * len;
    return r;
  }
  case 'a': { // angular fisheye
    double xa = xp * v.horiz / 180, ya = yp * v.vert / 180;
    double rad = std::sqrt(xa * xa + ya * ya);
    if (rad > 1) return std::nullopt;
    double z = std::cos(pi * rad);
    double s = rad > 1e-9 ? std::sin(pi * rad) / rad : pi;
    r.dir = unit(combine(z, D, s * xa, v.hvec, s * ya, v.vvec));
    r.org = add(v.point, scale(r.dir, v.fore));
    if (v.aft > 0) r.maxlen = v.aft - v.fore;
    return r;
  }
  case 's': { // stereographic (planisphere) fisheye
    double xs = xp * std::sqrt(v.hn2), ys = yp * std::sqrt(v.vn2);
    double d2 = xs * xs + ys * ys;
    double z = (1 - d2) / (1 + d2);
    r.dir = unit(combine(z, D, (1 + z) * xs, v.hvec, (1 + z) * ys, v.vvec));
    r.org = add(v.point, scale(r.dir, v.fore));
    if (v.aft > 0) r.maxlen = v.aft - v.fore;
    return r;
  }
  default:
    return std::nullopt;
  }
}

double view_aspect(const options::View& v) {
  return std::sqrt(v.vn2 / v.hn2);
}

double normalize_aspect(double va, int& xres, int& yres, double pa) {
  if (pa <= 1e-6) return va * xres / yres;
  if (va * xres > pa * yres)
    xres = static_cast<int>(yres / va * pa + 0.5);
  else
    yres = static_cast<int>(xres * va / pa + 0.5);
  return pa;
}

} // namespace radcl::image
