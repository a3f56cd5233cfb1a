// The BRDF materials (scene-format.md §3.11, §3.12; Radiance's m_brdf.c) against hand-computed
// values: a floor (z = 0, normal +z) under a 1-degree sun of radiance 1000, seen along chosen
// rays with -ab 0 -dj 0 -dt 0, so every value is deterministic. With the sun in unit direction
// l and the floor's normal n facing the ray (ldot = n.l), a source of solid angle omega adds
//   diffuse:  1000 rdiff ldot omega / pi
//   function: 1000 f ldot omega rspec (metfunc/metdata: x colour; transmitted light: tspec,
//             x colour for transfunc/transdata)
// where f is the user's function of the light direction in function coordinates.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <unistd.h>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/rad_reader.h"
#include "radcl/util/error.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;
namespace fs = std::filesystem;

namespace {

using Rgb = std::array<double, 3>;
using Vec = std::array<double, 3>;

const double kPi = std::numbers::pi;
// Solid angle of the 1-degree sun and its radiance.
const double kOmega = 2 * kPi * (1 - std::cos(0.5 * kPi / 180));
const double kSun = 1000;

const char* kCal = R"(
const(dx, dy, dz, o) = A5;
const7(dx, dy, dz, o) = A7;
lightz(dx, dy, dz, o) = dz;
minusy(dx, dy, dz, o) = -dy;
solid(dx, dy, dz, o) = o * 1000;
viewdep(dx, dy, dz, o) = RdotP * CrP + NzP;
bad(dx, dy, dz, o) = 1 / (dz - dz);
half(dx, dy, dz, o) = 0.5;
quarter(dx, dy, dz, o) = 0.25;
cz(dx, dy, dz, o) = dz;
scaled(v, dx, dy, dz, o) = v * A5;
scaled7(v, dx, dy, dz, o) = v * A7;
)";

struct Ray {
  Vec org, dir;
};

class FuncMaterials : public test::SceneDir {
protected:
  render::RenderSettings st;
  void SetUp() override {
    test::SceneDir::SetUp();
    std::ofstream(dir / "f.cal") << kCal;
    fs::copy_file(test::data("render/brdf_dz.dat"), dir / "brdf_dz.dat");
    st.ab = 0;
    st.dj = 0;
    st.dt = 0;
  }
  // Renders `rays` in a scene of a sun in direction `sun`, `rest`, and (if `floor` names a
  // material) the floor made of it.
  std::vector<Rgb> render(const Vec& sun, const std::string& rest, const std::string& floor,
                          const std::vector<Ray>& rays) {
    std::ofstream f(dir / "scene.rad");
    f << "void light sunmat 0 0 3 1000 1000 1000\n"
      << "sunmat source sun 0 0 4 " << sun[0] << " " << sun[1] << " " << sun[2] << " 1\n"
      << rest << "\n";
    if (!floor.empty()) f << floor << " polygon floor 0 0 12 -20 -20 0 20 -20 0 20 20 0 -20 20 0\n";
    f.close();
    std::vector<render::PrimaryRay> pr;
    for (const Ray& ray : rays)
      pr.push_back({ray.org, ray.dir, 0});
    std::vector<Rgb> out;
    for (const auto& x : render_rays("scene.rad", pr, st))
      out.push_back(x.value);
    return out;
  }
  // The floor seen straight down at the origin.
  Rgb down(const Vec& sun, const std::string& rest) {
    return render(sun, rest, "m", {{{0, 0, 1}, {0, 0, -1}}})[0];
  }
  void fails(const std::string& rest, const std::string& want) {
    try {
      down({0, 0, 1}, rest);
      ADD_FAILURE() << "no error for " << rest;
    } catch (const FatalError& e) {
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
    }
  }
};

void expect_rgb(const Rgb& got, const Rgb& want, const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], 1e-4 * std::abs(want[c]) + 1e-9) << what << " channel " << c;
}

Vec unit(double x, double y, double z) {
  double n = std::sqrt(x * x + y * y + z * z);
  return {x / n, y / n, z / n};
}

} // namespace

