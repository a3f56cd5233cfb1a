// Light-source set-up after Radiance's marksources() and its per-surface set-up functions
// (srcsupp.c): which surfaces are sources, Radiance's checks and messages, and the geometry the
// sampling kernels need.
#include "radcl/render/lights/light_sources.h"
#include "radcl/util/vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "radcl/geometry/triangulate.h"
#include "radcl/scene/material_chain.h"
#include "radcl/scene/object_type.h"
#include "radcl/util/error.h"

namespace radcl::render {
namespace {

using V3 = std::array<double, 3>;
using namespace radcl::vec;
using P2 = std::array<double, 2>;
constexpr double kTiny = 1e-6; // Radiance's FTINY
constexpr double kPi = std::numbers::pi;

V3 arg3(const std::vector<double>& f, std::size_t i) {
  return {f[i], f[i + 1], f[i + 2]};
}

// A unit vector perpendicular to n (deterministic, unlike Radiance's random one).
V3 perpendicular(const V3& n) {
  const V3 axis =
      std::abs(n[0]) < 0.6 ? V3{1, 0, 0} : (std::abs(n[1]) < 0.6 ? V3{0, 1, 0} : V3{0, 0, 1});
  return normalized(cross(axis, n));
}

// Radiance's getperpendicular() without randomizing (-u-): the last axis, scanning z, y, x, on
// which n is under 0.6, crossed with n. Rings use it so that their partition cells (and so
// which of them a spotlight's cone keeps) lie where Radiance's do.
V3 radiance_perpendicular(const V3& n) {
  for (int i = 2; i >= 0; --i)
    if (std::abs(n[i]) < 0.6) {
      V3 axis{0, 0, 0};
      axis[i] = 1;
      return normalized(cross(axis, n));
    }
  return perpendicular(n);
}

rc_float4 f4(const V3& v, double w) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]),
          static_cast<float>(w)};
}

// Radiance's objerror() text: "<msg> for <type> \"<name>\"".
std::string about(const scene::Object& o, const std::string& msg) {
  return msg + " for " + std::string(scene::type_name(o.type)) + " \"" + o.name + "\"";
}

// Radiance's inface(): crossing test in the coordinate plane most nearly perpendicular to the
// normal, a point on an edge counting as inside.
bool in_face(const V3& p, const std::vector<V3>& v, const V3& n) {
  int ax = std::abs(n[1]) > std::abs(n[0]) ? 1 : 0;
  if (std::abs(n[2]) > std::abs(n[ax])) ax = 2;
  const int xi = (ax + 1) % 3, yi = (ax + 2) % 3;
  auto releq = [](double a, double b) {
    return std::abs(a - b) <= kTiny * 0.5 * (std::abs(a) + std::abs(b));
  };
  const double x = p[xi], y = p[yi];
  int ncross = 0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const V3 &p0 = v[j], &p1 = v[i];
    if ((p0[yi] > y) != (p1[yi] > y)) {
      const int tst = (p0[xi] > x) + (p1[xi] > x);
      if (tst == 2) {
        ++ncross;
      } else if (tst) {
        const double a = (p0[yi] - y) * (p1[xi] - x), b = (p0[xi] - x) * (p1[yi] - y);
        if (releq(a, b)) return true;
        ncross += (p1[yi] > p0[yi]) != (a > b);
      } else if (releq(p0[xi], x) && releq(p1[xi], x)) {
        return true;
      }
    } else if (releq(p0[yi], y) && releq(p1[yi], y) && ((p0[xi] > x) != (p1[xi] > x))) {
      return true;
    }
  }
  return ncross & 1;
}

// Andrew's monotone chain; counter-clockwise hull.
std::vector<P2> convex_hull(std::vector<P2> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  auto turn = [](const P2& o, const P2& a, const P2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<P2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0)
      --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(h[k - 2], h[k - 1], p[i]) <= 0)
      --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

class Compiler {
public:
  Compiler(const scene::SceneDescription& s, const geometry::SceneGeometry& g,
           const std::function<std::uint32_t(std::int32_t)>& idx)
      : scene_(s), centre_(g.centre()), index_(idx) {}

