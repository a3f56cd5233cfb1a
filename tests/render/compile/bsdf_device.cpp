// kernels/materials/bsdf_eval.cl on the device against the host reference evaluator
// (radcl/bsdf/evaluate.h), on the reference genBSDF files and the hand-made ones: values,
// totals, the sampler's directions, densities and distribution, and Radiance's preprocessing
// (render/compile/bsdf_tables.h). The device program is built from
// tests/render/compile/bsdf_device_kernel.cl.
#include "radcl/bsdf/evaluate.h"
#include "radcl/bsdf/xml_reader.h"
#include "radcl/device/buffer.h"
#include "radcl/device/context.h"
#include "radcl/device/program.h"
#include "radcl/render/compile/bsdf_tables.h"

#include "files.h"
#include "test_env.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace radcl;
using bsdf::BsdfData;
using bsdf::Component;
using bsdf::Part;
using bsdf::Xyz;
using device::Buffer;
using vec::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
const char* const kFiles[] = {"scenes/blinds_klems.xml", "scenes/film_t3.xml",
                              "scenes/glossy_t3.xml",    "bsdf/klems_3ring.xml",
                              "bsdf/tt3_small.xml",      "bsdf/tt4_small.xml"};

struct Tables {
  std::vector<BsdfData> data;
  render::BsdfTables t;
  Buffer files, comps, vals, ints;
  std::unique_ptr<device::Program> program;
};

Tables& tables() {
  static std::unique_ptr<Tables> s;
  if (s) return *s;
  s = std::make_unique<Tables>();
  for (const char* f : kFiles) {
    s->data.push_back(bsdf::read_bsdf_xml(test::data(f)));
    s->t.add(s->data.back());
  }
  auto& ctx = device::default_context();
  s->files = Buffer::from(ctx, s->t.files);
  s->comps = Buffer::from(ctx, s->t.comps);
  s->vals = Buffer::from(ctx, s->t.vals);
  s->ints = Buffer::from(ctx, s->t.ints);
  const std::string text =
      test::read_file(test::source_dir() + "/tests/render/compile/bsdf_device_kernel.cl");
  // Test kernels are not embedded: they come in as the generated file, which the feature probe
  // (compiled with no material defines, so empty) includes.
  s->program = std::make_unique<device::Program>(
      ctx, device::ProgramSource{{"probe/features.cl"}, text, "-cl-std=CL1.2"});
  return *s;
}

rc_float4 f4(const Vec3& v) {
  return {float(v[0]), float(v[1]), float(v[2]), 0.0f};
}

struct DevEval {
  Xyz f;
  double total, trans, pdf;
};

// Component (file = false) or file functions at pairs of directions.
std::vector<DevEval> dev_eval(uint32_t which, bool file, const std::vector<Vec3>& in,
                              const std::vector<Vec3>& out) {
  Tables& s = tables();
  auto& ctx = device::default_context();
  std::vector<rc_float4> a, b;
  for (size_t i = 0; i < in.size(); ++i)
    a.push_back(f4(in[i])), b.push_back(f4(out[i]));
  Buffer ba = Buffer::from(ctx, a), bb = Buffer::from(ctx, b);
  Buffer res(ctx, 2 * in.size() * sizeof(rc_float4));
  device::Kernel k = s.program->kernel("rc_test_bsdf_eval");
  k.arg(0, s.files).arg(1, s.comps).arg(2, s.vals).arg(3, s.ints).arg(4, which);
  k.arg(5, uint32_t(file)).arg(6, ba).arg(7, bb).arg(8, uint32_t(in.size())).arg(9, res);
  ctx.run(k, in.size());
  ctx.finish();
  auto r = res.to_vector<rc_float4>(2 * in.size());
  std::vector<DevEval> v(in.size());
  for (size_t i = 0; i < in.size(); ++i)
    v[i] = {{r[2 * i].x, r[2 * i].y, r[2 * i].z}, r[2 * i + 1].x, r[2 * i + 1].y, r[2 * i + 1].z};
  return v;
}

struct DevSample {
  Vec3 out;
  double pdf; // 0: nothing drawn
};