// A constant BRDF K: 1000 omega (C (1 - spec) / pi + K spec), uncoloured for plasfunc.
TEST_F(FuncMaterials, PlasfuncConstantBrdf) {
  Rgb v = down({0, 0, 1}, "void plasfunc m 2 const f.cal 0 5 0.5 0.4 0.3 0.2 3");
  Rgb want;
  const Rgb c{0.5, 0.4, 0.3};
  for (int i = 0; i < 3; ++i)
    want[i] = kSun * kOmega * (c[i] * 0.8 / kPi + 3 * 0.2);
  expect_rgb(v, want, "plasfunc");
}

// metfunc colours the function part with the material's colour.
TEST_F(FuncMaterials, MetfuncColoursTheFunction) {
  Rgb v = down({0, 0, 1}, "void metfunc m 2 const f.cal 0 5 0.5 0.4 0.3 0.2 3");
  const Rgb c{0.5, 0.4, 0.3};
  Rgb want;
  for (int i = 0; i < 3; ++i)
    want[i] = kSun * kOmega * (c[i] * 0.8 / kPi + 3 * 0.2 * c[i]);
  expect_rgb(v, want, "metfunc");
}

// The function sees the light direction in function coordinates, and the solid angle: with the
// sun at (0.6, 0, 0.8), lightz gives 0.8; under "-rz 90" the function's y axis is world -x, so
// -dy is the sun's x, 0.6; solid() returns 1000 omega.
TEST_F(FuncMaterials, LightDirectionTransformAndSolidAngle) {
  const Vec sun = unit(0.6, 0, 0.8);
  const double ldot = 0.8, diff = 0.5 * 0.9 / kPi;
  auto expect = [&](const std::string& mat, double f, const std::string& what) {
    Rgb v = down(sun, mat);
    double want = kSun * kOmega * ldot * (diff + f * 0.1);
    expect_rgb(v, {want, want, want}, what);
  };
  expect("void plasfunc m 2 lightz f.cal 0 4 0.5 0.5 0.5 0.1", 0.8, "lightz");
  expect("void plasfunc m 4 minusy f.cal -rz 90 0 4 0.5 0.5 0.5 0.1", 0.6, "minusy -rz 90");
  expect("void plasfunc m 2 solid f.cal 0 4 0.5 0.5 0.5 0.1", 1000 * kOmega, "solid angle");
}

// The ray variables of the view ray: RdotP (cosine with the view ray), CrP (the colour) and
// NzP (the normal), for a ray straight down and one at 60 degrees from the normal.
TEST_F(FuncMaterials, RayVariables) {
  std::vector<Ray> rays{{{0, 0, 1}, {0, 0, -1}},
                        {{0, 0, 1}, {std::sin(kPi / 3), 0, -std::cos(kPi / 3)}}};
  auto v = render({0, 0, 1}, "void plasfunc m 2 viewdep f.cal 0 4 0.4 0.5 0.6 0.1", "m", rays);
  const Rgb c{0.4, 0.5, 0.6};
  const double rdot[] = {1, 0.5};
  for (int k = 0; k < 2; ++k) {
    double f = rdot[k] * 0.4 + 1;
    Rgb want;
    for (int i = 0; i < 3; ++i)
      want[i] = kSun * kOmega * (c[i] * 0.9 / kPi + f * 0.1);
    expect_rgb(v[k], want, "ray " + std::to_string(k));
  }
}

// The ambient coefficient is the colour x (1 - trans), specular share included (Radiance has
// no specular rays for these materials); with -ab 0 it multiplies -av.
TEST_F(FuncMaterials, AmbientUsesTheColour) {
  st.av = {0.1, 0.2, 0.3};
  // The sun on the horizon adds nothing (n.l = 0).
  Rgb v = down({1, 0, 0}, "void plasfunc m 2 const f.cal 0 5 0.5 0.4 0.3 0.2 3");
  expect_rgb(v, {0.05, 0.08, 0.09}, "plasfunc ambient");
  // transfunc: trans = 0.5 (1 - 0.2) = 0.4 beyond, the rest on the ray's side.
  v = down({1, 0, 0}, "void transfunc m 2 const f.cal 0 7 0.5 0.4 0.3 0.2 0.5 0.25 3");
  expect_rgb(v, {0.05, 0.08, 0.09}, "transfunc ambient, both sides");
}

