// kernels/lights/sources.cl on the device: irradiance summed over every -ds sample of a source
// against analytic irradiance, Radiance's partition counts, and the spotlight, glow and
// behind-the-source cut-offs.
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <memory>
#include <numbers>
#include <string>
#include <unistd.h>
#include <vector>

#include "files.h"
#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device/program.h"
#include "radcl/render/lights/light_sources.h"
#include "radcl/scene/loader.h"
#include "temp_dir.h"
#include "test_env.h"

using namespace radcl;
using radcl::device::Buffer;

namespace {

constexpr double kPi = std::numbers::pi;
using D3 = std::array<double, 3>;

struct Pt {
  D3 p, n;
};
struct Res {
  double e = 0; // red channel irradiance
  unsigned cells = 0;
  unsigned usable = 0;
  double omega = 0, first_dist = 0;
};

rc_float4 f4(double x, double y, double z, double w = 0) {
  return {float(x), float(y), float(z), float(w)};
}

D3 unit(D3 a) {
  const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return {a[0] / l, a[1] / l, a[2] / l};
}

device::Program& program() {
  static std::unique_ptr<device::Program> p;
  if (!p) {
    // A test kernel is not embedded: it comes in as the generated file, which the feature
    // probe (no material defines, so it adds nothing) includes.
    const std::string text =
        test::read_file(test::source_dir() + "/tests/render/lights/test_sources.cl");
    p = std::make_unique<device::Program>(device::default_context(),
                                          device::ProgramSource{{"probe/features.cl"}, text, ""});
  }
  return *p;
}

std::vector<Res> run(const rc_source& s, const std::vector<rc_float4>& verts,
                     const std::vector<Pt>& pts, float ds, float dj, unsigned seed = 1) {
  auto& ctx = device::default_context();
  std::vector<rc_float4> pp, nn;
  for (const Pt& q : pts) {
    pp.push_back(f4(q.p[0], q.p[1], q.p[2]));
    D3 n = q.n == D3{0, 0, 0} ? q.n : unit(q.n);
    nn.push_back(f4(n[0], n[1], n[2]));
  }
  Buffer bs = Buffer::from(ctx, std::vector<rc_source>{s});
  Buffer bv = Buffer::from(ctx, verts.empty() ? std::vector<rc_float4>{f4(0, 0, 0)} : verts);
  Buffer bp = Buffer::from(ctx, pp), bn = Buffer::from(ctx, nn);
  Buffer out(ctx, 2 * pts.size() * sizeof(rc_float4));
  device::Kernel k = program().kernel("rc_test_source_irradiance");
  k.arg(0, bs).arg(1, bv).arg(2, bp).arg(3, bn);
  k.arg(4, static_cast<std::uint32_t>(pts.size())).arg(5, ds).arg(6, dj).arg(7, seed);
  k.arg(8, out);
  ctx.run(k, pts.size());
  ctx.finish();
  auto o = out.to_vector<rc_float4>(2 * pts.size());
  std::vector<Res> r(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    r[i].e = o[2 * i].x;
    r[i].cells = static_cast<unsigned>(o[2 * i].w);
    r[i].usable = static_cast<unsigned>(o[2 * i + 1].x);
    r[i].omega = o[2 * i + 1].y;
    r[i].first_dist = o[2 * i + 1].z;
  }
  return r;
}

// Irradiance per point: one run without jitter; with jitter the mean over 64 seeds, since one
// jittered sample per part is unbiased but noisy (several percent this close to a source).
std::vector<double> irradiance(const rc_source& s, const std::vector<rc_float4>& verts,
                               const std::vector<Pt>& pts, float ds, float dj) {
  const unsigned seeds = dj > 0 ? 64 : 1;
  std::vector<double> e(pts.size(), 0.0);
  for (unsigned seed = 0; seed < seeds; ++seed) {
    auto r = run(s, verts, pts, ds, dj, seed);
    for (std::size_t i = 0; i < pts.size(); ++i)
      e[i] += r[i].e / seeds;
  }
  return e;
}

rc_source base(unsigned kind, double L) {
  rc_source s{};
  s.kind = kind;
  s.surface = 0;
  s.emit = f4(L, L, L);
  s.spot = f4(0, 0, 0, -2);
  return s;
}

// Disc of radius r at the origin facing down (-z).
rc_source disc(double r, double L) {
  rc_source s = base(RC_SRC_FLAT, L);
  s.pos = f4(0, 0, 0, r);
  s.axis = f4(0, 0, -1, kPi * r * r);
  s.su = f4(r, 0, 0, 0);
  s.sv = f4(0, -r, 0, 0); // su x sv along -z
  return s;
}

// Unit square [0,1]^2 at z = 0 facing down, vertices counter-clockwise about -z.
const std::vector<rc_float4> kSquare = {f4(0, 0, 0, 1), f4(0, 1, 0, 1), f4(1, 1, 0, 1),
                                        f4(1, 0, 0, 1)};
rc_source square(double L) {
  rc_source s = base(RC_SRC_FLAT, L);
  s.pos = f4(0.5, 0.5, 0, std::sqrt(0.5));
  s.axis = f4(0, 0, -1, 1);
  s.su = f4(0, 0.5, 0, 0);
  s.sv = f4(0.5, 0, 0, 0);
  s.verts = 0;
  s.nverts = 4;
  return s;
}

rc_source sphere(D3 c, double r, double L) {
  rc_source s = base(RC_SRC_SPHERE, L);
  s.pos = f4(c[0], c[1], c[2], r);
  s.axis = f4(0, 0, 0, kPi * r * r);
  return s;
}

// Exact irradiance from a uniform polygon wholly above the horizon (Lambert's edge formula).
double polygon_irradiance(const std::vector<rc_float4>& v, const Pt& q, double L) {
  const D3 n = unit(q.n);
  double sum = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const rc_float4 &a4 = v[i], &b4 = v[(i + 1) % v.size()];
    D3 a = unit({a4.x - q.p[0], a4.y - q.p[1], a4.z - q.p[2]});
    D3 b = unit({b4.x - q.p[0], b4.y - q.p[1], b4.z - q.p[2]});
    const double c = std::clamp(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], -1.0, 1.0);
    D3 x = unit({a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]});
    sum += std::acos(c) * (x[0] * n[0] + x[1] * n[1] + x[2] * n[2]);
  }
  return 0.5 * L * std::abs(sum);
}

