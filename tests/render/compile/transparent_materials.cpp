// trans, glass, dielectric and interface at chosen rays against values worked out by hand from
// Radiance's formulas (scene-format.md §3.2-3.5), including shadow rays through them.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "temp_dir.h"

using namespace radcl;

namespace {

constexpr double kL = 1000;         // radiance of the lights
constexpr double kSunAngle = 0.533; // degrees

// A scene from `materials` (a .rad text) plus a big light overhead (facing down at z = 5)
// or a sun straight overhead.
struct Scene {
  explicit Scene(const std::string& body, bool sun) {
    std::ofstream f(path);
    if (sun)
      f << "void light solar 0 0 3 " << kL << " " << kL << " " << kL << "\n"
        << "solar source sun 0 0 4 0 0 1 " << kSunAngle << "\n";
    else
      f << "void light lamp 0 0 3 " << kL << " " << kL << " " << kL << "\n"
        << "lamp polygon ceiling 0 0 12 -100 -100 5  -100 100 5  100 100 5  100 -100 5\n";
    f << body;
  }
  // Radiance of a ray, or irradiance at a -I sensor (or, with `meters`, at the surface the
  // ray hits: -i).
  double value(render::PrimaryRay ray, bool sensor = false, bool meters = false) {
    scene::LoadedScene ls = scene::load_scene({path});
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    st.ds = 0.01;
    st.dt = 0;
    st.dc = 1;
    st.lw = 1e-9; // deterministic: no Russian roulette
    st.lr = 60;
    st.irradiance_I = sensor;
    st.irradiance_i = meters;
    render::Renderer r(ls, st, device::default_context());
    std::vector<render::PrimaryResult> res(1);
    r.render(std::span(&ray, 1), res);
    return res[0].value[1];
  }
  radcl::test::TempFolder dir{"transparent_materials"};
  std::string path = (dir / "s.rad").string();
};

double sun_solid_angle() {
  return 2 * M_PI * (1 - std::cos(kSunAngle * M_PI / 360));
}

// Thin glass (scene-format.md §3.3) at cosine c.
double glass_T(double tn, double c, double n = 1.52) {
  double c2 = std::sqrt(1 - (1 - c * c) / (n * n));
  double t = std::pow(tn, 1 / c2);
  double rs = std::pow((c - n * c2) / (c + n * c2), 2);
  double rp = std::pow((1 / c - n / c2) / (1 / c + n / c2), 2);
  return 0.5 * (1 - rs) * (1 - rs) * t / (1 - rs * rs * t * t) +
         0.5 * (1 - rp) * (1 - rp) * t / (1 - rp * rp * t * t);
}

// Radiance's transmittance -> transmissivity for n = 1.52.
double glass_tn(double Tn) {
  return (std::sqrt(0.8402528435 + 0.0072522239 * Tn * Tn) - 0.9166530661) / 0.0036261119 / Tn;
}

const std::string kPane = "void glass pane 0 0 3 {0} {0} {0}\n"
                          "pane polygon window 0 0 12 -50 -50 1  50 -50 1  50 50 1  -50 50 1\n";

std::string pane(double tn) {
  std::string s = kPane;
  for (std::size_t p; (p = s.find("{0}")) != std::string::npos;)
    s.replace(p, 3, std::to_string(tn));
  return s;
}

} // namespace

TEST(Glass, NormalIncidenceGivesMeasuredTransmittance) {
  // 88 % glass as Radiance's documentation converts it: tn = 0.9584.
  double tn = glass_tn(0.88);
  EXPECT_NEAR(tn, 0.9584, 1e-4);
  EXPECT_NEAR(glass_T(tn, 1), 0.88, 1e-6);
  Scene s(pane(tn), false);
  double v = s.value({{0, 0, 0}, {0, 0, 1}, 0});
  EXPECT_NEAR(v, kL * 0.88, kL * 1e-4);
}

TEST(Glass, ObliqueRayAndSunThroughPane) {
  Scene s(pane(0.9), false);
  double c = std::cos(50 * M_PI / 180);
  double v = s.value({{0, 0, 0}, {std::sqrt(1 - c * c), 0, c}, 0});
  EXPECT_NEAR(v, kL * glass_T(0.9, c), kL * 2e-4);

  // The sun reaches a sensor under the pane through it: shadow rays pass with T.
  Scene sun(pane(0.9), true);
  double e = sun.value({{0, 0, 0}, {0, 0, 1}, 0}, true);
  EXPECT_NEAR(e, kL * sun_solid_angle() * glass_T(0.9, 1), 1e-3 * e);
}

TEST(Trans, PureSpecularPassesRaysAndShadowRays) {
  // tau = 0.6, tau_s = 0.3 (spec 0 < 0.018: no Fresnel), colour 0.8: coefficient 0.24.
  std::string body = "void trans clear 0 0 7 0.8 0.8 0.8 0 0 0.6 0.5\n"
                     "clear polygon sheet 0 0 12 -50 -50 1  50 -50 1  50 50 1  -50 50 1\n";
  Scene s(body, false);
  // Looking up: the light through the clear part, plus the diffuse transmission C tau_d E / pi
  // of the irradiance E on the far side (as the source sampling computes it there).
  double e_far = s.value({{0, 0, 1 + 1e-4}, {0, 0, 1}, 0}, true);
  double v = s.value({{0, 0, 0}, {0, 0, 1}, 0});
  EXPECT_NEAR(v, kL * 0.24 + 0.8 * 0.3 * e_far / M_PI, 1e-4 * v);
  Scene sun(body, true);
  double e = sun.value({{0, 0, 0}, {0, 0, 1}, 0}, true);
  EXPECT_NEAR(e, kL * sun_solid_angle() * 0.24, 1e-3 * e);
}