// transfunc: trans = A5 (1 - A4), tspec = trans A6, diffuse transmission trans - tspec, all
// coloured; the function is coloured on the transmitted side only. Seen from above with the
// sun above (reflection), and from below (the back face turned toward the ray).
TEST_F(FuncMaterials, TransfuncReflectionAndTransmission) {
  const std::string mat = "void transfunc m 2 const7 f.cal 0 7 0.5 0.4 0.3 0.2 0.5 0.25 3";
  const Rgb c{0.5, 0.4, 0.3};
  const double trans = 0.5 * 0.8, tspec = trans * 0.25, tdiff = trans - tspec;
  auto v = render({0, 0, 1}, mat, "m", {{{0, 0, 1}, {0, 0, -1}}, {{0, 0, -1}, {0, 0, 1}}});
  Rgb refl, tran;
  for (int i = 0; i < 3; ++i) {
    refl[i] = kSun * kOmega * (c[i] * (1 - trans - 0.2) / kPi + 3 * 0.2);
    tran[i] = kSun * kOmega * (c[i] * tdiff / kPi + 3 * tspec * c[i]);
  }
  expect_rgb(v[0], refl, "reflected side");
  expect_rgb(v[1], tran, "transmitted side");
}

// -bv-: the back of a plasfunc is invisible: the ray goes on and sees the sun (radiance 1000).
TEST_F(FuncMaterials, BackFaceInvisibleWithoutBv) {
  st.bv = false;
  auto v = render({0, 0, 1}, "void plasfunc m 2 const f.cal 0 5 0.5 0.4 0.3 0.2 3", "m",
                  {{{0, 0, -1}, {0, 0, 1}}});
  expect_rgb(v[0], {1000, 1000, 1000}, "back face");
}

// A compute error in the function leaves the diffuse part (Radiance warns and goes on).
TEST_F(FuncMaterials, ComputeErrorKeepsTheDiffusePart) {
  Rgb v = down({0, 0, 1}, "void plasfunc m 2 bad f.cal 0 4 0.5 0.5 0.5 0.2");
  double want = kSun * kOmega * 0.5 * 0.8 / kPi;
  expect_rgb(v, {want, want, want}, "bad");
}

// plasdata: the data file (tests/data/render/brdf_dz.dat: 1-D over 0..1, values 0.2 0.5 1)
// at the coordinate cz = dz, through scaled(v) = v A5. Sun at dz = 0.75: v = 0.75.
TEST_F(FuncMaterials, PlasdataInterpolatesTheFile) {
  const Vec sun = unit(std::sqrt(1 - 0.75 * 0.75), 0, 0.75);
  Rgb v = down(sun, "void plasdata m 4 scaled brdf_dz.dat f.cal cz 0 5 0.5 0.4 0.3 0.2 2");
  const Rgb c{0.5, 0.4, 0.3};
  Rgb want;
  for (int i = 0; i < 3; ++i)
    want[i] = kSun * kOmega * 0.75 * (c[i] * 0.8 / kPi + 0.75 * 2 * 0.2);
  expect_rgb(v, want, "plasdata");
  // metdata colours it; the sun overhead is at the data's end, v = 1.
  v = down({0, 0, 1}, "void metdata m 4 scaled brdf_dz.dat f.cal cz 0 5 0.5 0.4 0.3 0.2 2");
  for (int i = 0; i < 3; ++i)
    want[i] = kSun * kOmega * (c[i] * 0.8 / kPi + 1.0 * 2 * 0.2 * c[i]);
  expect_rgb(v, want, "metdata");
}

// transdata from below: the interpolated value on the transmitted side, coloured.
TEST_F(FuncMaterials, TransdataTransmits) {
  const std::string mat = "void transdata m 4 scaled7 brdf_dz.dat f.cal cz 0 7 0.5 0.4 0.3 0.2 "
                          "0.5 0.25 2";
  auto v = render({0, 0, 1}, mat, "m", {{{0, 0, -1}, {0, 0, 1}}});
  const Rgb c{0.5, 0.4, 0.3};
  const double tspec = 0.1, tdiff = 0.3; // trans = 0.5 (1 - 0.2) = 0.4, a quarter of it clear
  // The light direction is in function (here world) coordinates whichever side is seen: the
  // sun overhead is at the data's end, dz = 1, v = 1, and the function gives 2.
  Rgb want;
  for (int i = 0; i < 3; ++i)
    want[i] = kSun * kOmega * c[i] * (tdiff / kPi + 2 * tspec);
  expect_rgb(v[0], want, "transdata from below");
}

