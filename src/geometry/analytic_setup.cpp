// Argument checks and conversions for quadric surfaces, following Radiance 5.4a's rules
// (oconv's sphere.c, common/cone.c): negative radii flip sphere<->bubble, cone<->cup,
// cylinder<->tube with a warning; equal cone radii make a cylinder. Degenerate surfaces are
// ignored with a warning: a zero sphere radius ("zero radius"), a zero cylinder radius, cone
// radii that are both zero (or of opposite signs) and equal ring radii ("illegal radii"), a
// zero axis ("unknown orientation"). A negative ring radius is fatal ("negative radii").
#include <cmath>
#include <string>

#include "analytic.h"
#include "radcl/util/error.h"

namespace radcl::geometry {
namespace {

constexpr double kTiny = 1e-6; // Radiance's FTINY: radii this small count as zero

std::string about(const scene::Object& o, scene::ObjectType t) {
  return std::string(" for ") + std::string(scene::type_name(t)) + " \"" + o.name + "\"";
}

scene::ObjectType flipped(scene::ObjectType t) {
  switch (t) {
  case RC_OBJ_SPHERE:
    return RC_OBJ_BUBBLE;
  case RC_OBJ_BUBBLE:
    return RC_OBJ_SPHERE;
  case RC_OBJ_CONE:
    return RC_OBJ_CUP;
  case RC_OBJ_CUP:
    return RC_OBJ_CONE;
  case RC_OBJ_CYLINDER:
    return RC_OBJ_TUBE;
  case RC_OBJ_TUBE:
    return RC_OBJ_CYLINDER;
  default:
    return t;
  }
}

int sign(double r) {
  return r < -kTiny ? -1 : (r > kTiny ? 1 : 0);
}

} // namespace

std::optional<AnalyticSurface> make_analytic(const scene::Object& o, std::int32_t index) {
  AnalyticSurface s;
  s.object = index;
  s.type = o.type;
  const auto& f = o.fargs;
  auto need = [&](std::size_t n) {
    if (f.size() != n) throw FatalError("bad # arguments" + about(o, o.type));
  };
  switch (o.type) {
  case RC_OBJ_SPHERE:
  case RC_OBJ_BUBBLE: {
    need(4);
    double r = f[3];
    if (r < -kTiny) {
      warning("negative radius" + about(o, o.type));
      s.type = flipped(o.type);
      r = -r;
    } else if (r <= kTiny) {
      warning("zero radius" + about(o, o.type));
      return std::nullopt;
    }
    s.shape = Shape::Sphere;
    s.c = {f[0], f[1], f[2]};
    s.r0 = s.r1 = r;
    s.inward = s.type == RC_OBJ_BUBBLE;
    return s;
  }
  case RC_OBJ_CYLINDER:
  case RC_OBJ_TUBE: {
    need(7);
    double r = f[6];
    if (r < -kTiny) {
      warning("negative radius" + about(o, o.type));
      s.type = flipped(o.type);
      r = -r;
    } else if (r <= kTiny) {
      warning("illegal radii" + about(o, o.type));
      return std::nullopt;
    }
    s.r0 = s.r1 = r;
    s.c = {f[0], f[1], f[2]};
    s.axis = sub(Vec3{f[3], f[4], f[5]}, s.c);
    break;
  }
  case RC_OBJ_CONE:
  case RC_OBJ_CUP:
  case RC_OBJ_RING: {
    need(8);
    const int s0 = sign(f[6]), s1 = sign(f[7]);
    if (s0 + s1 == 0) { // both zero, or opposite signs (Radiance tests this first)
      warning("illegal radii" + about(o, o.type));
      return std::nullopt;
    }
    if (s0 < 0 || s1 < 0) {
      if (o.type == RC_OBJ_RING) throw FatalError("negative radii" + about(o, o.type));
      warning("negative radii" + about(o, o.type));
      s.type = flipped(o.type);
    }
    // Radii below the threshold count as exactly zero (a pointed end).
    const double ra = std::abs(f[6]) * (s0 != 0), rb = std::abs(f[7]) * (s1 != 0);
    const Vec3 pa{f[0], f[1], f[2]}, pb{f[3], f[4], f[5]};
    if (o.type == RC_OBJ_RING) {
      if (std::abs(ra - rb) <= kTiny) {
        warning("illegal radii" + about(o, o.type));
        return std::nullopt;
      }
      s.shape = Shape::Ring;
      s.c = pa;
      s.r0 = std::min(ra, rb);
      s.r1 = std::max(ra, rb);
      s.axis = pb;
      const double l = length(s.axis);
      if (l == 0) {
        warning("unknown orientation" + about(o, s.type));
        return std::nullopt;
      }
      s.axis = scale(s.axis, 1 / l);
      return s;
    }
    if (std::abs(ra - rb) <= kTiny) { // equal radii: Radiance makes it a cylinder/tube
      s.type = s.type == RC_OBJ_CONE ? RC_OBJ_CYLINDER : RC_OBJ_TUBE;
      s.r0 = s.r1 = ra;
      s.c = pa;
      s.axis = sub(pb, pa);
    } else if (ra < rb) {
      s.r0 = ra, s.r1 = rb, s.c = pa, s.axis = sub(pb, pa);
    } else {
      s.r0 = rb, s.r1 = ra, s.c = pb, s.axis = sub(pa, pb);
    }
    break;
  }
  default:
    throw FatalError("not a quadric surface" + about(o, o.type));
  }
  s.shape = Shape::Cone;
  s.inward = s.type == RC_OBJ_CUP || s.type == RC_OBJ_TUBE;
  s.length = length(s.axis);
  if (s.length == 0) {
    warning("unknown orientation" + about(o, s.type));
    return std::nullopt;
  }
  s.axis = scale(s.axis, 1 / s.length);
  return s;
}

void shift(AnalyticSurface& s, const Vec3& origin) {
  s.c = sub(s.c, origin);
}

std::array<Vec3, 2> analytic_bounds(const AnalyticSurface& s) {
  std::array<Vec3, 2> b;
  if (s.shape == Shape::Sphere) {
    for (int k = 0; k < 3; ++k)
      b[0][k] = s.c[k] - s.r0, b[1][k] = s.c[k] + s.r0;
    return b;
  }
  // A disc of radius r about axis a spans r * sqrt(1 - a_k^2) along axis k.
  auto disc = [&](const Vec3& centre, double r, std::array<Vec3, 2>& out, bool first) {
    for (int k = 0; k < 3; ++k) {
      const double e = r * std::sqrt(std::max(0.0, 1 - s.axis[k] * s.axis[k]));
      const double lo = centre[k] - e, hi = centre[k] + e;
      out[0][k] = first ? lo : std::min(out[0][k], lo);
      out[1][k] = first ? hi : std::max(out[1][k], hi);
    }
  };
  if (s.shape == Shape::Ring) {
    disc(s.c, s.r1, b, true);
  } else {
    disc(s.c, s.r0, b, true);
    disc(madd(s.c, s.axis, s.length), s.r1, b, false);
  }
  return b;
}

} // namespace radcl::geometry
