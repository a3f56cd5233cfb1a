// Records made from sampled hemispheres (render/ambient_record.h,
// kernels/ambient/ambient_record.cl) against a double-precision reference written here from the
// derivation in docs/cache-internals.md
// ("Making a record"): per-triangle sums of full 3x3 edge terms, as Radiance assembles them,
// where the kernel gathers per edge in the tangent frame. The reference's gradient and Hessian
// are checked against finite differences of the mesh's irradiance (Lambert's formula), and the
// kernel against closed forms for a sphere, a ceiling, a half-bright sky and a wall.
#include "radcl/luminance.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <vector>

#include "radcl/ambient/dircode.h"
#include "radcl/ambient/record_maker.h"
#include "radcl/device/context.h"

using namespace radcl;
using ambient::HemisphereSettings;

namespace {

using D3 = std::array<double, 3>;

D3 operator+(D3 a, D3 b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
D3 operator-(D3 a, D3 b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
D3 operator*(double s, D3 a) {
  return {s * a[0], s * a[1], s * a[2]};
}
double dot(D3 a, D3 b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
D3 cross(D3 a, D3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double len(D3 a) {
  return std::sqrt(dot(a, a));
}
D3 unit(D3 a) {
  return (1.0 / len(a)) * a;
}
D3 f3(const rc_float4& v) {
  return {v.x, v.y, v.z};
}
double bright(D3 c) {
  return radcl::bright(c);
}

using M3 = std::array<D3, 3>;

// ---- the reference ------------------------------------------------------------------------

struct Edge {
  D3 grad{};
  M3 hess{};
};

// The form-factor gradient and (minus) Hessian of edge p0 -> p1 seen from x with normal n.
Edge edge_terms(D3 x, D3 n, D3 p0, D3 p1) {
  const D3 r0 = p0 - x, r1 = p1 - x, e = p1 - p0, rc = cross(r0, r1);
  const double dd = dot(rc, rc), a0 = dot(r0, r0), a1 = dot(r1, r1), c = dot(e, e);
  const double i1 =
      std::acos(std::clamp(dot(r0, r1) / std::sqrt(a0 * a1), -1.0, 1.0)) / std::sqrt(dd);
  const double i2 = (dot(e, r1) / a1 - dot(e, r0) / a0 + c * i1) / (2 * dd);
  const double j2 = (0.5 * (1 / a0 - 1 / a1) - dot(e, r0) * i2) / c;
  const double i3 = (dot(e, r1) / (a1 * a1) - dot(e, r0) / (a0 * a0) + 3 * c * i2) / (4 * dd);
  const double j3 = (0.25 * (1 / (a0 * a0) - 1 / (a1 * a1)) - dot(e, r0) * i3) / c;
  const double k3 = (i2 - a0 * i3 - 2 * dot(e, r0) * j3) / c;
  const D3 g = i2 * r0 + j2 * e, nc = cross(n, e);
  const double nr = dot(n, rc);
  Edge out;
  out.grad = (0.5 / M_PI) * (i1 * nc + 2 * nr * g);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double m = i3 * r0[a] * r0[b] + j3 * (r0[a] * e[b] + e[a] * r0[b]) + k3 * e[a] * e[b];
      out.hess[a][b] = -(nc[a] * g[b] + g[a] * nc[b] + nr * (4 * m - (a == b ? i2 : 0))) / M_PI;
    }
  return out;
}

// Radiance's atan2a in double.
double atan2a(double y, double x) {
  if (x == 0) return y > 0 ? M_PI / 2 : 1.5 * M_PI;
  const double q = y / x, aq = std::fabs(q);
  if (aq > 1.01) return M_PI / 2 - atan2a(x, y);
  return M_PI / 4 * q - q * (aq - 1) * (0.2447 + 0.0663 * aq) + M_PI * (x < 0);
}

struct Ref {
  int status = 0;
  D3 val{};
  double rad[2] = {0, 0};
  D3 u{}, v{};
  double pg[2] = {0, 0}, dg[2] = {0, 0};
  std::uint32_t corral = 0;
  M3 hess{};              // before projection
  D3 grad{};              // before projection
  double lam[2] = {0, 0}; // tangential eigenvalues, larger magnitude first
  double ra_raw[2] = {0, 0};
};

Ref reference(const rc_amb_hemi& h, const std::vector<rc_amb_sample>& all) {
  const rc_amb_sample* s = all.data() + h.first;
  const int ns = static_cast<int>(h.ns), n2 = ns * ns;
  const D3 x = f3(h.pos), n = f3(h.nrm), ux = f3(h.ux), uy = f3(h.uy);
  const double minarad = h.nrm.w, maxarad = h.ux.w, aa = h.uy.w, wt = h.pos.w;
  Ref r;
  int ok = 0;
  for (int k = 0; k < n2; ++k)
    if (s[k].val.w >= 0) {
      r.val = r.val + D3{s[k].val.x, s[k].val.y, s[k].val.z};
      ++ok;
    }
  r.u = ux;
  r.v = uy;
  if (ok == 0) return r;
  if (ok < n2 || ns < 7) {
    r.status = -1;
    return r;
  }
  const double bs = 0.5 * bright(r.val);
  const bool lit = bs > 1e-6;
  std::vector<double> y(n2), d(n2);
  std::vector<D3> p(n2);
  for (int k = 0; k < n2; ++k) {
    const D3 c{s[k].val.x, s[k].val.y, s[k].val.z};
    y[k] = lit ? 0.99 * n2 * bright(c) / bright(r.val) + 0.01 : 0.5 * bright(c) * bs + 1;
    d[k] = s[k].val.w;
    p[k] = f3(s[k].pnt);
  }
  auto back = [&](int a, int b, int c) {
    if (d[a] <= d[b]) return d[a] <= d[c] ? y[a] : y[c];
    return d[b] <= d[c] ? y[b] : y[c];
  };
  // Per triangle: its weight times the sum over its three edges, both triangles of a cell
  // counter-clockwise seen from above.
  auto add_tri = [&](int a, int b, int c) {
    const double w = back(a, b, c);
    const int v[4] = {a, b, c, a};
    for (int k = 0; k < 3; ++k) {
      Edge e = edge_terms(x, n, p[v[k]], p[v[k + 1]]);
      r.grad = r.grad + w * e.grad;
      for (int i = 0; i < 3; ++i)
        r.hess[i] = r.hess[i] + w * e.hess[i];
    }
  };
  for (int i = 0; i + 1 < ns; ++i)
    for (int j = 0; j + 1 < ns; ++j) {
      add_tri(i * ns + j, i * ns + j + 1, (i + 1) * ns + j);
      add_tri((i + 1) * ns + j + 1, (i + 1) * ns + j, i * ns + j + 1);
    }
  auto hq = [&](D3 a, D3 b) {
    return dot(a, D3{dot(r.hess[0], b), dot(r.hess[1], b), dot(r.hess[2], b)});
  };
  const double hxx = hq(ux, ux), hxy = 0.5 * (hq(ux, uy) + hq(uy, ux)), hyy = hq(uy, uy);
  // Eigen-decomposition of the tangential block.
  const double mid = 0.5 * (hxx + hyy), disc = 0.25 * (hxx - hyy) * (hxx - hyy) + hxy * hxy;
  const bool dbl = disc <= 1e-12;
  const double sq = dbl ? 0 : std::sqrt(disc);
  double lo = mid - sq, hi = mid + sq, ra[2];
  if (std::fabs(lo) <= 1e-12 || std::fabs(hi) <= 1e-12) {
    ra[0] = ra[1] = maxarad;
  } else {
    const double big = std::fabs(lo) > std::fabs(hi) ? lo : hi;
    const double small = std::fabs(lo) > std::fabs(hi) ? hi : lo;
    r.lam[0] = big;
    r.lam[1] = small;
    ra[0] = std::pow(4 / std::fabs(big), 0.25);
    ra[1] = std::pow(4 / std::fabs(small), 0.25);
    if (!dbl) {
      // (H - small I) v = 0, v the long axis; u = v x n.
      double vx = hxy, vy = small - hxx;
      if (vx * vx + vy * vy < (small - hyy) * (small - hyy) + hxy * hxy) vx = small - hyy, vy = hxy;
      const double l = std::hypot(vx, vy);
      vx /= l, vy /= l;
      if ((std::fabs(vx) >= std::fabs(vy) ? vx : vy) < 0) vx = -vx, vy = -vy;
      r.v = vx * ux + vy * uy;
      r.u = cross(r.v, n);
    }
  }
  r.ra_raw[0] = ra[0];
  r.ra_raw[1] = ra[1];
  if (lit) {
    r.pg[0] = dot(r.grad, r.u);
    r.pg[1] = dot(r.grad, r.v);
    D3 t{};
    for (int k = 0; k < n2; ++k) {
      const D3 vd = p[k] - x;
      t = t + (y[k] / dot(n, vd)) * vd;
    }
    r.dg[0] = -dot(r.v, t) / n2;
    r.dg[1] = dot(r.u, t) / n2;
    if (ra[0] * std::fabs(r.pg[0]) > 1) ra[0] = 1 / std::fabs(r.pg[0]);
    if (ra[1] * std::fabs(r.pg[1]) > 1) ra[1] = 1 / std::fabs(r.pg[1]);
    if (ra[0] > ra[1]) ra[0] = ra[1];
  }
  if (ra[0] < minarad) {
    ra[0] = minarad;
    if (ra[1] < minarad) ra[1] = minarad;
  }
  ra[0] /= std::sqrt(wt);
  ra[1] /= std::sqrt(wt);
  if (ra[1] > 2 * ra[0]) ra[1] = 2 * ra[0];
  if (ra[1] > maxarad) {
    ra[1] = maxarad;
    if (ra[0] > maxarad) ra[0] = maxarad;
  }
  if (ns >= 8) { // corral (radcl marks black hemispheres too; Radiance does not)
    const double r0 = ra[0] * aa, r1 = ra[1] * aa, max_d = 1 / (minarad * aa + 0.001);
    const double res = 0.5 * M_PI / ns, step = res / (int(16 / M_PI * res) + 1.01);
    double avg = 0;
    for (int i = ns / 4; i < ns * 3 / 4; ++i)
      for (int j = ns / 4; j < ns * 3 / 4; ++j)
        avg += d[i * ns + j];
    avg *= 4.0 / n2;
    if (avg * r0 < 1 && avg < max_d)
      for (int i = 0; i < ns; ++i)
        for (int j = 0; j < ns; j += (i == 0 || i == ns - 1) ? 1 : ns - 1) {
          const int k = i * ns + j;
          if (d[k] <= 1e-6 || d[k] >= max_d) continue;
          const D3 vd = p[k] - x;
          const double u = dot(vd, r.u), v = dot(vd, r.v);
          if ((r0 * r0 * u * u + r1 * r1 * v * v) * d[k] * d[k] <= u * u + v * v) continue;
          const double ang = atan2a(v, u);
          for (double a = ang - res; a <= ang + res; a += step)
            r.corral |= 1u << int(16 / M_PI * (a + 2 * M_PI * (a < 0)));
        }
  }
  if (lit) {
    const double e = r.pg[0] * r.pg[0] * ra[0] * ra[0] + r.pg[1] * r.pg[1] * ra[1] * ra[1];
    if (e > 1) r.pg[0] /= std::sqrt(e), r.pg[1] /= std::sqrt(e);
  }
  r.rad[0] = ra[0];
  r.rad[1] = ra[1];
  r.status = ra[0] > 1e-6 ? 1 : -1;
  return r;
}

// ---- synthetic hemispheres ----------------------------------------------------------------

// The concentric square-to-disc map (Shirley and Chiu) at stratum centres: local direction
// (x along ux, y along uy, z along the normal) of stratum i*ns + j.
D3 stratum_dir(int ns, int i, int j) {
  const double a = 2 * (j + 0.5) / ns - 1, b = 2 * (i + 0.5) / ns - 1;
  double rr, phi;
  if (a == 0 && b == 0) {
    rr = phi = 0;
  } else if (std::fabs(a) > std::fabs(b)) {
    rr = a;
    phi = M_PI / 4 * (b / a);
  } else {
    rr = b;
    phi = M_PI / 2 - M_PI / 4 * (a / b);
  }
  const double dx = rr * std::cos(phi), dy = rr * std::sin(phi);
  return {dx, dy, std::sqrt(1 - dx * dx - dy * dy)};
}

// What a local direction sees: distance (infinity: nothing) and radiance.
struct Hit {
  double t;
  D3 rad;
};
using Scene = std::function<Hit(D3)>;

// A frame tilted away from the axes so the projections are exercised.
struct Frame {
  D3 o{0.3, -0.2, 0.7}, n = unit(D3{0.2, -0.3, 0.9}), ux, uy;
  Frame() {
    ux = unit(cross(D3{0.1, 1, 0.05}, n));
    uy = cross(n, ux);
  }
  D3 world(D3 l) const { return o + (l[0] * ux + l[1] * uy + l[2] * n); }
};

struct Hemi {
  rc_amb_hemi h;
  std::vector<rc_amb_sample> s;
};

Hemi make(const Scene& scene, int ns, HemisphereSettings set, double wt = 1.0, int level = 0,
          const Frame& f = Frame()) {
  Hemi out;
  out.h = ambient::make_hemisphere(f.o, f.n, f.ux, ns, 0, level, wt, set);
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j < ns; ++j) {
      const D3 dl = stratum_dir(ns, i, j);
      const Hit hit = scene(dl);
      rc_amb_sample s{};
      const double scale = 1.0 / (ns * ns);
      s.val = {float(hit.rad[0] * scale), float(hit.rad[1] * scale), float(hit.rad[2] * scale),
               std::isfinite(hit.t) ? float(1 / hit.t) : 0.0f};
      const double t = std::min(hit.t, 1000.0); // the host's clamp (10 * cube + 1000)
      const D3 p = f.world(t * dl);
      s.pnt = {float(p[0]), float(p[1]), float(p[2]), 0};
      out.s.push_back(s);
    }
  return out;
}

struct Result {
  rc_amb_record rec;
  rc_amb_made made;
};

Result run(const Hemi& hm) {
  static ambient::RecordMaker maker(device::default_context());
  ambient::MadeRecords m = maker.make({&hm.h, 1}, hm.s);
  return {m.records.at(0), m.made.at(0)};
}

D3 gpos3(const rc_amb_record& r) {
  const D3 u = f3(r.udir), v = cross(f3(r.nrm), u);
  return r.grad.x * u + r.grad.y * v;
}
D3 gdir3(const rc_amb_record& r) {
  const D3 u = f3(r.udir), v = cross(f3(r.nrm), u);
  return r.grad.z * u + r.grad.w * v;
}

// Kernel against reference: radii, value and the gradients as vectors (their components follow
// the axes, which are arbitrary where the Hessian is isotropic) within `tol` relative, with
// `gscale` the size below which a gradient counts as zero.
void expect_matches(const Result& k, const Ref& r, double tol, double gscale) {
  ASSERT_EQ(k.made.status, r.status);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(f3(k.rec.val)[c], r.val[c], tol * std::fabs(r.val[c]) + 1e-12);
  if (r.status != 1) return;
  EXPECT_NEAR(k.rec.nrm.w, r.rad[0], tol * r.rad[0]);
  EXPECT_NEAR(k.rec.udir.w, r.rad[1], tol * r.rad[1]);
  const D3 gp = r.pg[0] * r.u + r.pg[1] * r.v, gd = r.dg[0] * r.u + r.dg[1] * r.v;
  const double gpm = std::max(len(gp), gscale), gdm = std::max(len(gd), gscale);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(gpos3(k.rec)[c], gp[c], tol * gpm) << "translational gradient, axis " << c;
    EXPECT_NEAR(gdir3(k.rec)[c], gd[c], tol * gdm) << "rotational gradient, axis " << c;
  }
  // The axes are defined where the eigenvalues differ clearly.
  if (std::fabs(r.lam[0] - r.lam[1]) > 1e-2 * std::fabs(r.lam[0]) && r.rad[0] < r.rad[1]) {
    EXPECT_GT(std::fabs(dot(f3(k.rec.udir), r.u)), 1 - 1e-6);
    // u is an eigenvector of the Hessian's tangential block: v'Hu = 0.
    const D3 u = f3(k.rec.udir), v = cross(f3(k.rec.nrm), u);
    const D3 hu{dot(r.hess[0], u), dot(r.hess[1], u), dot(r.hess[2], u)};
    EXPECT_NEAR(dot(v, hu), 0, 1e-4 * std::fabs(r.lam[0]));
  }
  // A flipped u axis (and v) turns the sectors by half a turn.
  std::uint32_t corral = r.corral;
  if (dot(f3(k.rec.udir), r.u) < 0) corral = corral >> 16 | corral << 16;
  EXPECT_EQ(k.made.corral, corral);
}

// Irradiance of the mesh (sum over triangles of weight x Lambert's form factor) seen from x with
// the hemisphere's normal; weights fixed as the reference picks them.
double mesh_irradiance(const Hemi& hm, D3 x) {
  const int ns = static_cast<int>(hm.h.ns), n2 = ns * ns;
  const D3 n = f3(hm.h.nrm);
  D3 sum{};
  for (const auto& s : hm.s)
    sum = sum + D3{s.val.x, s.val.y, s.val.z};
  auto y = [&](int k) {
    const auto& s = hm.s[k];
    return 0.99 * n2 * bright(D3{s.val.x, s.val.y, s.val.z}) / bright(sum) + 0.01;
  };
  auto back = [&](int a, int b, int c) {
    const double da = hm.s[a].val.w, db = hm.s[b].val.w, dc = hm.s[c].val.w;
    if (da <= db) return da <= dc ? y(a) : y(c);
    return db <= dc ? y(b) : y(c);
  };
  auto ff = [&](int a, int b, int c) {
    const int v[4] = {a, b, c, a};
    double f = 0;
    for (int k = 0; k < 3; ++k) {
      const D3 r0 = f3(hm.s[v[k]].pnt) - x, r1 = f3(hm.s[v[k + 1]].pnt) - x;
      const D3 rc = cross(r0, r1);
      const double th = std::atan2(len(rc), dot(r0, r1));
      f += th * dot(n, rc) / len(rc);
    }
    return back(a, b, c) * f / (2 * M_PI);
  };
  double e = 0;
  for (int i = 0; i + 1 < ns; ++i)
    for (int j = 0; j + 1 < ns; ++j) {
      e += ff(i * ns + j, i * ns + j + 1, (i + 1) * ns + j);
      e += ff((i + 1) * ns + j + 1, (i + 1) * ns + j, i * ns + j + 1);
    }
  return e;
}

const D3 kWhite{1, 1, 1};

Scene sphere(double radius, D3 rad) {
  return [=](D3) { return Hit{radius, rad}; };
}
Scene ceiling(double h, D3 rad) {
  return [=](D3 d) { return Hit{h / d[2], rad}; };
}
// A bright wall at x = w (radiance 1) under a ceiling at height h (radiance 0.2).
Scene wall(double w, double h) {
  return [=](D3 d) {
    const double tc = h / d[2], tw = d[0] > 0 ? w / d[0] : INFINITY;
    return tw < tc ? Hit{tw, D3{1, 1, 1}} : Hit{tc, D3{0.2, 0.2, 0.2}};
  };
}

HemisphereSettings settings(double minarad, double maxarad, double aa) {
  HemisphereSettings s;
  s.minarad = minarad;
  s.maxarad = maxarad;
  s.aa = aa;
  return s;
}

} // namespace

// The reference's gradient and Hessian are the first and (minus the) second derivatives of the
// mesh's irradiance with its vertices fixed.
TEST(AmbientRecordReference, DerivativesOfTheMeshIrradiance) {
  for (const Scene& sc : {wall(0.7, 1.0), ceiling(1.3, kWhite)}) {
    Hemi hm = make(sc, 12, settings(0.01, 100, 0.1));
    Ref r = reference(hm.h, hm.s);
    const D3 x = f3(hm.h.pos), ux = f3(hm.h.ux), uy = f3(hm.h.uy);
    const double dl = 1e-4;
    const D3 ax[2] = {ux, uy};
    for (int a = 0; a < 2; ++a) {
      const double fd =
          (mesh_irradiance(hm, x + dl * ax[a]) - mesh_irradiance(hm, x - dl * ax[a])) / (2 * dl);
      EXPECT_NEAR(dot(r.grad, ax[a]), fd, 1e-6 + 1e-5 * std::fabs(fd));
      for (int b = 0; b < 2; ++b) {
        const D3 pa = dl * ax[a], pb = dl * ax[b];
        const double fab = (mesh_irradiance(hm, x + pa + pb) - mesh_irradiance(hm, x + pa - pb) -
                            mesh_irradiance(hm, x - pa + pb) + mesh_irradiance(hm, x - pa - pb)) /
                           (4 * dl * dl);
        const D3 hb{dot(r.hess[0], ax[b]), dot(r.hess[1], ax[b]), dot(r.hess[2], ax[b])};
        EXPECT_NEAR(dot(ax[a], hb), -fab, 1e-4 * (1 + std::fabs(fab)));
      }
    }
  }
}

// (a) The centre of a sphere of uniform radiance: the value is the radiance, no gradients, and
// the Hessian is the one of the cap the outer ring of strata bounds: for strata centres on the
// circle rho = 1 - 1/ns (the disc map keeps rings round) a closed form gives 4 rho^2 z^2 / R^2
// in every tangent direction (z^2 = 1 - rho^2).
TEST(AmbientRecord, UniformSphere) {
  const int ns = 32;
  const double rho = 1.0 - 1.0 / ns, z2 = 1 - rho * rho;
  for (double radius : {1.0, 4.0}) {
    const D3 rad{0.3, 0.5, 0.7};
    // Unclamped: minarad below and maxarad above what the Hessian asks for.
    Hemi hm = make(sphere(radius, rad), ns, settings(0.001, 1000, 0.1));
    Ref r = reference(hm.h, hm.s);
    Result k = run(hm);
    expect_matches(k, r, 1e-4, 1 / radius);
    EXPECT_NEAR(k.rec.val.x, rad[0], 1e-6);
    EXPECT_NEAR(k.rec.val.y, rad[1], 1e-6);
    EXPECT_NEAR(k.rec.val.z, rad[2], 1e-6);
    EXPECT_LT(len(gpos3(k.rec)), 1e-5 / radius);
    EXPECT_LT(len(gdir3(k.rec)), 1e-5);
    const double lam = 4 * rho * rho * z2 / (radius * radius);
    const double ra = std::pow(4 / lam, 0.25); // 2.04 sqrt(R) for ns = 32
    // The mesh's boundary is a polygon of 4(ns-1) vertices: within 2% of the round cap.
    EXPECT_NEAR(r.lam[0], lam, 0.02 * lam);
    EXPECT_NEAR(r.lam[1], lam, 0.02 * lam);
    EXPECT_NEAR(k.rec.nrm.w, ra, 0.01 * ra);
    EXPECT_NEAR(k.rec.udir.w, ra, 0.01 * ra);
    // Radiance's clamps: maxarad caps both; minarad raises both; 1/sqrt(weight) scales both.
    Hemi cap = make(sphere(radius, rad), ns, settings(0.001, 0.5, 0.1));
    Result kc = run(cap);
    EXPECT_EQ(kc.rec.nrm.w, 0.5f);
    EXPECT_EQ(kc.rec.udir.w, 0.5f);
    Hemi floor_ = make(sphere(radius, rad), ns, settings(10, 1000, 0.1));
    Result kf = run(floor_);
    EXPECT_FLOAT_EQ(kf.rec.nrm.w, 10.0f);
    EXPECT_FLOAT_EQ(kf.rec.udir.w, 10.0f);
    Hemi light = make(sphere(radius, rad), ns, settings(0.001, 1000, 0.1), 0.25, 2);
    Result kl = run(light);
    expect_matches(kl, reference(light.h, light.s), 1e-4, 1 / radius);
    EXPECT_NEAR(kl.rec.nrm.w, 2 * k.rec.nrm.w, 1e-5 * kl.rec.nrm.w);
    EXPECT_EQ(kl.rec.val.w, 2.0f);
    EXPECT_EQ(kl.rec.pos.w, 0.25f);
  }
}

// (b) Under an infinite uniform ceiling at height h: the outer strata bound a disc of radius
// h rho / z, whose form factor from a point offset by a has second derivative
// -4 h^2 s^2 / (h^2 + s^2)^3 = -4 rho^2 z^4 / h^2. The radius (4/lambda)^(1/4) therefore grows
// as sqrt(h): doubling h multiplies both radii by sqrt(2) (not 2).
TEST(AmbientRecord, CeilingRadiiGrowAsRootOfHeight) {
  const int ns = 32;
  const double rho = 1.0 - 1.0 / ns, z2 = 1 - rho * rho;
  double prev = 0;
  for (double h : {0.5, 1.0, 2.0}) {
    Hemi hm = make(ceiling(h, kWhite), ns, settings(0.001, 1000, 0.1));
    Ref r = reference(hm.h, hm.s);
    Result k = run(hm);
    expect_matches(k, r, 1e-4, 1 / h);
    const double lam = 4 * rho * rho * z2 * z2 / (h * h);
    EXPECT_NEAR(r.lam[0], lam, 0.03 * lam);
    EXPECT_NEAR(r.lam[1], lam, 0.03 * lam);
    EXPECT_LT(len(gpos3(k.rec)), 1e-5 / h);
    EXPECT_LT(len(gdir3(k.rec)), 1e-5);
    EXPECT_NEAR(k.rec.val.y, 1.0, 1e-6);
    if (prev > 0) {
      EXPECT_NEAR(k.rec.nrm.w / prev, std::sqrt(2.0), 1e-4);
    }
    prev = k.rec.nrm.w;
  }
}

// (c) A sphere whose half towards +ux is bright: the rotational gradient is
// (1/ns^2) sum Y tan(theta) turned by 90 degrees, along uy (tilting the normal towards the
// bright side, n x n' points along uy), for the continuous hemisphere
// (1/pi) integral of Y (ux . w) dw = (Y1 - Y0)/2 = 0.99 (L1 - L0)/(L1 + L0).
Scene half_bright(double l1, double l0) {
  return [=](D3 d) { return Hit{2.0, d[0] > 0 ? D3{l1, l1, l1} : D3{l0, l0, l0}}; };
}

TEST(AmbientRecord, HalfBrightRotationalGradient) {
  const int ns = 32;
  const double l1 = 3, l0 = 1;
  Hemi hm = make(half_bright(l1, l0), ns, settings(0.001, 1000, 0.1));
  Ref r = reference(hm.h, hm.s);
  Result k = run(hm);
  expect_matches(k, r, 1e-4, 0.5);
  const D3 gd = gdir3(k.rec), uy = f3(hm.h.uy), ux = f3(hm.h.ux);
  // The strata's sum, written directly.
  double sum = 0;
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j < ns; ++j) {
      const D3 d = stratum_dir(ns, i, j);
      const double y = 0.99 * (d[0] > 0 ? l1 : l0) / ((l1 + l0) / 2) + 0.01;
      sum += y * d[0] / d[2];
    }
  sum /= ns * ns;
  EXPECT_NEAR(dot(gd, uy), sum, 1e-4 * sum);
  EXPECT_NEAR(dot(gd, ux), 0, 1e-5);
  EXPECT_NEAR(k.rec.val.x, (l1 + l0) / 2, 1e-6 * l1);
}