// BRTDfunc with constant coefficients and no diffuse part: a mirror ray weighted by the
// reflection expressions and a straight ray by the transmission ones, from either side (no
// back-face rule). Glowing planes above (1 2 3, facing down) and below (4 5 6, facing up).
TEST_F(FuncMaterials, BrtdfuncMirrorAndTransmission) {
  st.bv = false; // BRTDfunc ignores it
  const std::string rest =
      "void glow top 0 0 4 1 2 3 0\n"
      "top polygon ceiling 0 0 12 -50 -50 2 -50 50 2 50 50 2 50 -50 2\n"
      "void glow bottom 0 0 4 4 5 6 0\n"
      "bottom polygon ground 0 0 12 -50 -50 -1 50 -50 -1 50 50 -1 -50 50 -1\n"
      "void BRTDfunc m 10 0.3 0.4 0.5 0.1 0.2 0.3 0 0 0 . 0 9 0 0 0 0 0 0 0 0 0";
  auto v =
      render({0, 0, -1}, rest, "m",
             {{{0, 0, 1}, {0, 0, -1}}, {{0, 0, -0.5}, {0, 0, 1}}, {{-1, 0, 1}, unit(1, 0, -1)}});
  expect_rgb(v[0], {0.3 * 1 + 0.1 * 4, 0.4 * 2 + 0.2 * 5, 0.5 * 3 + 0.3 * 6}, "from above");
  expect_rgb(v[1], {0.3 * 4 + 0.1 * 1, 0.4 * 5 + 0.2 * 2, 0.5 * 6 + 0.3 * 3}, "from below");
  expect_rgb(v[2], {0.3 * 1 + 0.1 * 4, 0.4 * 2 + 0.2 * 5, 0.5 * 3 + 0.3 * 6}, "oblique");
}

// Shadow rays pass a BRTDfunc with its transmission expressions: a plastic floor under a
// BRTDfunc sheet at z = 1 receives the sun times (0.1, 0.2, 0.3).
TEST_F(FuncMaterials, BrtdfuncTransmitsShadowRays) {
  const std::string rest =
      "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
      "void BRTDfunc sheet 10 0 0 0 0.1 0.2 0.3 0 0 0 . 0 9 0 0 0 0 0 0 0 0 0\n"
      "sheet polygon roof 0 0 12 -50 -50 1 50 -50 1 50 50 1 -50 50 1";
  auto v = render({0, 0, 1}, rest, "grey", {{{0, 0, 0.5}, {0, 0, -1}}});
  double d = kSun * kOmega * 0.5 / kPi;
  expect_rgb(v[0], {0.1 * d, 0.2 * d, 0.3 * d}, "shadowed floor");
}

// BRTDfunc's directional-diffuse functions on direct light, per channel ("0" is zero, a name
// repeated reuses the value), added to the front or back diffuse reflectance or the diffuse
// transmittance, never coloured by the material.
TEST_F(FuncMaterials, BrtdfuncDirectFrontBackTransmitted) {
  const std::string mat = "void BRTDfunc m 10 0 0 0 0 0 0 half 0 half f.cal 0 "
                          "9 0.1 0.2 0.3 0.4 0.5 0.6 0.05 0.06 0.07";
  const double k = kSun * kOmega;
  // Sun above: from above the front reflectance, from below the diffuse transmittance.
  auto v = render({0, 0, 1}, mat, "m", {{{0, 0, 1}, {0, 0, -1}}, {{0, 0, -1}, {0, 0, 1}}});
  expect_rgb(v[0], {k * (0.1 / kPi + 0.5), k * 0.2 / kPi, k * (0.3 / kPi + 0.5)}, "front");
  expect_rgb(v[1], {k * (0.05 / kPi + 0.5), k * 0.06 / kPi, k * (0.07 / kPi + 0.5)}, "transmitted");
  // Sun below, seen from below: the back reflectance.
  v = render({0, 0, -1}, mat, "m", {{{0, 0, -1}, {0, 0, 1}}});
  expect_rgb(v[0], {k * (0.4 / kPi + 0.5), k * 0.5 / kPi, k * (0.6 / kPi + 0.5)}, "back");
  // Without diffuse parts the direct part still runs when the red function is not "0"...
  Rgb w =
      down({0, 0, 1}, "void BRTDfunc m 10 0 0 0 0 0 0 quarter half 0 f.cal 0 9 0 0 0 0 0 0 0 0 0");
  expect_rgb(w, {k * 0.25, k * 0.5, 0}, "functions only");
  // ... and, as in Radiance, not when it is.
  w = down({0, 0, 1}, "void BRTDfunc m 10 0 0 0 0 0 0 0 half 0 f.cal 0 9 0 0 0 0 0 0 0 0 0");
  expect_rgb(w, {0, 0, 0}, "red function 0");
}