void expect_rel(double got, double want, double tol, const std::string& what) {
  EXPECT_NEAR(got, want, tol * want)
      << what << ": got " << got << ", want " << want << " (rel " << (got - want) / want << ")";
}

const float kDs[] = {0.05f, 0.01f};
const float kDj[] = {0.0f, 1.0f};

} // namespace

TEST(SourceSampling, DiscOnAxis) {
  const double r = 0.5, L = 100;
  const rc_source s = disc(r, L);
  std::vector<Pt> pts;
  const double hs[] = {0.5, 1, 2, 4};
  for (double h : hs)
    pts.push_back({{0, 0, -h}, {0, 0, 1}});
  for (float ds : kDs)
    for (float dj : kDj) {
      auto e = irradiance(s, {}, pts, ds, dj);
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const double want = kPi * L * r * r / (r * r + hs[i] * hs[i]);
        expect_rel(e[i], want, 0.01,
                   "disc h=" + std::to_string(hs[i]) + " ds=" + std::to_string(ds) +
                       " dj=" + std::to_string(dj));
      }
    }
}

TEST(SourceSampling, SquarePolygon) {
  const double L = 10;
  const rc_source s = square(L);
  const std::vector<Pt> pts = {{{0.5, 0.5, -0.5}, {0, 0, 1}},   {{0.5, 0.5, -1}, {0, 0, 1}},
                               {{0.2, 0.7, -0.3}, {0, 0, 1}},   {{1.5, 0.2, -0.5}, {0, 0, 1}},
                               {{0.3, 0.6, -0.4}, {0.3, 0, 1}}, {{-1, -1, -2}, {0.2, 0.4, 1}}};
  for (float ds : kDs)
    for (float dj : kDj) {
      auto e = irradiance(s, kSquare, pts, ds, dj);
      for (std::size_t i = 0; i < pts.size(); ++i)
        expect_rel(e[i], polygon_irradiance(kSquare, pts[i], L), 0.01,
                   "square point " + std::to_string(i) + " ds=" + std::to_string(ds) +
                       " dj=" + std::to_string(dj));
    }
}