// The same with stratum centres approaches the continuous value from below: the outer ring's
// centre (rho = 1 - 1/ns) stands for an annulus where tan(theta) ~ 1/sqrt(1 - rho) peaks, so
// it misses (Y1 - Y0)/2 (4/pi)(2 - sqrt(2))/sqrt(ns) to leading order (random positions within
// the strata, as Radiance's, have no such bias on average).
TEST(AmbientRecordReference, RotationalGradientConverges) {
  const double l1 = 3, l0 = 1, cont = 0.99 * (l1 - l0) / (l1 + l0);
  for (int ns : {32, 64, 128, 256}) {
    Hemi hm = make(half_bright(l1, l0), ns, settings(0.001, 1000, 0.1));
    Ref r = reference(hm.h, hm.s);
    const double got = dot(r.dg[0] * r.u + r.dg[1] * r.v, f3(hm.h.uy));
    const double miss = cont * 4 / M_PI * (2 - std::sqrt(2.0)) / std::sqrt(double(ns));
    EXPECT_NEAR(cont - got, miss, 0.1 * miss) << ns;
  }
}

// (d) A bright wall on the +ux side: the translational gradient points at it. (The mesh's
// diagonals all run one way, which breaks the scene's mirror symmetry about ux slightly: the
// sideways component is below 1% of the gradient at ns = 32, 0.05% at 256.)
TEST(AmbientRecord, WallTranslationalGradient) {
  const int ns = 32;
  Hemi hm = make(wall(0.7, 1.0), ns, settings(0.001, 1000, 0.1));
  Ref r = reference(hm.h, hm.s);
  Result k = run(hm);
  expect_matches(k, r, 1e-4, 1);
  const D3 gp = gpos3(k.rec), ux = f3(hm.h.ux), uy = f3(hm.h.uy);
  EXPECT_GT(dot(gp, ux), 0.4);
  EXPECT_LT(std::fabs(dot(gp, uy)), 0.01 * len(gp));
}