// Patterns multiply the diffuse values (and CrP..) of the BRDF materials.
TEST_F(FuncMaterials, PatternsModifyTheColour) {
  Rgb v = down({0, 0, 1}, "void colorfunc tint 4 0.5 1 2 . 0 0\n"
                          "tint metfunc m 2 const f.cal 0 5 0.5 0.4 0.3 0.2 3");
  const Rgb c{0.25, 0.4, 0.6};
  Rgb want;
  for (int i = 0; i < 3; ++i)
    want[i] = kSun * kOmega * (c[i] * 0.8 / kPi + 3 * 0.2 * c[i]);
  expect_rgb(v, want, "patterned metfunc");
}

// Inside an instance placed with -rz 90 the function's coordinates are the instance's: the sun
// at world (0.6, 0, 0.8) is at (0, -0.6, 0.8) there, so -dy gives 0.6 (0 without the placement).
TEST_F(FuncMaterials, InstancePlacesTheFunction) {
  std::ofstream(dir / "inner.rad")
      << "void plasfunc m 2 minusy f.cal 0 4 0.5 0.5 0.5 0.1\n"
      << "m polygon floor 0 0 12 -20 -20 0 20 -20 0 20 20 0 -20 20 0\n";
  const Vec sun = unit(0.6, 0, 0.8);
  std::ofstream(dir / "main.rad") << "void light sunmat 0 0 3 1000 1000 1000\n"
                                  << "sunmat source sun 0 0 4 " << sun[0] << " " << sun[1] << " "
                                  << sun[2] << " 1\n"
                                  << "void instance it 3 inner.oct -rz 90 0 0\n";
  scene::LoadedScene ls;
  scene::read_rad_file(ls.main, "main.rad");
  auto inner = std::make_shared<scene::SceneDescription>();
  scene::read_rad_file(*inner, "inner.rad");
  ls.octrees[(dir / "inner.oct").string()] = inner;
  render::Renderer r(ls, st, device::default_context());
  std::vector<render::PrimaryRay> pr{{{0, 0, 1}, {0, 0, -1}, 0}};
  std::vector<render::PrimaryResult> res(1);
  r.render(pr, res);
  double want = kSun * kOmega * 0.8 * (0.5 * 0.9 / kPi + 0.6 * 0.1);
  expect_rgb(res[0].value, {want, want, want}, "instance");
}

// The BRDF materials as sides of a mixture (Radiance's raymixture): each side shades the hit
// alone, weighted by its share. A plasfunc (with a colour pattern of its own, its function of
// RdotP CrP NzP) and a plain plastic at coefficient 0.3, seen obliquely under the sun overhead.
TEST_F(FuncMaterials, PlasfuncSideOfMixture) {
  const std::string rest = "void colorfunc halve 4 0.5 0.5 0.5 . 0 0\n"
                           "halve plasfunc pf 2 viewdep f.cal 0 4 0.5 0.5 0.5 0.5\n"
                           "void plastic pl 0 0 5 0.2 0.4 0.6 0 0\n"
                           "void mixfunc m 4 pf pl 0.3 . 0 0";
  auto v = render({0, 0, 1}, rest, "m", {{{-1, 0, 1}, unit(1, 0, -1)}});
  double c = 0.5 * 0.5, rspec = 0.5;                              // CrP: colour x pattern
  double f = std::sqrt(0.5) * c + 1;                              // RdotP CrP + NzP
  double a = kSun * kOmega * (c * (1 - rspec) / kPi + f * rspec); // ldot = 1
  Rgb b{kSun * kOmega * 0.2 / kPi, kSun * kOmega * 0.4 / kPi, kSun * kOmega * 0.6 / kPi};
  expect_rgb(v[0], {0.3 * a + 0.7 * b[0], 0.3 * a + 0.7 * b[1], 0.3 * a + 0.7 * b[2]},
             "plasfunc side");
}

