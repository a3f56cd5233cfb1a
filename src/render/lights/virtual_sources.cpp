// Virtual sources for planar mirrors and prisms (Radiance's markvirtuals(), mir_proj(),
// dir_proj(), makevsrc(), vstestvis()). Everything is in the re-centred frame of the compiled
// sources.
#include "radcl/render/lights/virtual_sources.h"
#include "radcl/util/vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <string>

#include "radcl/geometry/triangulate.h"
#include "radcl/render/lights/redirect_function.h"
#include "radcl/scene/material_chain.h"
#include "radcl/scene/object_type.h"
#include "radcl/util/error.h"

namespace radcl::render {
namespace {

using V3 = std::array<double, 3>;
using Mat4 = std::array<std::array<double, 4>, 4>; // Radiance's row-vector convention
using namespace radcl::vec;
constexpr double kTiny = 1e-6; // Radiance's FTINY

V3 xyz(const rc_float4& f) {
  return {f.x, f.y, f.z};
}
rc_float4 f4(const V3& v, double w) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]),
          static_cast<float>(w)};
}

// A mirror, or one redirection of a prism, with the host's copy of its geometry.
struct Mirror {
  rc_mirror dev{};
  int redirect = 0;                       // 0: mirror; k: the prism's k-th redirection
  const RedirectFunction* func = nullptr; // prisms
  std::string material;                   // prisms: its name for messages
  V3 n{}, centre{}, u{}, w{};             // front normal, disc centre, in-plane axes
  double offset = 0;                      // dot(n, x) on the plane
  double rad2 = 0;                        // squared radius of the disc holding it
  double r0 = 0, r1 = 0;                  // ring radii
  std::vector<V3> verts;                  // polygon
  bool ring = false;

  V3 reflect_vector(const V3& v) const { return sub(v, scale(n, 2 * dot(n, v))); }

  // Whether plane point q lies within the outline (even-odd rule in the plane's frame).
  bool contains(const V3& q) const {
    const V3 d = sub(q, centre);
    if (ring) {
      const double r2 = dot(d, d) - dot(d, n) * dot(d, n);
      return r2 <= r1 * r1 && r2 >= r0 * r0;
    }
    const double x = dot(d, u), y = dot(d, w);
    bool in = false;
    for (std::size_t i = 0, j = verts.size() - 1; i < verts.size(); j = i++) {
      const V3 a = sub(verts[j], centre), b = sub(verts[i], centre);
      const double ax = dot(a, u), ay = dot(a, w), bx = dot(b, u), by = dot(b, w);
      if ((ay > y) != (by > y) && x < ax + (y - ay) * (bx - ax) / (by - ay)) in = !in;
    }
    return in;
  }
};

V3 perpendicular(const V3& n) {
  const V3 axis =
      std::abs(n[0]) < 0.6 ? V3{1, 0, 0} : (std::abs(n[1]) < 0.6 ? V3{0, 1, 0} : V3{0, 0, 1});
  return normalized(cross(axis, n));
}

// Deterministic uniform numbers in [0, 1) (a splitmix64 stream).
struct Random {
  std::uint64_t state;
  double operator()() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
};

class Builder {
public:
  Builder(const scene::SceneDescription& s, const geometry::SceneGeometry& g,
          const std::function<std::uint32_t(std::int32_t)>& idx, int pretest,
          const ShadowTester& test, CompiledSources& out)
      : scene_(s), geom_(g), index_(idx), pretest_(pretest), test_(test), out_(out) {}

  void run(int relays) {
    if (relays <= 0) return;
    find_mirrors();
    if (mirrors_.empty()) return;
    for (std::size_t i = out_.sources.size(); i-- > 0;) // Radiance's order
      relay(static_cast<std::uint32_t>(i), relays);
  }

private:
  const scene::SceneDescription& scene_;
  const geometry::SceneGeometry& geom_;
  const std::function<std::uint32_t(std::int32_t)>& index_;
  int pretest_;
  const ShadowTester& test_;
  CompiledSources& out_;
  std::vector<Mirror> mirrors_;
  std::map<std::int32_t, std::unique_ptr<RedirectFunction>> funcs_; // by prism material