std::vector<DevSample> dev_sample(uint32_t which, bool file, const std::vector<Vec3>& in,
                                  std::mt19937_64& rng) {
  Tables& s = tables();
  auto& ctx = device::default_context();
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<rc_float4> a, xi;
  for (const Vec3& v : in) {
    a.push_back(f4(v));
    xi.push_back({u(rng), u(rng), u(rng), 0.0f});
    for (float* x : {&xi.back().x, &xi.back().y, &xi.back().z})
      *x = std::fmin(*x, 0x1.fffffep-1f);
  }
  Buffer ba = Buffer::from(ctx, a), bx = Buffer::from(ctx, xi);
  Buffer res(ctx, in.size() * sizeof(rc_float4));
  device::Kernel k = s.program->kernel("rc_test_bsdf_sample");
  k.arg(0, s.files).arg(1, s.comps).arg(2, s.vals).arg(3, s.ints).arg(4, which);
  k.arg(5, uint32_t(file)).arg(6, ba).arg(7, bx).arg(8, uint32_t(in.size())).arg(9, res);
  ctx.run(k, in.size());
  ctx.finish();
  auto r = res.to_vector<rc_float4>(in.size());
  std::vector<DevSample> v(in.size());
  for (size_t i = 0; i < in.size(); ++i)
    v[i] = {{r[i].x, r[i].y, r[i].z}, r[i].w};
  return v;
}

// A unit vector on the side of zsign, uniform in solid angle, rounded to float as the device
// gets it.
Vec3 random_dir(std::mt19937_64& rng, double zsign) {
  std::uniform_real_distribution<double> u(0, 1);
  const double z = 1e-3 + (1 - 1e-3) * u(rng), phi = 2 * kPi * u(rng);
  const double r = std::sqrt(1 - z * z);
  return {float(r * std::cos(phi)), float(r * std::sin(phi)), float(zsign * z)};
}

bool in_front(Part p) {
  return p == Part::ReflectFront || p == Part::TransmitFront;
}
bool out_front(Part p) {
  return p == Part::ReflectFront || p == Part::TransmitBack;
}
bool transmits(Part p) {
  return p == Part::TransmitFront || p == Part::TransmitBack;
}

// Every component kept on the device, with its file.
struct Comp {
  size_t file;
  uint32_t index;
  const Component* c;
  const rc_bsdf_comp& rec() const { return tables().t.comps[index]; }
};
std::vector<Comp> kept_components() {
  std::vector<Comp> v;
  Tables& s = tables();
  for (size_t f = 0; f < s.data.size(); ++f)
    for (int p = 0; p < 4; ++p)
      if (s.t.files[f].comp[p] != RC_NONE)
        v.push_back({f, s.t.files[f].comp[p], s.data[f].find(Part(p))});
  return v;
}

// The residual's Y on the host: the raw value less the Lambertian part the tables split off.
double host_res(const Comp& k, const Vec3& in, const Vec3& out) {
  return bsdf::f(*k.c, in, out).y - k.rec().lamb.y;
}

// log2 of a tree's finest leaf resolution.
int finest(const bsdf::TensorTree& t, int32_t k = 0, int depth = 0) {
  if (t.nodes[k] >= 0) return depth + t.nodes[k];
  int m = 0;
  for (int c = 0; c < (1 << t.ndim); ++c)
    m = std::max(m, finest(t, t.nodes[k + 1 + c], depth + 1));
  return m;
}
// The host's total for one component (with its Lambertian part), exact on tree leaves.
double host_total(const Comp& k, const Vec3& in) {
  BsdfData one;
  one.format = k.c->format;
  one.components = {*k.c};
  const int n = k.c->format == bsdf::Format::Klems ? 0 : std::max(256, 1 << finest(k.c->tree.y));
  return bsdf::hemispherical(one, in, !transmits(k.c->part), n).y;
}

bool agree(double dev, double host, double rel) {
  return std::fabs(dev - host) <= rel * std::max(std::fabs(host), 1e-6);
}

// A pair whose host value changes within 1e-5 radians of it (a patch or leaf boundary), to
// the device's value: float and double may fall on either side.
bool near_boundary(const Component& c, const Vec3& in, const Vec3& out, double dev, double lamb) {
  const double e = 1e-5;
  for (int which = 0; which < 2; ++which)
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {-1.0, 1.0}) {
        Vec3 a = in, b = out;
        Vec3& v = which ? b : a;
        v[axis] += sign * e;
        v = vec::normalized(v);
        if (agree(dev, bsdf::f(c, a, b).y - lamb, 1e-5)) return true;
      }
  return false;
}

} // namespace