// For the continuous scene (infinite wall at distance w with radiance 1, ceiling at h with 0.2)
// the relative irradiance changes by 0.99 (L1 - L0) / Lmean x h^2 / (2 (w^2 + h^2)^1.5) per unit
// step towards the wall (the wall's form factor is (1 - w / sqrt(w^2 + h^2)) / 2). The mesh,
// which ends at the outer ring of strata and gives each triangle its farthest vertex's value,
// approaches it at first order in 1/ns.
TEST(AmbientRecordReference, TranslationalGradientConverges) {
  const double w = 0.7, h = 1.0;
  const double fwall = 0.5 * (1 - w / std::hypot(w, h)), lmean = fwall + (1 - fwall) * 0.2;
  const double cont = 0.99 * 0.8 / lmean * h * h / (2 * std::pow(w * w + h * h, 1.5));
  double prev = 0;
  for (int ns : {32, 64, 128, 256}) {
    Hemi hm = make(wall(w, h), ns, settings(0.001, 1000, 0.1));
    Ref r = reference(hm.h, hm.s);
    const double err = cont - dot(r.pg[0] * r.u + r.pg[1] * r.v, f3(hm.h.ux));
    EXPECT_GT(err, 0) << ns;
    if (prev > 0) {
      EXPECT_NEAR(err / prev, 0.5, 0.1) << ns;
    }
    prev = err;
  }
  EXPECT_LT(prev, 0.02 * cont);
}