TEST(SourceSampling, TrianglePolygonFromCompiler) {
  // A triangle goes through compile_sources(): covering rectangle off its centroid, cells
  // that the triangle only partly covers.
  const test::TempFolder dir("source_sampling");
  const auto path = dir / "t.rad";
  std::ofstream(path) << "void light l 0 0 3 10 10 10\nl polygon t 0 0 9  0 0 0  0 3 0  4 0 0\n";
  scene::LoadedScene ls = scene::load_scene({path.string()});
  geometry::SceneGeometry geom(ls);
  auto cs = render::compile_sources(ls.main, geom, [](std::int32_t) { return 0u; });
  ASSERT_EQ(cs.sources.size(), 1u);
  const auto c = geom.centre();
  std::vector<rc_float4> world = {f4(0, 0, 0), f4(0, 3, 0), f4(4, 0, 0)};
  const std::vector<Pt> pts = {
      {{1, 1, -0.5}, {0, 0, 1}}, {{2, 2, -1.5}, {0, 0, 1}}, {{-1, 0.5, -1.5}, {0.5, 0, 1}}};
  std::vector<Pt> local;
  for (const Pt& q : pts)
    local.push_back({{q.p[0] - c[0], q.p[1] - c[1], q.p[2] - c[2]}, q.n});
  for (float ds : kDs)
    for (float dj : kDj) {
      auto e = irradiance(cs.sources[0], cs.verts, local, ds, dj);
      for (std::size_t i = 0; i < pts.size(); ++i)
        expect_rel(e[i], polygon_irradiance(world, pts[i], 10), 0.01,
                   "triangle point " + std::to_string(i) + " ds=" + std::to_string(ds) +
                       " dj=" + std::to_string(dj));
    }
}

TEST(SourceSampling, SphereOnAndOffAxis) {
  const double r = 0.1, L = 1000;
  const rc_source s = sphere({0, 0, 0}, r, L);
  // Jitter moves the one sample across the projected disc, which lowers the mean cosine by
  // about r^2 / (4 d^2) (Radiance's jitter inside the sphere does likewise): 0.4% at d = 0.8.
  const std::vector<Pt> pts = {{{0, 0, -0.8}, {0, 0, 1}},
                               {{0, 0, -2}, {0, 0, 1}},
                               {{0, 0, -1}, {std::sqrt(3.0), 0, 1}}}; // 60 degrees off
  const double want[] = {kPi * L * r * r / 0.64, kPi * L * r * r / 4, 0.5 * kPi * L * r * r};
  for (float ds : kDs)
    for (float dj : kDj) {
      auto e = irradiance(s, {}, pts, ds, dj);
      for (std::size_t i = 0; i < pts.size(); ++i) {
        EXPECT_EQ(run(s, {}, {pts[i]}, ds, dj)[0].cells, 1u); // Radiance never divides a sphere
        expect_rel(e[i], want[i], 0.01, "sphere point " + std::to_string(i));
      }
    }
}

TEST(SourceSampling, DistantSource) {
  const double L = 1e5, angle = 0.533 * kPi / 180;
  const double omega = 2 * kPi * (1 - std::cos(angle / 2));
  rc_source s = base(RC_SRC_DISTANT, L);
  s.pos = f4(0, 0, 1, std::sqrt(omega / kPi));
  s.axis = f4(0, 0, 1, omega);
  s.surface = RC_NONE;
  const std::vector<Pt> pts = {{{0, 0, 0}, {0, 0, 1}}, {{5, 3, 1}, {1, 0, std::sqrt(3.0)}}};
  for (float ds : kDs)
    for (float dj : kDj) {
      auto res = run(s, {}, pts, ds, dj);
      EXPECT_EQ(res[0].cells, 1u);
      EXPECT_GT(res[0].first_dist, 1e9);
      auto e = irradiance(s, {}, pts, ds, dj);
      expect_rel(e[0], L * omega, 1e-3, "distant normal incidence");
      expect_rel(e[1], L * omega * std::cos(kPi / 6), 1e-3, "distant at 30 degrees");
    }
}

TEST(SourceSampling, Cylinder) {
  // Thin tube along x from -2 to 2 seen from 1 below its middle: Radiance's model (projected
  // width 2r sin(theta)) integrates to 2 r L [x / (2(1+x^2)) + atan(x) / 2] from -2 to 2.
  const double r = 0.02, L = 500;
  rc_source s = base(RC_SRC_CYLINDER, L);
  s.pos = f4(0, 0, 0, r);
  s.axis = f4(1, 0, 0, 4);
  const double want = 2 * r * L * 2 * (2.0 / 10 + std::atan(2.0) / 2);
  const std::vector<Pt> pts = {{{0, 0, -1}, {0, 0, 1}}};
  for (float ds : kDs)
    for (float dj : kDj) {
      EXPECT_GT(run(s, {}, pts, ds, dj)[0].cells, 8u);
      expect_rel(irradiance(s, {}, pts, ds, dj)[0], want, 0.01,
                 "cylinder ds=" + std::to_string(ds));
    }
  EXPECT_EQ(run(s, {}, pts, 0, 0)[0].cells, 1u);
  EXPECT_EQ(run(s, {}, {{{1, 0, -0.01}, {0, 0, 1}}}, 0.05f, 0)[0].cells, 0u); // inside
}

