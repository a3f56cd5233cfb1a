// Issue 8 case 5: extreme sources. A sun of 1e9 W/sr/m2, lights of 1e-9, a light enclosed in
// an opaque box, a spotlight with a 0.5 degree cone, a glow of zero radius. Direct light with
// -ab 0 -dj 0 -ds 0 -dt 0 is deterministic and has closed forms: E = L omega cos for a
// distant source, pi L r^2 cos / d^2 for a sphere wholly in front (a spotlight's also times
// d^2 / (d + f)^2, f its aim vector's length). A zero-radius glow is no direct source but
// fills ambient samples: inside a glowing bubble E = pi L exactly, whatever the samples.
// Values scale linearly with source strength; a light below FTINY in all components is no
// source (Radiance's "don't bother").
#include <array>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <vector>

#include "radcl/render/pipeline/renderer.h"
#include "scene_dir.h"

using namespace radcl;

namespace {

constexpr double kPi = std::numbers::pi;
using V = std::array<double, 3>;

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

class StabilityExtremeSources : public test::SceneDir {
protected:
  static render::RenderSettings direct(bool sensors) {
    return test::direct_light_settings(sensors);
  }
  std::vector<render::PrimaryResult> render(const std::string& text,
                                            const std::vector<render::PrimaryRay>& rays,
                                            const render::RenderSettings& st) {
    std::ofstream("s.rad", std::ios::trunc) << text;
    auto res = render_rays("s.rad", rays, st);
    for (std::size_t i = 0; i < res.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(std::isfinite(res[i].value[k])) << "ray " << i;
        EXPECT_GE(res[i].value[k], 0) << "ray " << i;
      }
    return res;
  }
};

// A sun at 40 degrees elevation, radiance L, 0.53 degrees across, over a plastic floor with a
// box on it.
std::string sun_scene(double L) {
  const double el = 40 * kPi / 180;
  return "void light sunl 0 0 3 " + num(L) + " " + num(L) + " " + num(L) + "\n" +
         "sunl source sun 0 0 4 " + num(std::cos(el)) + " 0 " + num(std::sin(el)) + " 0.53\n" +
         "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
         "grey polygon floor 0 0 12 -50 -50 0 50 -50 0 50 50 0 -50 50 0\n"
         "grey polygon wall 0 0 12 -1 -2 0 -1 2 0 -1 2 1 -1 -2 1\n";
}

double sun_omega() {
  return 2 * kPi * (1 - std::cos(0.53 / 2 * kPi / 180));
}

} // namespace

// The 1e9 sun: sensors read L omega cos exactly, a view ray into the sun reads L, the floor
// reads rho E / pi, the shade behind the wall 0; with ambient bounces everything stays finite
// and the lit floor's value is at least its direct part.
TEST_F(StabilityExtremeSources, HugeSun) {
  const double L = 1e9, el = 40 * kPi / 180;
  const double E = L * sun_omega() * std::sin(el);
  const std::vector<render::PrimaryRay> sensors = {
      {{2, 0, 0}, {0, 0, 1}, 0},                       // open floor
      {{-1.2, 0, 0}, {0, 0, 1}, 0},                    // behind the wall
      {{2, 0, 0}, {std::cos(el), 0, std::sin(el)}, 0}, // facing the sun
      {{2, 0, 0}, {0, 0, -1}, 0},                      // under the floor
  };
  auto s = render(sun_scene(L), sensors, direct(true));
  EXPECT_NEAR(s[0].value[0], E, 1e-5 * E);
  EXPECT_EQ(s[1].value[0], 0);
  EXPECT_NEAR(s[2].value[0], L * sun_omega(), 1e-5 * L * sun_omega());
  EXPECT_EQ(s[3].value[0], 0);

  const std::vector<render::PrimaryRay> views = {
      {{2, 0, 0.5}, {std::cos(el), 0, std::sin(el)}, 0}, // into the sun
      {{2, 0, 3}, {0, 0, -1}, 0},                        // the lit floor
      {{-1.2, 0, 3}, {0, 0, -1}, 0},                     // the shaded floor
  };
  auto v = render(sun_scene(L), views, direct(false));
  EXPECT_NEAR(v[0].value[0], L, 1e-6 * L);
  EXPECT_NEAR(v[1].value[0], 0.5 * E / kPi, 1e-5 * E);
  EXPECT_EQ(v[2].value[0], 0);

  render::RenderSettings st = direct(false);
  st.ab = 2;
  st.ad = 128;
  st.as = 32;
  auto a = render(sun_scene(L), views, st);
  EXPECT_GE(a[1].value[0], v[1].value[0] * (1 - 1e-5));
  EXPECT_LE(a[1].value[0], v[1].value[0] * 1.2); // the wall adds a little light at most
  EXPECT_GT(a[2].value[0], 0);
  EXPECT_LT(a[2].value[0], v[1].value[0]);
}