// (e) A low obstacle close by towards +ux: the corral bits cover its directions (plus Radiance's
// half-stratum margin) and nothing else; without it no bits are set.
TEST(AmbientRecord, CorralTowardsNearOccluder) {
  const int ns = 32;
  const double t_near = 0.08, half = 25 * M_PI / 180;
  auto occluded = [&](D3 d) { return std::fabs(std::atan2(d[1], d[0])) < half && d[2] < 0.35; };
  Scene sc = [&](D3 d) { return occluded(d) ? Hit{t_near, kWhite} : Hit{1.0 / d[2], kWhite}; };
  const HemisphereSettings set = settings(0.2, 2, 0.25);
  Hemi hm = make(sc, ns, set, 0.25);
  Ref r = reference(hm.h, hm.s);
  Result k = run(hm);
  expect_matches(k, r, 1e-4, 1);
  ASSERT_NE(k.made.corral, 0u);
  // Angles in the record's frame (u = udir): the occluded perimeter strata's span.
  const D3 u = f3(k.rec.udir), v = cross(f3(k.rec.nrm), u), ux = f3(hm.h.ux), uy = f3(hm.h.uy);
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < ns; ++i)
    for (int j = 0; j < ns; ++j) {
      if (i != 0 && i != ns - 1 && j != 0 && j != ns - 1) continue;
      const D3 d = stratum_dir(ns, i, j);
      if (!occluded(d)) continue;
      const D3 wd = d[0] * ux + d[1] * uy;
      double a = std::atan2(dot(wd, v), dot(wd, u));
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
  const double res = 0.5 * M_PI / ns, slack = 0.002; // atan2a is within 0.002 of atan2
  for (int b = 0; b < 32; ++b) {
    if (!(k.made.corral >> b & 1u)) continue;
    const double s0 = b * M_PI / 16, s1 = (b + 1) * M_PI / 16;
    bool near = false;
    for (double shift : {-2 * M_PI, 0.0, 2 * M_PI})
      near |= s1 + shift >= lo - res - slack && s0 + shift <= hi + res + slack;
    EXPECT_TRUE(near) << "sector " << b << " away from the occluder";
  }
  // The sectors of the occluder's central direction are set.
  const D3 wx = ux;
  double a0 = std::atan2(dot(wx, v), dot(wx, u));
  if (a0 < 0) a0 += 2 * M_PI;
  EXPECT_TRUE(k.made.corral >> int(a0 * 16 / M_PI) & 1u);
  Hemi open = make([&](D3 d) { return Hit{1.0 / d[2], kWhite}; }, ns, set, 0.25);
  Result ko = run(open);
  EXPECT_EQ(ko.made.corral, 0u);
  expect_matches(ko, reference(open.h, open.s), 1e-4, 1);
}

