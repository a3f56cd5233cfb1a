// Textures bend glass and dielectrics (Radiance's m_glass, m_dielectric): the normal tilted by a
// texfunc decides the Fresnel terms and the reflected and transmitted directions. A pane (or a
// dielectric boundary) at z = 1 carries a constant perturbation (0.1, 0, 0); a glowing floor at
// z = 0 (facing up, red = Px + 10) and a glowing ceiling at z = 3 (facing down, green =
// Px + 10) tell where each ray landed, so every value is hand-computed from the geometry:
//   normal n' = (a, 0, 1) / s, s = sqrt(1 + a^2), cos = 1 / s;
//   glass transmitted d + 2 (1 - index) pert, reflected d + 2 cos n';
//   dielectric refracted r d + (r cos - cos2) n' (r the index ratio), Fresnel with cos.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <unistd.h>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;
namespace fs = std::filesystem;

namespace {

using Rgb = std::array<double, 3>;

const double kA = 0.1;                    // the texture's x perturbation
const double kS = std::sqrt(1 + kA * kA); // |n + pert|
const double kCos = 1 / kS;               // cosine with the tilted normal (normal incidence)
const double kX0 = 0.3, kY0 = 0.2;        // where the rays meet the surface
const double kIndex = 1.52;               // glass's default index
const double kOmega = 2 * std::numbers::pi * (1 - std::cos(0.5 * std::numbers::pi / 180));

// Radiance's thin-glass transmittance and reflectance for transmissivity tn at cosine c.
std::array<double, 2> glass_tr(double tn, double c) {
  double n = kIndex;
  double cos2 = std::sqrt((1 - 1 / (n * n)) + c * c / (n * n));
  double t = std::pow(tn, 1 / cos2);
  double re = (c - n * cos2) / (c + n * cos2);
  re *= re;
  double rm = (1 / c - n / cos2) / (1 / c + n / cos2);
  rm *= rm;
  double tr = 0.5 * (1 - re) * (1 - re) * t / (1 - re * re * t * t) +
              0.5 * (1 - rm) * (1 - rm) * t / (1 - rm * rm * t * t);
  double rf = 0.5 * re * (1 + (1 - 2 * re) * t * t) / (1 - re * re * t * t) +
              0.5 * rm * (1 + (1 - 2 * rm) * t * t) / (1 - rm * rm * t * t);
  return {tr, rf};
}

// Fresnel reflectance and (1 - R) r^2 of a dielectric boundary, index ratio r, cosine c.
std::array<double, 3> dielectric_rt(double r, double c) {
  double cos2 = std::sqrt(1 - r * r * (1 - c * c));
  double rs = (c - r * cos2) / (c + r * cos2);
  double rp = (1 / c - r / cos2) / (1 / c + r / cos2);
  double refl = 0.5 * (rs * rs + rp * rp);
  return {refl, (1 - refl) * r * r, cos2};
}

class TextureBending : public test::SceneDir {
protected:
  render::RenderSettings st;
  void SetUp() override {
    test::SceneDir::SetUp();
    std::ofstream(dir / "pos.cal") << "at = Px + 10;\n";
    st.ab = 0;
    st.dj = 0;
    st.dt = 0;
  }
  // The backdrop (unless `bare`), `rest`, and a surface at z = 1 (normal +z, or -z when
  // `down`) made of `mod`; rays from (kX0, kY0, z) along (0, 0, dz).
  std::vector<render::PrimaryResult> render(const std::string& rest, const std::string& mod,
                                            bool down, const std::vector<std::array<double, 2>>& zs,
                                            bool bare = false) {
    std::ofstream f(dir / "scene.rad");
    if (!bare)
      f << "void colorfunc red_at 4 at 0 0 pos.cal 0 0\n"
        << "red_at glow floorglow 0 0 4 1 1 1 0\n"
        << "floorglow polygon floor 0 0 12 -20 -20 0 20 -20 0 20 20 0 -20 20 0\n"
        << "void colorfunc green_at 4 0 at 0 pos.cal 0 0\n"
        << "green_at glow ceilglow 0 0 4 1 1 1 0\n"
        << "ceilglow polygon ceiling 0 0 12 -20 -20 3 -20 20 3 20 20 3 20 -20 3\n";
    f << "void texfunc tilt 4 0.1 0 0 . 0 0\n" << rest << "\n";
    if (down)
      f << mod << " polygon pane 0 0 12 -20 -20 1 -20 20 1 20 20 1 20 -20 1\n";
    else
      f << mod << " polygon pane 0 0 12 -20 -20 1 20 -20 1 20 20 1 -20 20 1\n";
    f.close();
    std::vector<render::PrimaryRay> pr;
    for (const auto& z : zs)
      pr.push_back({{kX0, kY0, z[0]}, {0, 0, z[1]}, 0});
    return render_rays("scene.rad", pr, st);
  }
};

void expect_rgb(const Rgb& got, const Rgb& want, const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], 1e-4) << what << " channel " << c;
}

} // namespace