  CompiledSources run() {
    for (std::size_t i = 0; i < scene_.objects.size(); ++i)
      visit(static_cast<std::int32_t>(i));
    return std::move(out_);
  }

private:
  const scene::SceneDescription& scene_;
  V3 centre_;
  const std::function<std::uint32_t(std::int32_t)>& index_;
  CompiledSources out_;

  V3 local(const V3& p) const { return sub(p, centre_); }

  void visit(std::int32_t obj) {
    const scene::Object& o = scene_.objects[obj];
    if (!scene::is_surface(o.type) || o.modifier == scene::kVoid) return;
    const std::int32_t m = scene::first_material(scene_, obj);
    if (m == scene::kVoid || !scene::is_light(scene_.objects[m].type)) return;
    const scene::Object& mat = scene_.objects[m];
    // Radiance checks the material's arguments before deciding whether it is worth a source.
    const std::size_t nargs = mat.type == RC_OBJ_GLOW ? 4 : mat.type == RC_OBJ_SPOTLIGHT ? 7 : 3;
    if (mat.fargs.size() != nargs) throw FatalError(about(mat, "bad # arguments"));
    if (!scene::is_light_source(scene_, obj)) return;

    rc_source s{};
    s.surface = RC_NONE;
    s.parent = s.mirror = RC_NONE;
    s.verts = 0;
    s.spot = {0, 0, 0, -2};
    switch (o.type) {
    case RC_OBJ_SOURCE:
      set_distant(o, s);
      break;
    case RC_OBJ_SPHERE:
      set_sphere(o, s);
      break;
    case RC_OBJ_POLYGON:
      set_polygon(o, s);
      break;
    case RC_OBJ_RING:
      set_ring(o, s);
      break;
    case RC_OBJ_CYLINDER:
      set_cylinder(o, s);
      break;
    default: // cone, cup, bubble, tube, instance, mesh: no source set-up in Radiance
      throw FatalError(about(o, "illegal material"));
    }
    if (o.type != RC_OBJ_SOURCE) s.surface = index_(obj);
    s.emit = f4({mat.fargs[0], mat.fargs[1], mat.fargs[2]}, 0);
    if (mat.type == RC_OBJ_ILLUM) s.flags |= RC_SRCF_ILLUM;
    if (mat.type == RC_OBJ_GLOW) {
      s.flags |= RC_SRCF_GLOW;
      s.emit.w = static_cast<float>(mat.fargs[3]);
    }
    if (mat.type == RC_OBJ_SPOTLIGHT && !set_spot(o, mat, s)) return;
    out_.sources.push_back(s);
    out_.names.push_back(o.name);
    out_.object_surface.push_back(index_(obj));
  }

  // Radiance's makespot() and checkspot(); false when the source is to be skipped.
  bool set_spot(const scene::Object& o, const scene::Object& mat, rc_source& s) {
    if (s.kind == RC_SRC_DISTANT) warning(about(o, "distant source is a spotlight"));
    if (mat.fargs[3] <= kTiny) throw FatalError(about(mat, "zero angle"));
    const V3 aim = arg3(mat.fargs, 4);
    const double flen = length(aim);
    if (flen == 0) throw FatalError(about(mat, "zero focus vector"));
    const V3 dir = scale(aim, 1 / flen);
    const double cosh = std::cos(mat.fargs[3] * (kPi / 360));
    s.flags |= RC_SRCF_SPOT;
    s.spot = f4(dir, cosh);
    s.spot_focus = static_cast<float>(flen);
    if (s.kind == RC_SRC_FLAT) {
      // Valid if the cone's axis is in front of the surface or the cone reaches its horizon.
      const double d = dot(dir, {s.axis.x, s.axis.y, s.axis.z});
      if (!(d > kTiny || 1 - kTiny - d * d < cosh * cosh)) {
        warning(about(o, "invalid spotlight direction"));
        return false;
      }
    }
    return true;
  }

  void set_distant(const scene::Object& o, rc_source& s) {
    if (o.fargs.size() != 4) throw FatalError(about(o, "bad arguments"));
    const V3 d = normalized(arg3(o.fargs, 0));
    if (length(d) == 0) throw FatalError(about(o, "zero direction"));
    const double theta = kPi / 360 * o.fargs[3];
    if (theta <= kTiny) throw FatalError(about(o, "zero size"));
    const double omega = 2 * kPi * (1 - std::cos(theta));
    s.kind = RC_SRC_DISTANT;
    s.pos = f4(d, std::sqrt(omega / kPi));
    s.axis = f4(d, omega);
  }

