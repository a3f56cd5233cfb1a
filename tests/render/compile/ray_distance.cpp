// The ray variable T (calc-language.md §5.1): the length of the whole ray tree from the
// primary's start to the point a pattern is evaluated at, times S, as Radiance's raydist()
// sums the segments up the parent chain; Ts: the segment plus the shadow segments before it.
// A glowing floor (z = 0, radiance 1, modulated by a brightfunc of T) seen directly, in a
// mirror, through glass and through surfaces a ray passes; a glowing ceiling seen by ambient
// samples; light sources and glass panes met by shadow rays, where a pattern's effect is the
// ratio of the floor's radiance with it to the radiance without it. Hand values: the segments'
// lengths.
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>
#include <vector>

#include "radcl/ambient/cache.h"
#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;
namespace fs = std::filesystem;

namespace {

const char* kCal = R"(
{ distances seen by patterns }
total = T;
shadow = Ts;
)";

// The floor: a glow of radiance 1 (no light source: radius 0) with modifier `mod`.
std::string floor_glow(const std::string& mod) {
  return mod + " glow floorg 0 0 4 1 1 1 0\n" +
         "floorg polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
}
// A horizontal square of half-size h at height z with modifier `mod`, facing up or down.
std::string pane(const std::string& mod, const std::string& name, double z, bool up,
                 double h = 10) {
  const std::string zs = std::to_string(z), a = std::to_string(-h), b = std::to_string(h);
  std::string v0 = a + " " + a + " " + zs, v1 = b + " " + a + " " + zs, v2 = b + " " + b + " " + zs,
              v3 = a + " " + b + " " + zs;
  return mod + " polygon " + name + " 0 0 12 " +
         (up ? v0 + " " + v1 + " " + v2 + " " + v3 : v0 + " " + v3 + " " + v2 + " " + v1) + "\n";
}

struct Ray {
  std::array<double, 3> org, dir;
};

class RayDistance : public test::SceneDir {
protected:
  void SetUp() override {
    test::SceneDir::SetUp();
    std::ofstream(dir / "t.cal") << kCal;
  }
  // Red channel of each ray's radiance in `scene`.
  static render::RenderSettings settings(bool bv = true) {
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    st.ds = 0; // one sample per source: its centre
    st.dt = 0; // every shadow ray tested
    st.bv = bv;
    return st;
  }
  std::vector<double> render(const std::string& scene, const std::vector<Ray>& rays,
                             bool bv = true) {
    return render(scene, rays, settings(bv));
  }
  std::vector<double> render(const std::string& scene, const std::vector<Ray>& rays,
                             const render::RenderSettings& st) {
    std::ofstream(dir / "scene.rad", std::ios::trunc) << scene;
    std::vector<render::PrimaryRay> pr;
    for (const Ray& ray : rays)
      pr.push_back({ray.org, ray.dir, 0});
    std::vector<double> out;
    for (const auto& v : render_rays("scene.rad", pr, st))
      out.push_back(v.value[0]);
    return out;
  }
};

const double kS2 = std::sqrt(2.0);
const std::string kT = "void brightfunc bf 2 total t.cal 0 0\n";
const std::string kTs = "void brightfunc bf 2 shadow t.cal 0 0\n";
// Function space scaled by 2 (S = 1/2) or by 1/2 (S = 2).
const std::string kTHalf = "void brightfunc bf 4 total t.cal -s 2 0 0\n";
const std::string kTDouble = "void brightfunc bf 4 total t.cal -s 0.5 0 0\n";

void expect_rel(double got, double want, const char* what) {
  EXPECT_NEAR(got, want, 1e-4 * want) << what;
}

} // namespace

// (a) A primary ray: T is its length to the floor.
TEST_F(RayDistance, PrimaryRay) {
  const std::vector<Ray> rays = {{{0.3, 0.2, 3}, {0, 0, -1}}, {{0, 0, 3}, {1, 0, -1}}};
  auto v = render(kT + floor_glow("bf"), rays);
  expect_rel(v[0], 3, "straight down");
  expect_rel(v[1], 3 * kS2, "oblique");
  auto h = render(kTHalf + floor_glow("bf"), rays);
  expect_rel(h[0], 1.5, "S = 1/2");
  expect_rel(h[1], 1.5 * kS2, "S = 1/2, oblique");
}