TEST(BsdfDevice, LayoutMatchesHost) {
  auto& ctx = device::default_context();
  Buffer out(ctx, 16 * sizeof(uint32_t));
  device::Kernel k = tables().program->kernel("rc_test_bsdf_layout");
  k.arg(0, out);
  ctx.run(k, 1);
  ctx.finish();
  const auto v = out.to_vector<uint32_t>(12);
  const std::vector<size_t> host = {sizeof(rc_bsdf),
                                    offsetof(rc_bsdf, lamb),
                                    offsetof(rc_bsdf, comp),
                                    offsetof(rc_bsdf, format),
                                    sizeof(rc_bsdf_comp),
                                    offsetof(rc_bsdf_comp, lamb),
                                    offsetof(rc_bsdf_comp, format),
                                    offsetof(rc_bsdf_comp, in_basis),
                                    offsetof(rc_bsdf_comp, values),
                                    offsetof(rc_bsdf_comp, rcdf),
                                    offsetof(rc_bsdf_comp, root),
                                    offsetof(rc_bsdf_comp, max_hemi)};
  for (size_t i = 0; i < host.size(); ++i)
    EXPECT_EQ(v[i], host[i]) << i;
}

// Lambertian parts, drops and the sharing of transmission, on files whose numbers are known.
TEST(BsdfDevice, RadiancePreprocessing) {
  Tables& s = tables();
  const auto& t = s.t;
  // klems_3ring: T (o + 1) + (i + 1) / 100 (+20 X, +30 Z), R the same + 10: minima at o = i = 0.
  const rc_bsdf& k3 = t.files[3];
  EXPECT_FLOAT_EQ(k3.lamb[RC_BSDF_TF].x, 21.01f);
  EXPECT_FLOAT_EQ(k3.lamb[RC_BSDF_TF].y, 1.01f);
  EXPECT_FLOAT_EQ(k3.lamb[RC_BSDF_TF].z, 31.01f);
  EXPECT_FLOAT_EQ(k3.lamb[RC_BSDF_RF].x, 11.01f);
  EXPECT_FLOAT_EQ(k3.lamb[RC_BSDF_TB].y, 1.01f); // no back transmission: the front's
  EXPECT_EQ(k3.lamb[RC_BSDF_RB].y, 0.0f);
  EXPECT_EQ(k3.comp[RC_BSDF_TB], RC_NONE);
  // The largest residual total: incident patch 8, sum over o of (o + 0.08) lambda(o).
  const auto& m = s.data[3].find(Part::TransmitFront)->klems;
  double hemi = 0;
  for (int o = 0; o < 9; ++o)
    hemi += (o + 0.08) * m.out_basis.lambda(o);
  EXPECT_NEAR(t.comps[k3.comp[RC_BSDF_TF]].max_hemi, hemi, 1e-5 * hemi);
  // tt3_small: back transmission is one leaf, 0.25: all Lambertian, the residual dropped, and
  // the front takes it. Front reflection's smallest readable value is 0 (a negative one).
  const rc_bsdf& t3 = t.files[4];
  EXPECT_EQ(t3.comp[RC_BSDF_TB], RC_NONE);
  EXPECT_FLOAT_EQ(t3.lamb[RC_BSDF_TB].y, 0.25f);
  EXPECT_FLOAT_EQ(t3.lamb[RC_BSDF_TF].x, 0.25f);
  EXPECT_NE(t3.comp[RC_BSDF_RF], RC_NONE);
  EXPECT_EQ(t3.lamb[RC_BSDF_RF].y, 0.0f);
  // tt4_small: grey, smallest value 1 >= 1.5/pi: not split. maxHemi: pi times the largest mean
  // over boxes of 1/4 (its smallest leaf) in the incident dimensions, that of children 3, 7,
  // 11 and 15 (the upper halves of both): 4, 8, 12, 16. Transmission: reverse tables too.
  const rc_bsdf& t4 = t.files[5];
  EXPECT_EQ(t4.lamb[RC_BSDF_TF].y, 0.0f);
  const rc_bsdf_comp& c4 = t.comps[t4.comp[RC_BSDF_TF]];
  EXPECT_NEAR(c4.max_hemi, kPi * (4 + 8 + 12 + 16) / 4, 1e-5);
  EXPECT_GE(t.ints[c4.root + 2], 0);
  std::printf("[ tables ] %zu files, %zu components kept: %zu floats, %zu ints\n", t.files.size(),
              t.comps.size(), t.vals.size(), t.ints.size());
  for (size_t f = 0; f < s.data.size(); ++f)
    if (s.data[f].format != bsdf::Format::Klems)
      std::printf("[ tables ] %-24s finest leaf 1/%d\n", kFiles[f],
                  1 << finest(s.data[f].components[0].tree.y));
  // The reference files: Lambertian parts within the totals; what was dropped was at most
  // 0.001 above its Lambertian part.
  for (size_t f = 0; f < s.data.size(); ++f)
    for (const Component& c : s.data[f].components) {
      const int p = int(c.part);
      const Vec3 in{0.3, 0.2, in_front(c.part) ? 0.932 : -0.932};
      BsdfData one;
      one.format = c.format;
      one.components = {c};
      const double total = bsdf::hemispherical(one, in, !transmits(c.part), 512).y;
      EXPECT_LE(kPi * t.files[f].lamb[p].y, total * (1 + 1e-5) + 1e-6) << kFiles[f] << " " << p;
      if (t.files[f].comp[p] == RC_NONE)
        EXPECT_LE(total - kPi * t.files[f].lamb[p].y, 0.001 + 1e-6) << kFiles[f] << " " << p;
      else
        EXPECT_GT(t.comps[t.files[f].comp[p]].max_hemi, 0.001f);
    }
}