  void set_sphere(const scene::Object& o, rc_source& s) {
    if (o.fargs.size() != 4) throw FatalError(about(o, "bad # arguments"));
    if (o.fargs[3] <= kTiny) throw FatalError(about(o, "illegal source radius"));
    s.kind = RC_SRC_SPHERE;
    s.pos = f4(local(arg3(o.fargs, 0)), o.fargs[3]);
    s.axis = f4({0, 0, 0}, kPi * o.fargs[3] * o.fargs[3]);
  }

  void set_ring(const scene::Object& o, rc_source& s) {
    if (o.fargs.size() != 8) throw FatalError(about(o, "bad # arguments"));
    const V3 n = normalized(arg3(o.fargs, 3));
    if (length(n) == 0) throw FatalError(about(o, "illegal source"));
    double r0 = std::abs(o.fargs[6]) <= kTiny ? 0 : std::abs(o.fargs[6]);
    double r1 = std::abs(o.fargs[7]) <= kTiny ? 0 : std::abs(o.fargs[7]);
    if (r0 > r1) std::swap(r0, r1);
    // A ring Radiance's getcone() rejects (equal radii, both zero) is no source at all.
    if (r1 - r0 <= kTiny) throw FatalError(about(o, "illegal source"));
    if (r0 > 0) throw FatalError(about(o, "cannot hit source center"));
    s.kind = RC_SRC_FLAT;
    s.pos = f4(local(arg3(o.fargs, 0)), r1);
    s.axis = f4(n, kPi * (r1 * r1 - r0 * r0));
    const V3 u = radiance_perpendicular(n);
    s.su = f4(scale(u, r1), r0);
    s.sv = f4(scale(cross(n, u), r1), 0);
  }

  void set_cylinder(const scene::Object& o, rc_source& s) {
    if (o.fargs.size() != 7) throw FatalError(about(o, "bad # arguments"));
    const V3 p0 = arg3(o.fargs, 0), p1 = arg3(o.fargs, 3);
    const double r = std::abs(o.fargs[6]); // a negative radius only turns the normal inward
    const double l = length(sub(p1, p0));
    if (l == 0 || r <= kTiny) throw FatalError(about(o, "illegal source")); // getcone() fails
    if (r > 0.2 * l) warning(about(o, "source aspect too small"));
    s.kind = RC_SRC_CYLINDER;
    s.pos = f4(local(scale(add(p0, p1), 0.5)), r);
    s.axis = f4(scale(sub(p1, p0), 1 / l), l);
  }