// Direct and ambient values scale with the source: a sphere light and the sun at strengths
// 1e-5, 1 and 1e9 give values in the same ratios (float rounding aside) with -as 0 and -as 64.
// (Below FTINY in every component a light is no source at all, as in Radiance: see below.)
TEST_F(StabilityExtremeSources, LinearInSourceStrength) {
  auto scene = [](double L) {
    return "void light lamp 0 0 3 " + num(L) + " " + num(L) + " " + num(L) + "\n" +
           "lamp sphere bulb 0 0 4 0 0 2 0.1\n" + sun_scene(L);
  };
  std::vector<render::PrimaryRay> rays;
  for (int i = 0; i < 16; ++i) {
    const double a = 2 * kPi * i / 16;
    rays.push_back({{3 * std::cos(a), 3 * std::sin(a), 0}, {0, 0, 1}, 0});
    rays.push_back({{-1.1, 1.5 * std::sin(a), 0.5}, {-1, 0.3 * std::cos(a), 0}, 0});
  }
  for (int as : {0, 64}) {
    render::RenderSettings st = direct(true);
    st.ab = 1;
    st.ad = 256;
    st.as = as;
    auto one = render(scene(1), rays, st);
    auto big = render(scene(1e9), rays, st);
    auto small = render(scene(1e-5), rays, st);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      ASSERT_GT(one[i].value[0], 0) << i;
      EXPECT_NEAR(big[i].value[0] / one[i].value[0], 1e9, 1e9 * 1e-5)
          << "as " << as << " ray " << i;
      EXPECT_NEAR(small[i].value[0] / one[i].value[0], 1e-5, 1e-5 * 1e-5)
          << "as " << as << " ray " << i;
    }
  }
}

// A light of 1e-9 is below FTINY in every component: Radiance does not make it a source
// ("don't bother"), and ambient rays never count lights, so it lights nothing; a view ray
// still sees its radiance. Beside it a light of 1e9 behind a screen changes nothing.
TEST_F(StabilityExtremeSources, FaintLightIsNoSource) {
  const std::string text = "void light faint 0 0 3 1e-9 1e-9 1e-9\n"
                           "faint sphere f 0 0 4 0 0 1 0.1\n"
                           "void light bright 0 0 3 1e9 1e9 1e9\n"
                           "bright sphere b 0 0 4 10 0 1 0.1\n"
                           "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "grey polygon screen 0 0 12 5 -5 0 5 -5 5 5 5 5 5 5 0\n";
  const std::vector<render::PrimaryRay> sensors = {{{0, 0, 0}, {0, 0, 1}, 0},
                                                   {{1, 0, 0}, {-1, 0, 1}, 0}};
  auto r = render(text, sensors, direct(true));
  EXPECT_EQ(r[0].value[0], 0);
  EXPECT_EQ(r[1].value[0], 0);
  render::RenderSettings st = direct(true);
  st.ab = 1;
  st.ad = 256;
  auto a = render(text, sensors, st);
  EXPECT_EQ(a[0].value[0], 0);
  EXPECT_EQ(a[1].value[0], 0);
  auto v = render(text, {{{0, 0, 0.5}, {0, 0, 1}, 0}}, direct(false));
  EXPECT_NEAR(v[0].value[0], 1e-9, 1e-15);
  // Just above FTINY it is a source, with the exact irradiance.
  const std::string lit = "void light faint 0 0 3 2e-6 2e-6 2e-6\nfaint sphere f 0 0 4 0 0 1 0.1\n";
  auto l = render(lit, {sensors[0]}, direct(true));
  const double d0 = 1 - meter_points("s.rad", {sensors[0]})[0][2]; // the meter to the centre
  const double e0 = kPi * 2e-6 * 0.01 / (d0 * d0);
  EXPECT_NEAR(l[0].value[0], e0, 1e-5 * e0);
}