// (f) Fewer than 7 divisions, or a failed sample: the value alone; no sample: nothing.
TEST(AmbientRecord, ValueOnlyAndFailure) {
  Hemi small = make(sphere(1, D3{2, 2, 2}), 6, settings(0.01, 1, 0.1));
  Result k = run(small);
  EXPECT_EQ(k.made.status, RC_AMB_VALUE_ONLY);
  EXPECT_NEAR(k.rec.val.x, 2.0, 1e-6);
  EXPECT_EQ(k.rec.nrm.w, 0.0f);
  Hemi partial = make(sphere(1, D3{2, 2, 2}), 8, settings(0.01, 1, 0.1));
  partial.s[5].val.w = -1;
  k = run(partial);
  EXPECT_EQ(k.made.status, RC_AMB_VALUE_ONLY);
  EXPECT_NEAR(k.rec.val.x, 2.0 * 63 / 64, 1e-6); // the failed stratum counts as black
  Hemi none = make(sphere(1, D3{2, 2, 2}), 8, settings(0.01, 1, 0.1));
  for (auto& s : none.s)
    s.val.w = -1;
  EXPECT_EQ(run(none).made.status, RC_AMB_FAILED);
  // A black hemisphere: radii from the geometry alone, no gradients, no corral.
  Hemi black = make(ceiling(1, D3{0, 0, 0}), 16, settings(0.001, 1000, 0.1));
  Result kb = run(black);
  Ref rb = reference(black.h, black.s);
  expect_matches(kb, rb, 1e-4, 1);
  EXPECT_EQ(kb.rec.grad.x, 0.0f);
  EXPECT_EQ(kb.rec.grad.w, 0.0f);
  Hemi lit = make(ceiling(1, kWhite), 16, settings(0.001, 1000, 0.1));
  EXPECT_NEAR(kb.rec.nrm.w, run(lit).rec.nrm.w, 1e-4 * kb.rec.nrm.w);
}