  void set_polygon(const scene::Object& o, rc_source& s) {
    if (o.fargs.size() < 9 || o.fargs.size() % 3) throw FatalError(about(o, "bad # arguments"));
    std::vector<V3> v;
    for (std::size_t i = 0; i < o.fargs.size(); i += 3)
      v.push_back(arg3(o.fargs, i));
    const V3 d0 = sub(v.front(), v.back());
    if (v.size() > 3 && dot(d0, d0) <= kTiny * kTiny) v.pop_back(); // closing vertex repeated
    const geometry::PolygonPlane pl = geometry::polygon_plane(v);
    if (pl.area == 0) throw FatalError(about(o, "zero source area"));
    const V3& n = pl.normal;
    V3 avg{0, 0, 0};
    for (const V3& p : v)
      avg = add(avg, p);
    avg = scale(avg, 1.0 / static_cast<double>(v.size()));
    if (!in_face(avg, v, n)) throw FatalError(about(o, "cannot hit source center"));

    // In-plane frame (u, w), u x w = n, at the vertex average moved onto the plane.
    const V3 org = sub(avg, scale(n, dot(n, avg) - pl.offset));
    const V3 u = perpendicular(n), w = cross(n, u);
    std::vector<P2> q(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      q[i] = {dot(sub(v[i], org), u), dot(sub(v[i], org), w)};
    // Area centroid (shoelace); seams cancel.
    double a2 = 0, cx = 0, cy = 0;
    for (std::size_t i = 0, j = q.size() - 1; i < q.size(); j = i++) {
      const double c = q[j][0] * q[i][1] - q[i][0] * q[j][1];
      a2 += c;
      cx += (q[j][0] + q[i][0]) * c;
      cy += (q[j][1] + q[i][1]) * c;
    }
    const P2 cen = std::abs(a2) > 0 ? P2{cx / (3 * a2), cy / (3 * a2)} : P2{0, 0};
    const V3 pos = add(org, add(scale(u, cen[0]), scale(w, cen[1])));
    double rad2 = 0;
    for (const V3& p : v)
      rad2 = std::max(rad2, dot(sub(p, pos), sub(p, pos)));

    s.kind = RC_SRC_FLAT;
    s.pos = f4(local(pos), std::sqrt(rad2));
    s.axis = f4(n, pl.area);
    V3 su{}, sv{}, rc{};
    if (!parallelogram(v, su, sv))
      covering_rectangle(q, u, w, org, su, sv, rc);
    else
      rc = pos;
    // Rectangle centre as offsets along su and sv (both in the plane, possibly skew).
    const V3 d = sub(rc, pos);
    const V3 nn = cross(su, sv);
    const double det = dot(nn, n);
    s.su = f4(su, dot(cross(d, sv), n) / det);
    s.sv = f4(sv, dot(cross(su, d), n) / det);
    s.verts = static_cast<std::uint32_t>(out_.verts.size());
    s.nverts = static_cast<std::uint32_t>(v.size());
    for (const V3& p : v)
      out_.verts.push_back(f4(local(p), 1));
  }

  // Radiance samples a four-vertex polygon over the parallelogram of its half edges; that covers
  // it exactly only when it is a parallelogram, so only then is it used here.
  static bool parallelogram(const std::vector<V3>& v, V3& su, V3& sv) {
    if (v.size() != 4) return false;
    const V3 gap = sub(add(v[0], v[2]), add(v[1], v[3]));
    su = scale(sub(v[1], v[0]), 0.5);
    sv = scale(sub(v[3], v[0]), 0.5);
    return length(gap) <= 1e-6 * (length(su) + length(sv));
  }

  // Smallest-area rectangle with a side along a convex-hull edge (the minimum is one of them).
  static void covering_rectangle(const std::vector<P2>& q, const V3& u, const V3& w, const V3& org,
                                 V3& su, V3& sv, V3& rc) {
    const std::vector<P2> h = convex_hull(q);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < h.size(); ++i) {
      const P2& a = h[i];
      const P2& b = h[(i + 1) % h.size()];
      const double el = std::hypot(b[0] - a[0], b[1] - a[1]);
      if (el == 0) continue;
      const P2 e{(b[0] - a[0]) / el, (b[1] - a[1]) / el}, f{-e[1], e[0]};
      double lo0 = 1e300, hi0 = -1e300, lo1 = 1e300, hi1 = -1e300;
      for (const P2& p : h) {
        const double x = p[0] * e[0] + p[1] * e[1], y = p[0] * f[0] + p[1] * f[1];
        lo0 = std::min(lo0, x), hi0 = std::max(hi0, x);
        lo1 = std::min(lo1, y), hi1 = std::max(hi1, y);
      }
      const double area = (hi0 - lo0) * (hi1 - lo1);
      if (area >= best) continue;
      best = area;
      const V3 e3 = add(scale(u, e[0]), scale(w, e[1])), f3 = add(scale(u, f[0]), scale(w, f[1]));
      su = scale(e3, 0.5 * (hi0 - lo0));
      sv = scale(f3, 0.5 * (hi1 - lo1));
      rc = add(org, add(scale(e3, 0.5 * (lo0 + hi0)), scale(f3, 0.5 * (lo1 + hi1))));
    }
  }
};

} // namespace

CompiledSources compile_sources(const scene::SceneDescription& scene,
                                const geometry::SceneGeometry& geom,
                                const std::function<std::uint32_t(std::int32_t)>& surface_index) {
  return Compiler(scene, geom, surface_index).run();
}

} // namespace radcl::render