// A component whose residual is negligible is dropped, keeping its Lambertian part; a grey
// tree at 1.5/pi or more keeps all of it.
TEST(BsdfDevice, DropsNegligibleResiduals) {
  BsdfData d;
  d.format = bsdf::Format::Klems;
  Component c;
  c.part = Part::ReflectBack;
  c.klems.in_basis = c.klems.out_basis = *bsdf::KlemsBasis::standard("LBNL/Klems Quarter");
  c.klems.y.assign(41 * 41, 0.1f);
  c.klems.y[5] = 0.1003f; // residual total 0.0003 * lambda(0) at most
  d.components.push_back(c);
  render::BsdfTables t;
  t.add(d);
  EXPECT_EQ(t.files[0].comp[RC_BSDF_RB], RC_NONE);
  EXPECT_FLOAT_EQ(t.files[0].lamb[RC_BSDF_RB].y, 0.1f);
  EXPECT_TRUE(t.comps.empty());
  BsdfData g;
  g.format = bsdf::Format::TensorTree3;
  Component tc;
  tc.format = bsdf::Format::TensorTree3;
  tc.tree.y = bsdf::parse_tensor_tree("{ 0.5 }", 3);
  g.components.push_back(tc);
  t.add(g);
  ASSERT_NE(t.files[1].comp[RC_BSDF_RF], RC_NONE);
  EXPECT_EQ(t.files[1].lamb[RC_BSDF_RF].y, 0.0f);
  EXPECT_NEAR(t.comps[0].max_hemi, 0.5 * kPi, 1e-6);
}

// f of every component at random pairs (and reversed pairs for transmission): the device's
// residual plus the Lambertian part against the host's value, to 1e-5 relative in X, Y and Z.
TEST(BsdfDevice, ValuesAgreeWithHost) {
  std::mt19937_64 rng(11);
  for (const Comp& k : kept_components()) {
    const Part p = k.c->part;
    std::vector<Vec3> in, out;
    for (int i = 0; i < 1000; ++i) {
      const bool rev = transmits(p) && i % 2; // light from the other side (reciprocity)
      const double si = in_front(p) ? 1 : -1, so = out_front(p) ? 1 : -1;
      in.push_back(random_dir(rng, rev ? so : si));
      out.push_back(random_dir(rng, rev ? si : so));
    }
    const auto dev = dev_eval(k.index, false, in, out);
    const rc_float4 l = k.rec().lamb;
    int boundary = 0;
    double worst = 0;
    for (size_t i = 0; i < in.size(); ++i) {
      const Xyz h = bsdf::f(*k.c, in[i], out[i]);
      const Xyz d{dev[i].f.x + l.x, dev[i].f.y + l.y, dev[i].f.z + l.z};
      if (agree(d.x, h.x, 1e-5) && agree(d.y, h.y, 1e-5) && agree(d.z, h.z, 1e-5)) {
        worst = std::max(worst, std::fabs(d.y - h.y) / std::max(h.y, 1e-6));
        continue;
      }
      ++boundary;
      EXPECT_TRUE(near_boundary(*k.c, in[i], out[i], dev[i].f.y, l.y))
          << kFiles[k.file] << " part " << int(p) << " pair " << i << ": " << d.y << " vs " << h.y;
    }
    EXPECT_LE(boundary, 10) << kFiles[k.file] << " part " << int(p);
    std::printf("[ values ] %-24s part %d: largest relative error %.2g, %d boundary pairs\n",
                kFiles[k.file], int(p), worst, boundary);
  }
}