// (b) Seen in a mirror at z = 3 from z = 1: the way up plus the way down.
TEST_F(RayDistance, ThroughMirror) {
  const std::string mirror = "void mirror mir 0 0 3 1 1 1\n" + pane("mir", "m", 3, false);
  const std::vector<Ray> rays = {{{0, 0, 1}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 1}}};
  auto v = render(kT + floor_glow("bf") + mirror, rays);
  expect_rel(v[0], 2 + 3, "straight");
  expect_rel(v[1], 2 * kS2 + 3 * kS2, "oblique");
  auto d = render(kTDouble + floor_glow("bf") + mirror, rays);
  expect_rel(d[0], 2 * 5, "S = 2");
  expect_rel(d[1], 2 * 5 * kS2, "S = 2, oblique");
  // Ts is the reflected segment alone (no shadow ray in its chain).
  auto s = render(kTs + floor_glow("bf") + mirror, rays);
  expect_rel(s[0], 3, "Ts");
  expect_rel(s[1], 3 * kS2, "Ts, oblique");
}

// (c) Through a glass pane at z = 1.5 (the ratio to the unpatterned floor removes the glass's
// transmission), a void surface, and a back face with -bv- (the ray goes on unchanged).
TEST_F(RayDistance, ThroughTransmittingSurfaces) {
  const std::vector<Ray> rays = {{{0, 0, 3}, {0, 0, -1}}, {{0, 0, 3}, {1, 0, -1}}};
  const std::string glass = "void glass gl 0 0 3 0.8 0.8 0.8\n" + pane("gl", "g", 1.5, true);
  auto plain = render(floor_glow("void") + glass, rays);
  auto v = render(kT + floor_glow("bf") + glass, rays);
  ASSERT_GT(plain[0], 0);
  expect_rel(v[0] / plain[0], 3, "glass");
  expect_rel(v[1] / plain[1], 3 * kS2, "glass, oblique");
  auto h = render(kTHalf + floor_glow("bf") + glass, rays);
  expect_rel(h[0] / plain[0], 1.5, "glass, S = 1/2");

  auto vd = render(kT + floor_glow("bf") + pane("void", "v", 1.5, true), rays);
  expect_rel(vd[0], 3, "void surface");
  expect_rel(vd[1], 3 * kS2, "void surface, oblique");

  const std::string back = "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n" +
                           pane("grey", "b", 1.5, false); // facing down, away from the rays
  auto vb = render(kT + floor_glow("bf") + back, rays, false);
  expect_rel(vb[0], 3, "back face, -bv-");
  expect_rel(vb[1], 3 * kS2, "back face, -bv-, oblique");
}

// (d) A light panel at z = 2 with a pattern of T over a plastic floor seen from z = 1: the
// shadow ray's T continues the primary's (1 + the shadow ray's length), as Radiance's shadow
// ray is a child of the ray that hit the floor.
TEST_F(RayDistance, SourcePatternOfShadowRay) {
  const std::string lamp =
      "light lampmat 0 0 3 100 100 100\n" + pane("lampmat", "lamp", 2, false, 0.05);
  const std::string floor =
      "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n" + pane("grey", "f", 0, true);
  const std::vector<Ray> rays = {{{0, 0, 1}, {0, 0, -1}}, {{1, 0, 1}, {0, 0, -1}}};
  auto plain = render("void " + lamp + floor, rays);
  auto v = render(kT + "bf " + lamp + floor, rays);
  ASSERT_GT(plain[0], 0);
  ASSERT_GT(plain[1], 0);
  expect_rel(v[0] / plain[0], 1 + 2, "below the lamp");
  expect_rel(v[1] / plain[1], 1 + std::sqrt(5.0), "beside it");
  auto h = render(kTHalf + "bf " + lamp + floor, rays);
  expect_rel(h[0] / plain[0], 1.5, "S = 1/2");
  expect_rel(h[1] / plain[1], (1 + std::sqrt(5.0)) / 2, "S = 1/2, beside it");
  auto s = render(kTs + "bf " + lamp + floor, rays);
  expect_rel(s[0] / plain[0], 2, "Ts: the shadow ray alone");
  expect_rel(s[1] / plain[1], std::sqrt(5.0), "Ts beside it");
}