// Several hemispheres of different sizes in one launch, each from its own first sample.
TEST(AmbientRecord, BatchMatchesSingles) {
  std::vector<Hemi> hs = {make(wall(0.5, 1.2), 16, settings(0.01, 10, 0.1)),
                          make(ceiling(0.8, kWhite), 7, settings(0.01, 10, 0.1)),
                          make(sphere(2, kWhite), 5, settings(0.01, 10, 0.1)),
                          make(wall(1.5, 0.6), 24, settings(0.01, 10, 0.1), 0.5, 1)};
  std::vector<rc_amb_hemi> hemis;
  std::vector<rc_amb_sample> samples;
  for (Hemi& h : hs) {
    h.h.first = static_cast<std::uint32_t>(samples.size());
    hemis.push_back(h.h);
    samples.insert(samples.end(), h.s.begin(), h.s.end());
  }
  ambient::RecordMaker maker(device::default_context());
  ambient::MadeRecords m = maker.make(hemis, samples);
  ASSERT_EQ(m.records.size(), hs.size());
  for (std::size_t i = 0; i < hs.size(); ++i) {
    SCOPED_TRACE(i);
    Result k{m.records[i], m.made[i]};
    expect_matches(k, reference(hemis[i], samples), 1e-4, 1);
  }
  EXPECT_EQ(m.made[2].status, RC_AMB_VALUE_ONLY);
}