// Glass from its front: the transmitted ray lands 2 (1 - 1.52) 0.1 = -0.104 along x on the floor,
// the mirror ray 2 * 2a / (1 - a^2) along x on the ceiling; both weights at the tilted cosine.
TEST_F(TextureBending, GlassFront) {
  auto tr = glass_tr(0.9, kCos);
  auto flat = glass_tr(0.9, 1);
  auto v = render("void glass clear 0 0 3 0.9 0.9 0.9\ntilt glass tilted 0 0 3 0.9 0.9 0.9",
                  "tilted", false, {{2, -1}});
  double x1 = kX0 + 2 * (1 - kIndex) * kA;
  double x2 = kX0 + 2 * 2 * kA / (1 - kA * kA);
  expect_rgb(v[0].value, {tr[0] * (x1 + 10), tr[1] * (x2 + 10), 0}, "textured");
  // rtrace's lengths stop at the textured pane (Radiance's rxt, rmt not extended).
  EXPECT_EQ(v[0].through_t, -1);
  EXPECT_EQ(v[0].mirror_t, 0);
  auto u = render("void glass clear 0 0 3 0.9 0.9 0.9", "clear", false, {{2, -1}});
  expect_rgb(u[0].value, {flat[0] * (kX0 + 10), flat[1] * (kX0 + 10), 0}, "plain");
  EXPECT_NEAR(u[0].through_t, 1, 1e-6);
  EXPECT_NEAR(u[0].mirror_t, 2, 1e-6);
}

// Glass from its back (-bv): the surface is flipped with its perturbation, so the transmitted
// ray to the ceiling bends by +0.104 per unit height and the mirror ray to the floor goes
// (-0.2, 0, -0.99).
TEST_F(TextureBending, GlassBack) {
  auto tr = glass_tr(0.9, kCos);
  auto v = render("tilt glass tilted 0 0 3 0.9 0.9 0.9", "tilted", false, {{0.5, 1}});
  double xt = kX0 - 2 * 2 * (1 - kIndex) * kA; // two units up to the ceiling
  double xr = kX0 - 2 * kA / (1 - kA * kA);    // one unit down to the floor
  expect_rgb(v[0].value, {tr[1] * (xr + 10), tr[0] * (xt + 10), 0}, "back");
}

// A textured pane still passes shadow rays straight (Radiance bends only other rays), with the
// transmittance at the tilted cosine: a grey floor under a pane facing down with a strong tilt
// (0.5, 0, 0), a bright sun overhead (the tilt alone changes the value by 0.2, 2000 times the
// tolerance).
TEST_F(TextureBending, GlassShadowRaysStraight) {
  auto tr = glass_tr(0.9, 1 / std::sqrt(1.25));
  std::string rest = "void light sunmat 0 0 3 1e6 1e6 1e6\n"
                     "sunmat source sun 0 0 4 0 0 1 1\n"
                     "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
                     "void texfunc strong 4 0.5 0 0 . 0 0\n"
                     "strong glass tilted 0 0 3 0.9 0.9 0.9\n"
                     "grey polygon under 0 0 12 -20 -20 0.5 20 -20 0.5 20 20 0.5 -20 20 0.5";
  auto v = render(rest, "tilted", true, {{0.75, -1}}, true);
  double d = 1e6 * kOmega * 0.5 / std::numbers::pi * tr[0];
  expect_rgb(v[0].value, {d, d, d}, "shadowed floor");
  EXPECT_GT(std::abs(d - 1e6 * kOmega * 0.5 / std::numbers::pi * glass_tr(0.9, 1)[0]), 0.1);
}

// Dielectric (index 1.5) entered from the front: refraction about the tilted normal, Fresnel at
// its cosine; the reflected ray as glass's.
TEST_F(TextureBending, DielectricEntering) {
  double r = 1 / 1.5;
  auto f = dielectric_rt(r, kCos);
  auto v = render("tilt dielectric tilted 0 0 5 1 1 1 1.5 0", "tilted", false, {{2, -1}});
  double d1 = r * kCos - f[2];
  double tx = d1 * kA / kS, tz = -r + d1 / kS;  // refracted direction (unnormalised)
  double x1 = kX0 + tx / -tz;                   // one unit down to the floor
  double x2 = kX0 + 2 * 2 * kA / (1 - kA * kA); // two units up to the ceiling
  expect_rgb(v[0].value, {f[1] * (x1 + 10), f[0] * (x2 + 10), 0}, "entering");
  EXPECT_EQ(v[0].through_t, -1);
  EXPECT_EQ(v[0].mirror_t, 0);
}