  void find_mirrors() {
    const V3 c = geom_.centre();
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
      const scene::Object& o = scene_.objects[i];
      if (!scene::is_surface(o.type) || o.modifier == scene::kVoid) continue;
      const std::int32_t m = scene::first_material(scene_, static_cast<std::int32_t>(i));
      if (m == scene::kVoid) continue;
      const scene::Object& mat = scene_.objects[m];
      const bool prism = mat.type == RC_OBJ_PRISM1 || mat.type == RC_OBJ_PRISM2;
      if (mat.type != RC_OBJ_MIRROR && !prism) continue;
      if (o.type != RC_OBJ_POLYGON && o.type != RC_OBJ_RING) {
        warning("secondary sources not supported for " + std::string(scene::type_name(o.type)) +
                " \"" + o.name + "\"");
        continue;
      }
      if (!prism && mat.fargs.size() != 3) continue; // refused when the material is compiled
      Mirror mr;
      if (o.type == RC_OBJ_POLYGON) {
        if (o.fargs.size() < 9 || o.fargs.size() % 3) continue;
        for (std::size_t k = 0; k < o.fargs.size(); k += 3)
          mr.verts.push_back(sub({o.fargs[k], o.fargs[k + 1], o.fargs[k + 2]}, c));
        const geometry::PolygonPlane pl = geometry::polygon_plane(mr.verts);
        if (pl.area == 0) continue;
        mr.n = pl.normal;
        mr.offset = pl.offset;
        V3 avg{0, 0, 0};
        for (const V3& v : mr.verts)
          avg = add(avg, scale(v, 1.0 / static_cast<double>(mr.verts.size())));
        mr.centre = sub(avg, scale(mr.n, dot(mr.n, avg) - mr.offset));
        for (const V3& v : mr.verts)
          mr.rad2 = std::max(mr.rad2, dot(sub(v, mr.centre), sub(v, mr.centre)));
      } else {
        if (o.fargs.size() != 8) continue;
        mr.ring = true;
        mr.n = normalized({o.fargs[3], o.fargs[4], o.fargs[5]});
        mr.centre = sub({o.fargs[0], o.fargs[1], o.fargs[2]}, c);
        mr.offset = dot(mr.n, mr.centre);
        mr.r0 = std::abs(o.fargs[6]);
        mr.r1 = std::abs(o.fargs[7]);
        if (mr.r0 > mr.r1) std::swap(mr.r0, mr.r1);
        mr.rad2 = mr.r1 * mr.r1;
      }
      if (mr.rad2 <= kTiny) continue; // Radiance: too small to relay anything
      mr.u = perpendicular(mr.n);
      mr.w = cross(mr.n, mr.u);
      rc_mirror& d = mr.dev;
      d.plane = f4(mr.n, mr.offset);
      d.centre = f4(mr.centre, mr.r1);
      d.refl = prism ? f4({1, 1, 1}, mr.r0) : f4({mat.fargs[0], mat.fargs[1], mat.fargs[2]}, mr.r0);
      d.surface = index_(static_cast<std::int32_t>(i));
      d.verts = static_cast<std::uint32_t>(out_.verts.size());
      d.nverts = static_cast<std::uint32_t>(mr.verts.size());
      for (const V3& v : mr.verts)
        out_.verts.push_back(f4(v, 1));
      int relays = 1;
      if (prism) {
        auto it = funcs_.find(m);
        if (it == funcs_.end())
          it = funcs_.emplace(m, std::make_unique<RedirectFunction>(mat)).first;
        mr.func = it->second.get();
        mr.material = std::string(scene::type_name(mat.type)) + " \"" + mat.name + "\"";
        relays = mr.func->count();
      }
      for (int k = 0; k < relays; ++k) { // Radiance's vproject(): each of the prism's projections
        Mirror e = mr;
        if (prism) e.redirect = e.dev.redirect = k + 1;
        mirrors_.push_back(std::move(e));
        out_.mirrors.push_back(mirrors_.back().dev);
      }
    }
  }

  void relay(std::uint32_t sn, int relays) {
    if (relays <= 0) return;
    for (std::size_t m = 0; m < mirrors_.size(); ++m)
      project(static_cast<std::uint32_t>(m), sn, relays - 1);
  }

  // mir_proj(): some part of the source must lie in front of the mirror.
  bool in_front(const rc_source& s, const Mirror& m) const {
    const V3 c = xyz(s.pos);
    if (s.kind == RC_SRC_DISTANT) return dot(m.n, c) + s.pos.w > kTiny;
    double ext = 0;
    switch (s.kind) {
    case RC_SRC_FLAT:
      ext = std::abs(dot(m.n, xyz(s.su))) + std::abs(dot(m.n, xyz(s.sv)));
      break;
    case RC_SRC_CYLINDER: {
      const double a = dot(m.n, xyz(s.axis));
      ext = std::abs(a) * 0.5 * s.axis.w + s.pos.w * std::sqrt(std::max(0.0, 1 - a * a));
      break;
    }
    default:
      ext = s.pos.w;
    }
    return dot(m.n, c) + ext > m.offset + kTiny;
  }

  // getdisk(): a relayed source can reach mirror m only from the far side of its own mirror.
  bool relay_possible(const rc_source& s, const Mirror& m) const {
    if (!(s.flags & RC_SRCF_VIRTUAL)) return true;
    const Mirror& r = mirrors_[s.mirror];
    double rd = dot(r.n, xyz(s.pos));
    if (s.kind != RC_SRC_DISTANT) rd -= r.offset;
    const double d = dot(r.n, m.centre) - r.offset;
    if ((d > 0) != (rd > 0)) return true;
    if (d * d >= m.rad2) return false;
    const double c = dot(r.n, m.n);
    return d * d < m.rad2 * (1 - c * c);
  }

  // makevsrc(): source s imaged by relay mi through the affine map pm (points p * pm, vectors
  // without the translation); directions are made unit again, sizes kept, as Radiance does.
  rc_source image(const rc_source& s, std::uint32_t sn, std::uint32_t mi, const Mat4& pm) {
    const Mirror& m = mirrors_[mi];
    auto vmap = [&](const V3& v) {
      V3 o{};
      for (int j = 0; j < 3; ++j)
        o[j] = v[0] * pm[0][j] + v[1] * pm[1][j] + v[2] * pm[2][j];
      return o;
    };
    auto pmap = [&](const V3& p) { return add(vmap(p), V3{pm[3][0], pm[3][1], pm[3][2]}); };
    auto unit = [](const V3& v) { return dot(v, v) > 0 ? normalized(v) : v; };
    rc_source v = s;
    auto vec = [&](rc_float4& f) { f = f4(vmap(xyz(f)), f.w); };
    auto dir = [&](rc_float4& f) { f = f4(unit(vmap(xyz(f))), f.w); };
    if (s.kind == RC_SRC_DISTANT)
      dir(v.pos);
    else
      v.pos = f4(pmap(xyz(s.pos)), s.pos.w);
    dir(v.axis);
    vec(v.su);
    vec(v.sv);
    if (s.flags & RC_SRCF_SPOT) dir(v.spot);
    if (s.nverts > 0) {
      v.verts = static_cast<std::uint32_t>(out_.verts.size());
      for (std::uint32_t k = 0; k < s.nverts; ++k) {
        const rc_float4 p = out_.verts[s.verts + k];
        out_.verts.push_back(f4(pmap(xyz(p)), p.w));
      }
    }
    v.flags |= RC_SRCF_VIRTUAL | RC_SRCF_FOLLOW;
    v.surface = m.dev.surface;
    v.parent = sn;
    v.mirror = mi;
    return v;
  }

  // A mirror's reflection as an affine map.
  static Mat4 reflection(const Mirror& m) {
    Mat4 pm{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        pm[i][j] = (i == j) - 2 * m.n[i] * m.n[j];
    for (int j = 0; j < 3; ++j)
      pm[3][j] = 2 * m.offset * m.n[j];
    pm[3][3] = 1;
    return pm;
  }

  // dir_proj(): the map that takes source s to where prism relay m makes it appear, from the
  // redirection of a ray from the source to the middle of the surface (a shear along the
  // plane, mirrored when the new direction leaves on the other side). False when there is
  // none: the ray misses, runs along the plane, or is redirected with no weight.
  bool redirection(const rc_source& s, const Mirror& m, Mat4& pm) const {
    V3 rdir;
    if (s.kind == RC_SRC_DISTANT) {
      rdir = scale(xyz(s.pos), -1);
    } else {
      rdir = sub(m.centre, xyz(s.pos));
      if (dot(rdir, rdir) <= 0) return false;
      rdir = normalized(rdir);
    }
    const double olddot = dot(rdir, m.n);
    if (std::abs(olddot) <= kTiny || !m.contains(m.centre)) return false;
    double coef;
    V3 nd;
    if (!m.func->eval(m.redirect - 1, add(m.centre, geom_.centre()), rdir, m.n, coef, nd)) {
      warning(m.material + ": projection compute error");
      return false;
    }
    if (coef <= kTiny) return false;
    const double newdot = dot(nd, m.n);
    if (std::abs(newdot) <= kTiny) return false;
    const V3 h = sub(scale(nd, 1 / newdot), scale(rdir, 1 / olddot));
    pm = Mat4{};
    for (int i = 0; i < 4; ++i)
      pm[i][i] = 1;
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 3; ++i)
        pm[i][j] += m.n[i] * h[j];
      pm[3][j] = -m.offset * h[j];
    }
    if ((newdot > 0) != (olddot > 0))
      for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i)
          pm[i][j] -= 2 * m.n[i] * m.n[j];
        pm[3][j] += 2 * m.offset * m.n[j];
      }
    return !identity(pm);
  }

  static bool identity(const Mat4& pm) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (std::abs(pm[i][j] - (i == j)) > 1e-12) return false;
    return true;
  }

  void project(std::uint32_t mi, std::uint32_t sn, int relays) {
    const rc_source s = out_.sources[sn];
    const Mirror& m = mirrors_[mi];
    // No surface images itself (nor one of a prism's redirections the other's sources).
    if ((s.flags & RC_SRCF_VIRTUAL) && mirrors_[s.mirror].dev.surface == m.dev.surface) return;
    if ((!m.redirect && !in_front(s, m)) || !relay_possible(s, m)) return;
    Mat4 pm;
    if (!m.redirect)
      pm = reflection(m);
    else if (!redirection(s, m, pm))
      return;
    rc_source v = image(s, sn, mi, pm);
    if (pretest_ > 0 && !pretest(v, m, s, sn)) {
      out_.verts.resize(v.nverts > 0 ? v.verts : out_.verts.size());
      return;
    }
    out_.sources.push_back(v);
    relay(static_cast<std::uint32_t>(out_.sources.size() - 1), relays);
  }

  // Reflectance along the way from `org` in direction `dir` to source s through its mirrors, 0
  // if the way misses one (the kernels' rc_virtual_path()).
  double path(std::uint32_t sn, V3 org, V3 dir) const {
    double f = 1;
    for (int k = 0; k < 64; ++k) {
      const rc_source& s = out_.sources[sn];
      if (!(s.flags & RC_SRCF_VIRTUAL)) return f;
      const Mirror& m = mirrors_[s.mirror];
      const double dn = dot(dir, m.n);
      if (m.redirect ? std::abs(dn) <= kTiny : dn >= -kTiny) return 0;
      const double t = (m.offset - dot(m.n, org)) / dn;
      if (t <= 0) return 0;
      org = add(org, scale(dir, t));
      if (!m.contains(org)) return 0;
      if (m.redirect) return f; // the way on is known only to the shadow rays that follow it
      f *= std::max({m.dev.refl.x, m.dev.refl.y, m.dev.refl.z});
      dir = m.reflect_vector(dir);
      sn = s.parent;
    }
    return 0;
  }

  // vstestvis(): shadow rays from points on mirror m to the source it images (aimed at its
  // centre). False when none gets there; clears RC_SRCF_FOLLOW in v when all get there
  // unchanged.
  bool pretest(rc_source& v, const Mirror& m, const rc_source& s, std::uint32_t sn) {
    int n;
    if (s.kind == RC_SRC_DISTANT) {
      const auto b = geom_.bounds();
      const double cu = std::max({b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2], 1e-3});
      n = static_cast<int>(32 * m.rad2 / (cu * cu) * pretest_ + 0.5);
    } else {
      const V3 off = sub(xyz(s.pos), m.centre);
      const double d = dot(off, off);
      n = d <= kTiny
              ? static_cast<int>(2 * std::numbers::pi * pretest_ + 0.5)
              : static_cast<int>(
                    2 * std::numbers::pi * (1 - std::sqrt(1 / (1 + m.rad2 / d))) * pretest_ + 0.5);
    }
    n = std::max(n, 16);
    Random rnd{static_cast<std::uint64_t>(out_.sources.size()) * 931 + 5827};
    const double r = std::sqrt(m.rad2);
    std::vector<rc_shadow> rays;
    const int limit = 32 * n;
    for (int i = 0, tries = 0; i < n; ++i) {
      V3 q;
      do {
        if (tries++ >= limit) return true; // too small a target to tell: follow every ray
        q = add(m.centre, add(scale(m.u, r * (2 * rnd() - 1)), scale(m.w, r * (2 * rnd() - 1))));
      } while (!m.contains(q));
      V3 dir;
      double dist;
      if (s.kind == RC_SRC_DISTANT) {
        dir = xyz(s.pos);
        dist = 1e10;
      } else {
        const V3 to = sub(xyz(s.pos), q);
        dist = std::sqrt(dot(to, to));
        if (dist <= 0) continue;
        dir = scale(to, 1 / dist);
      }
      // Radiance counts only samples the source would light (its front, its spot, the way
      // through its own mirrors).
      if (s.kind == RC_SRC_FLAT && dot(dir, xyz(s.axis)) >= 0) continue;
      if ((s.flags & RC_SRCF_SPOT) && -dot(dir, xyz(s.spot)) < s.spot.w) continue;
      if (path(sn, q, dir) <= 0) continue;
      rc_shadow sh{};
      sh.org = f4(q, geom_.epsilon());
      sh.dir = f4(dir, dist);
      sh.contrib = rc_float4{1, 1, 1, 0};
      const std::uint32_t global = RC_MEDIUM_GLOBAL; // as a primary's (its extinction: none)
      std::memcpy(&sh.cext.w, &global, sizeof global);
      sh.primary = 0;
      sh.source = sn;
      rays.push_back(sh);
    }
    if (rays.empty()) return false;
    const std::vector<float> got = test_(out_, rays);
    int hits = 0;
    for (float f : got) {
      if (f > 0 && f < 1 - 1e-4f) return true; // an intervening transmitter: follow
      hits += f > 0;
    }
    if (hits == 0) return false;
    // A prism's shadow rays always follow: they take its coefficient at the point they meet.
    if (hits == static_cast<int>(got.size()) && !m.redirect) v.flags &= ~RC_SRCF_FOLLOW;
    return true;
  }
};

} // namespace

void add_virtual_sources(const scene::SceneDescription& scene, const geometry::SceneGeometry& geom,
                         const std::function<std::uint32_t(std::int32_t)>& surface_index,
                         int relays, int pretest, const ShadowTester& test,
                         CompiledSources& sources) {
  Builder(scene, geom, surface_index, pretest, test, sources).run(relays);
}

} // namespace radcl::render