// Directional-hemispherical totals: the device's residual total plus pi times the Lambertian
// part against the host's sum (Klems) or quadrature on the tree's own cells.
TEST(BsdfDevice, TotalsAgreeWithHost) {
  std::mt19937_64 rng(12);
  for (const Comp& k : kept_components()) {
    const Part p = k.c->part;
    std::vector<Vec3> in;
    for (int i = 0; i < 12; ++i)
      in.push_back(random_dir(rng, in_front(p) != (transmits(p) && i >= 8) ? 1 : -1));
    const auto dev = dev_eval(k.index, false, in, in);
    double worst = 0;
    for (size_t i = 0; i < in.size(); ++i) {
      const bool rev = (in[i][2] > 0) != in_front(p);
      if (rev && k.c->format == bsdf::Format::TensorTree3) { // not sampled, as in Radiance
        EXPECT_EQ(dev[i].total, 0.0);
        continue;
      }
      const double h = host_total(k, in[i]), d = dev[i].total + kPi * k.rec().lamb.y;
      EXPECT_TRUE(agree(d, h, 1e-5))
          << kFiles[k.file] << " part " << int(p) << ": " << d << " vs " << h;
      worst = std::max(worst, std::fabs(d - h) / h);
    }
    std::printf("[ totals ] %-24s part %d: largest relative error %.2g\n", kFiles[k.file], int(p),
                worst);
  }
}

namespace {

// The bin of a sampled direction, and each bin's probability from the host: outgoing (or,
// reversed, incident) patches for Klems; an 8 x 8 grid of the square the descent picks in.
struct Bins {
  std::vector<double> p;
  std::function<int(const Vec3&)> of;
};

Bins bins_for(const Comp& k, const Vec3& in) {
  const Component& c = *k.c;
  const bool rev = (in[2] > 0) != in_front(c.part) && in[2] != 0;
  const double lamb = k.rec().lamb.y;
  Bins b;
  if (c.format == bsdf::Format::Klems) {
    const auto& m = c.klems;
    const int fixed = rev ? bsdf::outgoing_patch(m.out_basis, in, out_front(c.part))
                          : bsdf::incident_patch(m.in_basis, in, in_front(c.part));
    const auto& basis = rev ? m.in_basis : m.out_basis;
    for (int j = 0; j < basis.size(); ++j)
      b.p.push_back(((rev ? m.value(j, fixed) : m.value(fixed, j)) - lamb) * basis.lambda(j));
    b.of = [&c, rev](const Vec3& out) {
      return rev ? bsdf::incident_patch(c.klems.in_basis, out, in_front(c.part))
                 : bsdf::outgoing_patch(c.klems.out_basis, out, out_front(c.part));
    };
  } else {
    const bsdf::TensorTree& t = c.tree.y;
    const int first = t.ndim == 3 ? 1 : rev ? 0 : 2; // the picked dimensions
    const double zs = (rev ? in_front(c.part) : out_front(c.part)) ? 1 : -1;
    const double a = t.ndim == 3 ? std::atan2(-in[1], -in[0]) : 0;
    const int n = std::max(64, 1 << finest(t));
    b.p.assign(64, 0.0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        auto d = bsdf::square_to_disk((i + 0.5) / n, (j + 0.5) / n);
        if (rev) d = {-d[0], -d[1]};
        const Vec3 o{d[0] * std::cos(a) - d[1] * std::sin(a),
                     d[0] * std::sin(a) + d[1] * std::cos(a),
                     zs * std::sqrt(std::fmax(0.0, 1 - d[0] * d[0] - d[1] * d[1]))};
        b.p[(i * 8 / n) * 8 + j * 8 / n] += host_res(k, in, o);
      }
    b.of = [&t, in, rev, first](const Vec3& out) {
      const auto pos = rev ? t.position(out, in) : t.position(in, out);
      return std::min(7, int(pos[first] * 8)) * 8 + std::min(7, int(pos[first + 1] * 8));
    };
  }
  double sum = 0;
  for (double v : b.p)
    sum += v;
  for (double& v : b.p)
    v /= sum;
  return b;
}

} // namespace