TEST(SourceSampling, PartitionCounts) {
  const rc_source s = square(1);
  // Worked by hand after Radiance's flt_partit(): at 1.5 below the centre with ds 0.5 the
  // square splits once each way (4 parts); at 2.5 it stays whole.
  auto res = run(
      s, kSquare,
      {{{0.5, 0.5, -1.5}, {0, 0, 1}}, {{0.5, 0.5, -2.5}, {0, 0, 1}}, {{0.5, 0.5, -0.5}, {0, 0, 1}}},
      0.5f, 0);
  EXPECT_EQ(res[0].cells, 4u);
  EXPECT_EQ(res[1].cells, 1u);
  EXPECT_EQ(run(s, kSquare, {{{0.5, 0.5, -0.5}, {0, 0, 1}}}, 0.05f, 0)[0].cells, 64u);
  // ds = 0: one sample of the whole source.
  auto one = run(s, kSquare, {{{0.5, 0.5, -0.2}, {0, 0, 1}}, {{3, 2, -1}, {0, 0, 1}}}, 0, 0);
  for (const Res& o : one) {
    EXPECT_EQ(o.cells, 1u);
    EXPECT_EQ(o.usable, 1u);
  }
  // The one sample stands for the whole square at its centre (0.5, 0.5, 0), seen from (3, 2, -1):
  // L * area * cos * cos' / d^2 with cos = cos' = 1 / |(-2.5, -1.5, 1)|.
  const double d2 = 2.5 * 2.5 + 1.5 * 1.5 + 1;
  expect_rel(one[1].e, 1.0 / (d2 * d2), 1e-4, "one sample of the whole square");
  EXPECT_EQ(run(disc(0.5, 1), {}, {{{0, 0, -0.1}, {0, 0, 1}}}, 0, 0)[0].cells, 1u);
  // Behind a flat source: nothing.
  auto behind = run(s, kSquare, {{{0.5, 0.5, 1}, {0, 0, -1}}}, 0.05f, 0);
  EXPECT_EQ(behind[0].cells, 0u);
  EXPECT_EQ(behind[0].e, 0);
  // Below the receiving surface's horizon: unusable samples.
  auto under = run(s, kSquare, {{{0.5, 0.5, -1}, {0, 0, -1}}}, 0.05f, 0);
  EXPECT_GT(under[0].cells, 1u);
  EXPECT_EQ(under[0].usable, 0u);
}

TEST(SourceSampling, SpotlightCone) {
  // Small disc aimed down with a 40 degree cone and its focus 1 behind the disc: inside the
  // cone the solid angle shrinks by d^2 / (d + 1)^2.
  const double r = 0.05, L = 1000;
  rc_source s = disc(r, L);
  s.flags = RC_SRCF_SPOT;
  s.spot = f4(0, 0, -1, std::cos(20 * kPi / 180));
  s.spot_focus = 1;
  auto res =
      run(s, {}, {{{0, 0, -2}, {0, 0, 1}}, {{0.5, 0, -2}, {0, 0, 1}}, {{2, 0, -2}, {0, 0, 1}}},
          0.05f, 0);
  const double on_axis = kPi * L * r * r / (r * r + 4) * (4.0 / 9);
  expect_rel(res[0].e, on_axis, 0.01, "spot on axis");
  EXPECT_GT(res[1].e, 0); // 14 degrees off the axis
  EXPECT_EQ(res[2].e, 0); // 45 degrees: outside the cone
  EXPECT_GT(res[2].usable, 0u);
}

TEST(SourceSampling, GlowRadius) {
  const double r = 0.12, L = 50;
  rc_source s = sphere({0, 0, 0}, r, L);
  s.flags = RC_SRCF_GLOW;
  s.emit.w = 1.5f;
  auto res =
      run(s, {}, {{{0, 0, -1.4}, {0, 0, 1}}, {{0, 0, -1.55}, {0, 0, 1}}, {{0, 0, -1.7}, {0, 0, 1}}},
          0.05f, 0);
  expect_rel(res[0].e, kPi * L * r * r / (1.4 * 1.4), 0.01, "glow within reach");
  EXPECT_EQ(res[1].cells, 1u); // within reach of the sphere's surface, not of its centre
  EXPECT_EQ(res[1].e, 0);
  EXPECT_EQ(res[2].cells, 0u); // beyond radius + sphere radius: skipped outright
}