// A BRTDfunc side: its mirror ray (weight 0.5) sees a green glow patch at z = 3, its front
// diffuse part (0.2) the sun; the other side a plastic, coefficient 0.3.
TEST_F(FuncMaterials, BrtdfuncSideOfMixture) {
  const std::string rest =
      "void glow patchglow 0 0 4 0 5 0 0\n"
      "patchglow polygon patch 0 0 12 2 -1 3 2 1 3 4 1 3 4 -1 3\n"
      "void BRTDfunc bt 10 0.5 0.5 0.5 0 0 0 0 0 0 . 0 9 0.2 0.2 0.2 0 0 0 0 0 0\n"
      "void plastic pl 0 0 5 0.2 0.4 0.6 0 0\n"
      "void mixfunc m 4 bt pl 0.3 . 0 0";
  auto v = render({0, 0, 1}, rest, "m", {{{-1, 0, 1}, unit(1, 0, -1)}});
  double diff = kSun * kOmega * 0.2 / kPi;
  Rgb a{diff, 0.5 * 5 + diff, diff};
  Rgb b{kSun * kOmega * 0.2 / kPi, kSun * kOmega * 0.4 / kPi, kSun * kOmega * 0.6 / kPi};
  expect_rgb(v[0], {0.3 * a[0] + 0.7 * b[0], 0.3 * a[1] + 0.7 * b[1], 0.3 * a[2] + 0.7 * b[2]},
             "BRTDfunc side");
}

// Shadow rays through a mixture pass a BRTDfunc side's transmission for its share (a void side
// passes whole): a grey floor under a sheet mixing a BRTDfunc (transmission 0.6) with void at
// 0.3 receives the sun times 0.3 x 0.6 + 0.7.
TEST_F(FuncMaterials, BrtdfuncSideTransmitsShadowRays) {
  const std::string rest =
      "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
      "void BRTDfunc sheet 10 0 0 0 0.6 0.6 0.6 0 0 0 . 0 9 0 0 0 0 0 0 0 0 0\n"
      "void mixfunc mx 4 sheet void 0.3 . 0 0\n"
      "mx polygon roof 0 0 12 -50 -50 1 50 -50 1 50 50 1 -50 50 1";
  auto v = render({0, 0, 1}, rest, "grey", {{{0, 0, 0.5}, {0, 0, -1}}});
  double d = kSun * kOmega * 0.5 / kPi * (0.3 * 0.6 + 0.7);
  expect_rgb(v[0], {d, d, d}, "shadowed floor");
}

TEST_F(FuncMaterials, Errors) {
  fails("void plasfunc m 1 const 0 4 0.5 0.5 0.5 0", "bad # arguments for plasfunc \"m\"");
  fails("void plasfunc m 2 const f.cal 0 3 0.5 0.5 0.5", "bad # arguments for plasfunc \"m\"");
  fails("void transfunc m 2 const f.cal 0 5 0.5 0.5 0.5 0 0", "bad # arguments for transfunc");
  fails("void metdata m 3 scaled brdf_dz.dat f.cal 0 4 0.5 0.5 0.5 0",
        "bad # arguments for metdata");
  fails("void BRTDfunc m 9 0 0 0 0 0 0 0 0 0 0 9 0 0 0 0 0 0 0 0 0",
        "bad # arguments for BRTDfunc");
  fails("void BRTDfunc m 10 0 0 0 0 0 0 0 0 0 . 0 8 0 0 0 0 0 0 0 0",
        "bad # arguments for BRTDfunc");
  fails("void plasfunc m 2 const nowhere.cal 0 4 0.5 0.5 0.5 0",
        "cannot find function file \"nowhere.cal\"");
  fails("void plasdata m 4 scaled nowhere.dat f.cal cz 0 4 0.5 0.5 0.5 0",
        "cannot find data file \"nowhere.dat\"");
  fails("void plasfunc m 2 nosuch f.cal 0 4 0.5 0.5 0.5 0", "nosuch: undefined function");
  fails("void plasfunc m 3 const f.cal -rx 0 4 0.5 0.5 0.5 0", "bad transform");
}