// The component sampler: unit directions on the right side; the density f cos / total; the
// Monte-Carlo total within 4 standard errors of the host's; bins filled as the host predicts.
TEST(BsdfDevice, ComponentSamplingMatchesHost) {
  std::mt19937_64 rng(13);
  const int n = 20000;
  for (const Comp& k : kept_components()) {
    const Part p = k.c->part;
    for (int dir = 0; dir < 6; ++dir) {
      const bool rev = transmits(p) && dir >= 4;
      const Vec3 in = random_dir(rng, in_front(p) != rev ? 1 : -1);
      if (rev && k.c->format == bsdf::Format::TensorTree3) { // not sampled, as in Radiance
        for (const DevSample& x : dev_sample(k.index, false, std::vector<Vec3>(100, in), rng))
          EXPECT_EQ(x.pdf, 0.0);
        continue;
      }
      const double total = host_total(k, in) - kPi * k.rec().lamb.y;
      const auto s = dev_sample(k.index, false, std::vector<Vec3>(n, in), rng);
      if (!(total > 1e-9)) { // nothing to sample (glossy_t3's transmission near the normal)
        for (const DevSample& x : s)
          EXPECT_EQ(x.pdf, 0.0);
        continue;
      }
      const double zs = (rev ? in_front(p) : out_front(p)) ? 1 : -1;
      const Bins b = bins_for(k, in);
      std::vector<int> count(b.p.size(), 0);
      double sum = 0, sum2 = 0, worst = 0;
      int failed = 0, off = 0;
      for (const DevSample& x : s) {
        if (!(x.pdf > 0)) {
          ++failed;
          continue;
        }
        ASSERT_NEAR(vec::length(x.out), 1.0, 1e-5);
        ASSERT_GE(zs * x.out[2], 0.0);
        const double f = host_res(k, in, x.out), want = f * std::fabs(x.out[2]) / total;
        if (agree(x.pdf, want, 1e-4)) {
          worst = std::max(worst, std::fabs(x.pdf - want) / want);
        } else {
          ++off;
          EXPECT_TRUE(
              near_boundary(*k.c, in, x.out, x.pdf * total / std::fabs(x.out[2]), k.rec().lamb.y))
              << kFiles[k.file] << " part " << int(p) << ": pdf " << x.pdf << " vs " << want;
        }
        const double e = f * std::fabs(x.out[2]) / x.pdf;
        sum += e, sum2 += e * e;
        ++count[b.of(x.out)];
      }
      EXPECT_LE(failed, n / 1000) << kFiles[k.file] << " part " << int(p);
      EXPECT_LE(off, n / 1000) << kFiles[k.file] << " part " << int(p);
      const double mean = sum / n, se = std::sqrt(std::fmax(0.0, sum2 / n - mean * mean) / n);
      EXPECT_NEAR(mean, total, 4 * se + 2e-5 * total) << kFiles[k.file] << " part " << int(p);
      double chi = 0; // per-bin deviations in standard deviations
      for (size_t j = 0; j < b.p.size(); ++j) {
        const double want = (n - failed) * b.p[j], sd = std::sqrt(want * (1 - b.p[j]));
        EXPECT_LE(std::fabs(count[j] - want), 5 * sd + 3) << kFiles[k.file] << " bin " << j;
        chi = std::max(chi, sd > 0 ? std::fabs(count[j] - want) / sd : 0.0);
      }
      std::printf("[ sample ] %-24s part %d%s: pdf error %.2g, MC total %.6g +- %.2g vs %.6g, "
                  "largest bin deviation %.2f sd\n",
                  kFiles[k.file], int(p), rev ? " (reciprocal)" : "", worst, mean, se, total, chi);
    }
  }
}