TEST(AmbientRecord, WeightAndFileForm) {
  EXPECT_FLOAT_EQ(ambient::ambient_record_weight(0, 1.0), 1.0f);
  EXPECT_FLOAT_EQ(ambient::ambient_record_weight(2, 0.5), 0.25f);
  EXPECT_FLOAT_EQ(ambient::ambient_record_weight(1, 0.04), 0.05f); // 1.25 x the ray's weight
  EXPECT_FLOAT_EQ(ambient::ambient_record_weight(1, 0.05), 0.5f);

  Hemi hm = make(wall(0.7, 1.0), 16, settings(0.01, 10, 0.1), 0.5, 1);
  Result k = run(hm);
  ASSERT_EQ(k.made.status, RC_AMB_RECORD);
  const std::array<double, 3> centre{100, -50, 20};
  ambient::AmbientRecord a = ambient::to_ambient_record(k.rec, k.made.corral, centre);
  EXPECT_FLOAT_EQ(a.pos[0], float(hm.h.pos.x + 100.0));
  EXPECT_FLOAT_EQ(a.pos[1], float(hm.h.pos.y - 50.0));
  EXPECT_FLOAT_EQ(a.pos[2], float(hm.h.pos.z + 20.0));
  const auto n = ambient::decode_dir(a.ndir), u = ambient::decode_dir(a.udir);
  EXPECT_GT(dot(n, f3(k.rec.nrm)), 1 - 1e-6);
  EXPECT_GT(dot(u, f3(k.rec.udir)), 1 - 1e-6);
  EXPECT_EQ(a.lvl, 1);
  EXPECT_EQ(a.weight, 0.5f);
  EXPECT_EQ(a.rad[0], k.rec.nrm.w);
  EXPECT_EQ(a.rad[1], k.rec.udir.w);
  EXPECT_EQ(a.gpos[0], k.rec.grad.x);
  EXPECT_EQ(a.gdir[1], k.rec.grad.w);
  EXPECT_TRUE(ambient::record_writable(a));
}