// A light sphere inside a closed opaque box: nothing of it outside, directly or by ambient
// bounces; inside, the wall facing it reads the closed form.
TEST_F(StabilityExtremeSources, LightEnclosedInOpaqueBox) {
  const std::string text = "void light lamp 0 0 3 1000 1000 1000\n"
                           "lamp sphere bulb 0 0 4 0 0 1 0.2\n"
                           "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "grey polygon floor 0 0 12 -20 -20 0 20 -20 0 20 20 0 -20 20 0\n"
                           "grey polygon b_bot 0 0 12 -1 -1 0.001 -1 1 0.001 1 1 0.001 1 -1 0.001\n"
                           "grey polygon b_top 0 0 12 -1 -1 2 1 -1 2 1 1 2 -1 1 2\n"
                           "grey polygon b_xlo 0 0 12 -1 -1 0.001 -1 -1 2 -1 1 2 -1 1 0.001\n"
                           "grey polygon b_xhi 0 0 12 1 -1 0.001 1 1 0.001 1 1 2 1 -1 2\n"
                           "grey polygon b_ylo 0 0 12 -1 -1 0.001 1 -1 0.001 1 -1 2 -1 -1 2\n"
                           "grey polygon b_yhi 0 0 12 -1 1 0.001 -1 1 2 1 1 2 1 1 0.001\n";
  const std::vector<render::PrimaryRay> rays = {
      {{3, 0, 0}, {0, 0, 1}, 0},      // the floor outside
      {{1, 0, 1}, {1, 0, 0}, 0},      // on the box's outside, facing out
      {{0, 0, 2}, {0, 0, 1}, 0},      // on its lid, facing up
      {{1.5, 0.5, 1}, {-1, 0, 0}, 0}, // facing the box
      {{1, 0, 1}, {-1, 0, 0}, 0},     // on the inside of the wall, facing the lamp
  };
  auto d = render(text, rays, direct(true));
  const double d_in = meter_points("s.rad", rays)[4][0]; // the meter to the lamp's centre
  const double e_in = kPi * 1000 * 0.04 / (d_in * d_in);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(d[i].value[0], 0) << i;
  EXPECT_NEAR(d[4].value[0], e_in, 1e-5 * e_in);
  render::RenderSettings st = direct(true);
  st.ab = 3;
  st.ad = 128;
  st.as = 32;
  auto a = render(text, rays, st);
  for (int i = 0; i < 4; ++i)
    EXPECT_EQ(a[i].value[0], 0) << i;
  EXPECT_GT(a[4].value[0], e_in); // the box's inside bounces light back
}

// A spotlight of 0.5 degrees (half-angle 0.25) aimed straight down from 10 m: lit inside the
// cone with the focus-adjusted closed form, dark just outside it.
TEST_F(StabilityExtremeSources, NarrowSpotlight) {
  const double h = 10, r = 0.01, L = 1e4, f = 2; // aim vector of length 2: focus 2 m behind
  const std::string text = "void spotlight spot 0 0 7 " + num(L) + " " + num(L) + " " + num(L) +
                           " 0.5 0 0 -2\n" + "spot sphere bulb 0 0 4 0 0 10 0.01\n" +
                           "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "grey polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";
  std::vector<double> angles = {0, 0.1, 0.2, 0.24, 0.26, 0.3, 1, 10};
  std::vector<render::PrimaryRay> rays;
  for (double a : angles)
    rays.push_back({{(h - 1e-4) * std::tan(a * kPi / 180), 0, 0}, {0, 0, 1}, 0});
  auto res = render(text, rays, direct(true));
  const std::vector<render::Vec3d> meters = meter_points("s.rad", rays);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double x = meters[i][0], dz = h - meters[i][2];
    const double d2 = x * x + dz * dz, d = std::sqrt(d2);
    const double want =
        angles[i] < 0.25 ? kPi * L * r * r / d2 * (dz / d) * d2 / ((d + f) * (d + f)) : 0;
    EXPECT_NEAR(res[i].value[0], want, 1e-5 * want) << angles[i] << " degrees";
  }
}

// A glow of zero radius: no direct source (-ab 0 reads 0), seen directly at its radiance, and
// a sensor inside a glowing bubble reads pi L exactly with any number of ambient samples.
TEST_F(StabilityExtremeSources, ZeroRadiusGlow) {
  const std::string text = "void glow sky 0 0 4 7 7 7 0\n"
                           "sky bubble dome 0 0 4 0 0 0 100\n"
                           "void glow tiny 0 0 4 1e9 1e9 1e9 0\n"
                           "tiny sphere dot 0 0 4 0 5 1 0.001\n";
  // Facing the dot of 1e9: still nothing with -ab 0.
  const std::vector<render::PrimaryRay> rays = {{{0, 0, 0}, {0, 1, 0.2}, 0},
                                                {{1, -2, 3}, {-0.3, 0.2, -1}, 0}};
  auto d = render(text, rays, direct(true));
  EXPECT_EQ(d[0].value[0], 0);
  EXPECT_EQ(d[1].value[0], 0);
  auto v = render(text, {{{0, 0, 1}, {1, 0, 0}, 0}, {{0, 0, 1}, {0, 1, 0}, 0}}, direct(false));
  EXPECT_NEAR(v[0].value[0], 7, 7e-6);
  EXPECT_NEAR(v[1].value[0], 1e9, 1e3);
  for (int ad : {16, 64, 512}) {
    render::RenderSettings st = direct(true);
    st.ab = 1;
    st.ad = ad;
    st.as = 0;
    // Facing away from the dot (it is behind both).
    const std::vector<render::PrimaryRay> away = {{{0, 0, 0}, {0, -1, 0}, 0},
                                                  {{1, -2, 3}, {0.3, -1, 0.2}, 0}};
    auto a = render(text, away, st);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(a[i].value[0], kPi * 7, kPi * 7 * 1e-5) << "ad " << ad << " ray " << i;
  }
}