// Leaving the dielectric (hit from behind): the tilted normal is turned with the side, index
// ratio 1.5, refracted up to the ceiling and reflected down to the floor.
TEST_F(TextureBending, DielectricLeaving) {
  double r = 1.5;
  auto f = dielectric_rt(r, kCos);
  auto v = render("tilt dielectric tilted 0 0 5 1 1 1 1.5 0", "tilted", false, {{0.5, 1}});
  double d1 = r * kCos - f[2];
  double tx = -d1 * kA / kS, tz = r - d1 / kS;
  double xt = kX0 + 2 * tx / tz;
  double xr = kX0 - 2 * kA / (1 - kA * kA);
  expect_rgb(v[0].value, {f[0] * (xr + 10), f[1] * (xt + 10), 0}, "leaving");
}

// Index 1: no refraction, no reflection, whatever the texture; the ray's length goes on.
TEST_F(TextureBending, DielectricIndexOneIsClear) {
  auto v = render("tilt dielectric tilted 0 0 5 1 1 1 1 0", "tilted", false, {{2, -1}});
  expect_rgb(v[0].value, {kX0 + 10, 0, 0}, "index 1");
  EXPECT_NEAR(v[0].through_t, 1, 1e-6);
}

// trans (m_normal): the clear transmission goes along d - pert, normalised. A pane with
// transmission 0.6, all of it clear, no specular reflection, white: from the front the ray lands
// 0.1 back along x on the floor one unit down; its length still adds to the unmirrored one
// (Radiance's rxt is not stopped by a texture on trans).
TEST_F(TextureBending, TransFront) {
  auto v = render("tilt trans tilted 0 0 7 1 1 1 0 0 0.6 1", "tilted", false, {{2, -1}});
  expect_rgb(v[0].value, {0.6 * (kX0 - kA + 10), 0, 0}, "textured trans");
  EXPECT_NEAR(v[0].through_t, std::sqrt(1 + kA * kA), 1e-5);
  EXPECT_EQ(v[0].mirror_t, -1);
  auto u = render("void trans clear 0 0 7 1 1 1 0 0 0.6 1", "clear", false, {{2, -1}});
  expect_rgb(u[0].value, {0.6 * (kX0 + 10), 0, 0}, "plain trans");
  EXPECT_NEAR(u[0].through_t, 1, 1e-6);
}

// From the back the surface and its perturbation are flipped: d - pert = (0.1, 0, 1), two units
// up to the ceiling.
TEST_F(TextureBending, TransBack) {
  auto v = render("tilt trans tilted 0 0 7 1 1 1 0 0 0.6 1", "tilted", false, {{0.5, 1}});
  expect_rgb(v[0].value, {0, 0.6 * (kX0 + 2 * kA + 10), 0}, "back");
  EXPECT_NEAR(v[0].through_t, 2 * std::sqrt(1 + kA * kA), 1e-5);
}

// Plastic (black, specular 0.015 below the Fresnel threshold) and mirror: the mirror ray about
// the tilted normal reaches the ceiling 2 * 2a / (1 - a^2) along x, and rtrace's mirrored length
// stops at the textured surface (Radiance's rmt = rot).
TEST_F(TextureBending, PlasticAndMirrorReflection) {
  double x2 = kX0 + 2 * 2 * kA / (1 - kA * kA);
  auto p = render("tilt plastic tilted 0 0 5 0 0 0 0.015 0", "tilted", false, {{2, -1}});
  expect_rgb(p[0].value, {0, 0.015 * (x2 + 10), 0}, "plastic");
  EXPECT_EQ(p[0].mirror_t, 0);
  auto q = render("void plastic flat 0 0 5 0 0 0 0.015 0", "flat", false, {{2, -1}});
  expect_rgb(q[0].value, {0, 0.015 * (kX0 + 10), 0}, "plain plastic");
  EXPECT_NEAR(q[0].mirror_t, 2, 1e-6);
  auto m = render("tilt mirror tilted 0 0 3 0.5 0.5 0.5", "tilted", false, {{2, -1}});
  expect_rgb(m[0].value, {0, 0.5 * (x2 + 10), 0}, "mirror");
  EXPECT_EQ(m[0].mirror_t, 0);
}

// Seen from the back (-bv), textured plastic tilts by the flipped perturbation: the mirror ray
// goes down to the floor at x0 - 2a / (1 - a^2).
TEST_F(TextureBending, PlasticBack) {
  double xr = kX0 - 2 * kA / (1 - kA * kA);
  auto p = render("tilt plastic tilted 0 0 5 0 0 0 0.015 0", "tilted", false, {{0.5, 1}});
  expect_rgb(p[0].value, {0.015 * (xr + 10), 0, 0}, "plastic back");
}