TEST(Trans, RoughTransBlocksShadowRays) {
  std::string body = "void trans frosted 0 0 7 0.8 0.8 0.8 0 0.1 0.6 0.5\n"
                     "frosted polygon sheet 0 0 12 -50 -50 1  50 -50 1  50 50 1  -50 50 1\n";
  Scene sun(body, true);
  EXPECT_EQ(sun.value({{0, 0, 0}, {0, 0, 1}, 0}, true), 0.0);
}

namespace {
// A slab of water-like dielectric between z = 0 and z = 1, normals outward.
std::string slab(const std::string& mat) {
  return mat + "\nwater polygon top 0 0 12 -50 -50 1  50 -50 1  50 50 1  -50 50 1\n"
               "water polygon bottom 0 0 12 -50 -50 0  -50 50 0  50 50 0  50 -50 0\n";
}
} // namespace

TEST(Dielectric, LeavingTheSlabWithAbsorptionAndInternalReflections) {
  const double n = 1.5, tn = 0.8, c = -std::log(tn);
  Scene s(slab("void dielectric water 0 0 5 0.8 0.8 0.8 1.5 0"), false);
  // From inside at z = 0.5 straight up: (1 - R) n^2 out of the top, then the series of
  // round trips (two reflections, path 2 each) that end up there too.
  double R = std::pow((1 - n) / (1 + n), 2);
  double expect = kL * (1 - R) * n * n * std::exp(-0.5 * c) / (1 - R * R * std::exp(-2 * c));
  double v = s.value({{0, 0, 0.5}, {0, 0, 1}, 0});
  EXPECT_NEAR(v, expect, 1e-3 * expect);
}

TEST(Dielectric, TotalInternalReflectionTrapsTheRay) {
  Scene s(slab("void dielectric water 0 0 5 1 1 1 1.5 0"), false);
  // 60 degrees from the normal is beyond the critical angle (41.8): never leaves.
  double v = s.value({{0, 0, 0.5}, {std::sin(M_PI / 3), 0, std::cos(M_PI / 3)}, 0});
  EXPECT_EQ(v, 0.0);
  // 30 degrees leaves the slab.
  double w = s.value({{0, 0, 0.5}, {0.5, 0, std::sqrt(0.75)}, 0});
  EXPECT_GT(w, kL);
}

TEST(Dielectric, SunThroughSlabToSensorBelow) {
  const double n = 1.5, tn = 0.8;
  Scene s(slab("void dielectric water 0 0 5 0.8 0.8 0.8 1.5 0"), true);
  double R = std::pow((1 - n) / (1 + n), 2);
  // In: (1 - R) / n^2, absorbed over 1, out: (1 - R) n^2.
  double expect = kL * sun_solid_angle() * (1 - R) * (1 - R) * tn;
  double e = s.value({{0, 0, -0.5}, {0, 0, 1}, 0}, true);
  EXPECT_NEAR(e, expect, 1e-3 * expect);
}

// -i: the view ray passes the slab straight (Radiance's raytirrad passes clear materials
// before a dielectric could change the ray's medium) and meets a meter on the floor below,
// which the sun reaches through the slab as above. The ray stays in the outside medium: it
// had kept the slab's absorption, which dimmed the meter's shadow ray (to 0.0257 here).
TEST(Dielectric, IrradianceModePassesTheSlabInTheOutsideMedium) {
  const double n = 1.5, tn = 0.8;
  Scene s(slab("void dielectric water 0 0 5 0.8 0.8 0.8 1.5 0") +
              "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
              "grey polygon floor 0 0 12 -50 -50 -1  50 -50 -1  50 50 -1  -50 50 -1\n",
          true);
  double R = std::pow((1 - n) / (1 + n), 2);
  double expect = kL * sun_solid_angle() * (1 - R) * (1 - R) * tn;
  double e = s.value({{0.1, 0, 2}, {0, 0, -1}, 0}, false, true);
  EXPECT_NEAR(e, expect, 1e-3 * expect);
}

TEST(Interface, MediaOnBothSides) {
  // Medium 1 (inside, n 1.5, tn 0.8) below the top surface, medium 2 (outside, n 1.2, tn 0.9)
  // above it; a ray from inside at z = 0.5 goes up through the top into medium 2 and meets the
  // light 4 further on.
  std::string body = "void interface iface 0 0 8 0.8 0.8 0.8 1.5 0.9 0.9 0.9 1.2\n"
                     "iface polygon top 0 0 12 -50 -50 1  50 -50 1  50 50 1  -50 50 1\n";
  Scene s(body, false);
  double eta = 1.5 / 1.2, R = std::pow((1 - eta) / (1 + eta), 2);
  double expect = kL * std::pow(0.9, 4) * (1 - R) * eta * eta * std::pow(0.8, 0.5);
  double v = s.value({{0, 0, 0.5}, {0, 0, 1}, 0});
  EXPECT_NEAR(v, expect, 1e-3 * expect);
}