// A shadow ray from the floor through two glass panes (z = 1.5 plain, z = 1.8 patterned) to
// the panel: at the second pane T = 1 (primary) + 1.8 (both shadow segments), Ts = 1.8.
TEST_F(RayDistance, ShadowRayThroughGlass) {
  const std::string lamp =
      "light lampmat 0 0 3 100 100 100\n" + pane("lampmat", "lamp", 2, false, 0.05);
  const std::string floor =
      "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n" + pane("grey", "f", 0, true);
  const std::string low = "void glass g1 0 0 3 0.9 0.9 0.9\n" + pane("g1", "p1", 1.5, true, 1);
  auto high = [](const std::string& mod) {
    return mod + " glass g2 0 0 3 0.7 0.7 0.7\n" + pane("g2", "p2", 1.8, true, 1);
  };
  const std::vector<Ray> rays = {{{0, 0, 1}, {0, 0, -1}}, {{0.5, 0, 1}, {0, 0, -1}}};
  auto plain = render("void " + lamp + floor + low + high("void"), rays);
  auto v = render(kT + "void " + lamp + floor + low + high("bf"), rays);
  ASSERT_GT(plain[0], 0);
  ASSERT_GT(plain[1], 0);
  // Beside the lamp the shadow ray's way is longer by the slant: 1 / cos = sqrt(0.25 + 4) / 2.
  const double slant = std::sqrt(4.25) / 2;
  expect_rel(v[0] / plain[0], 1 + 1.8, "T at the second pane");
  expect_rel(v[1] / plain[1], 1 + 1.8 * slant, "T at the second pane, slanted");
  auto s = render(kTs + "void " + lamp + floor + low + high("bf"), rays);
  expect_rel(s[0] / plain[0], 1.8, "Ts at the second pane");
  expect_rel(s[1] / plain[1], 1.8 * slant, "Ts at the second pane, slanted");
  auto d = render(kTDouble + "void " + lamp + floor + low + high("bf"), rays);
  expect_rel(d[0] / plain[0], 2 * 2.8, "S = 2");
}

// (e) Ambient samples are children of the ray that hit the floor: a grey floor (reflectance
// 0.5) seen from z = 1 under a glowing ceiling (z = 2, half-size 10) of radiance T, so a
// sample meeting the ceiling r away brings 1 + r. The floor's radiance is
// 0.5 / pi x the integral over the ceiling of (1 + r) h^2 / r^4 dA (h = 2), about 2.13; were
// the samples to start from 0 it would be about 1.65. Hemisphere sampling (-aa 0, 64 x 64
// strata) and the irradiance cache (records made from the samples of the ray that needs
// them) both stay within 2% of the integral.
namespace {
double ceiling_integral(double h, double half, bool with_primary) {
  const int n = 2000;
  const double step = 2 * half / n;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -half + (i + 0.5) * step, y = -half + (j + 0.5) * step;
      const double r2 = x * x + y * y + h * h, r = std::sqrt(r2);
      sum += ((with_primary ? 1 : 0) + r) * h * h / (r2 * r2);
    }
  return sum * step * step;
}
} // namespace

TEST_F(RayDistance, AmbientSamplesContinueTheTree) {
  const std::string scene = kT + "bf glow ceil 0 0 4 1 1 1 0\n" + pane("ceil", "c", 2, false) +
                            "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n" +
                            pane("grey", "f", 0, true);
  const double want = 0.5 / M_PI * ceiling_integral(2, 10, true);
  const double without = 0.5 / M_PI * ceiling_integral(2, 10, false);
  ASSERT_GT(want - without, 0.1 * want); // the test tells the two apart
  const std::vector<Ray> rays = {{{0, 0, 1}, {0, 0, -1}}, {{0.2, -0.1, 1}, {0, 0, -1}}};
  render::RenderSettings st = settings();
  st.ab = 1;
  st.ad = 4096;
  st.as = 0;
  st.lw = 1e-6; // no Russian roulette among the samples
  auto v = render(scene, rays, st);
  for (double x : v)
    EXPECT_NEAR(x, want, 0.02 * want) << "-aa 0";
  st.aa = 0.1;
  st.make_records = true;
  st.cube_size = 20;
  st.ambient_min_radius = ambient::ambient_min_radius(20, 128);
  st.ambient_max_radius = ambient::ambient_max_radius(20, 128);
  auto c = render(scene, rays, st);
  for (double x : c)
    EXPECT_NEAR(x, want, 0.02 * want) << "irradiance cache";
}