// Whole files: f with the Lambertian parts against the host's f for pairs anywhere, the
// reflectance and transmittance, and the Monte-Carlo total of the file sampler.
TEST(BsdfDevice, FilesAgreeWithHost) {
  std::mt19937_64 rng(14);
  Tables& s = tables();
  for (uint32_t f = 0; f < s.data.size(); ++f) {
    const BsdfData& d = s.data[f];
    std::vector<Vec3> in, out;
    for (int i = 0; i < 1000; ++i) {
      in.push_back(random_dir(rng, i % 2 ? 1 : -1));
      out.push_back(random_dir(rng, i % 4 < 2 ? 1 : -1));
    }
    const auto dev = dev_eval(f, true, in, out);
    int boundary = 0;
    for (size_t i = 0; i < in.size(); ++i) {
      const double h = bsdf::f(d, in[i], out[i]).y;
      if (agree(dev[i].f.y, h, 1e-5)) continue;
      const Component* c = bsdf::component_for(d, in[i], out[i]);
      ASSERT_TRUE(c) << kFiles[f];
      ++boundary;
      EXPECT_TRUE(near_boundary(*c, in[i], out[i], dev[i].f.y, 0)) << kFiles[f] << " " << i;
    }
    EXPECT_LE(boundary, 10) << kFiles[f];
    for (size_t i = 0; i < 8; ++i) {
      const double r = bsdf::hemispherical(d, in[i], true, 512).y;
      const double t = bsdf::hemispherical(d, in[i], false, 512).y;
      EXPECT_TRUE(agree(dev[i].total, r, 1e-4)) << kFiles[f] << ": " << dev[i].total << " " << r;
      // Transmission through a TT3 tree's reciprocity is not sampled, so not in the total.
      const Component* tc = bsdf::component_for(d, in[i], {0, 0, -in[i][2]});
      const bool unsampled = tc && tc->format == bsdf::Format::TensorTree3 &&
                             in_front(tc->part) != (in[i][2] > 0) &&
                             s.t.files[f].comp[int(tc->part)] != RC_NONE;
      if (unsampled) { // only the Lambertian part
        const rc_bsdf& rec = s.t.files[f];
        EXPECT_FLOAT_EQ(dev[i].trans, kPi * rec.lamb[in[i][2] > 0 ? RC_BSDF_TF : RC_BSDF_TB].y);
        continue;
      }
      EXPECT_TRUE(agree(dev[i].trans, t, 1e-4)) << kFiles[f] << ": " << dev[i].trans << " " << t;
      const int n = 20000;
      const auto smp = dev_sample(f, true, std::vector<Vec3>(n, in[i]), rng);
      double sum = 0, sum2 = 0;
      int failed = 0, off = 0;
      for (const DevSample& x : smp) {
        if (!(x.pdf > 0)) {
          ++failed;
          continue;
        }
        EXPECT_NEAR(vec::length(x.out), 1.0, 1e-5);
        const double e = bsdf::f(d, in[i], x.out).y * std::fabs(x.out[2]) / x.pdf;
        const double want = bsdf::f(d, in[i], x.out).y * std::fabs(x.out[2]) / (r + t);
        if (!agree(x.pdf, want, 1e-4)) {
          ++off;
          EXPECT_TRUE(near_boundary(*bsdf::component_for(d, in[i], x.out), in[i], x.out,
                                    x.pdf * (r + t) / std::fabs(x.out[2]), 0))
              << kFiles[f] << ": pdf " << x.pdf << " vs " << want;
        }
        sum += e, sum2 += e * e;
      }
      EXPECT_LE(failed, n / 1000) << kFiles[f];
      EXPECT_LE(off, n / 1000) << kFiles[f];
      const double mean = sum / n, se = std::sqrt(std::fmax(0.0, sum2 / n - mean * mean) / n);
      EXPECT_NEAR(mean, r + t, 4 * se + 2e-5 * (r + t)) << kFiles[f];
      std::printf("[ file   ] %-24s in.z %+.2f: R %.5g T %.5g, MC R+T %.6g +- %.2g, %d boundary "
                  "samples\n",
                  kFiles[f], in[i][2], r, t, mean, se, off);
    }
  }
}
