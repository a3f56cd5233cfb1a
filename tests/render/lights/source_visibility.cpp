// What rays see at light sources (scene-format.md §3.6; Radiance's m_light, whose tests come
// in this order: badcomponent, passillum, srcignore). Ambient rays see the front of an illum
// as black, since the direct calculation already counts the light the illum stands for,
// whether or not it has an alternate material; from behind they pass through it (or meet its
// alternate material). A glow is seen by ambient rays only beyond its radius of influence, and
// never with a negative radius. With -dv- every source is black to every ray except a glow
// beyond its radius along the whole path. A meter at the origin faces up; a bright glow
// (radius 0: no source, seen by ambient rays only) lies behind the illum, so an ambient ray that
// wrongly passed would bring its 10 W/sr/m².
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <string>

#include "scene_dir.h"

using namespace radcl;

namespace {

constexpr double kPi = std::numbers::pi;

const char* kGlow = "void glow bright 0 0 4 10 10 10 0\n";

class SourceVisibility : public test::SceneDir {
protected:
  // Red of one ray from `org` along `dir` (with `meter`, the irradiance at a meter at `org`
  // facing `dir`), with -ab `ab` -aa 0 and -dv as `dv`.
  double trace(const std::string& scene, int ab, const render::Vec3d& org, const render::Vec3d& dir,
               bool meter = true, bool dv = true) {
    std::ofstream("scene.rad") << scene;
    render::RenderSettings st;
    st.ab = ab;
    st.ad = 256;
    st.aa = 0;
    st.lw = 1e-4;
    st.dv = dv;
    st.irradiance_I = meter;
    return render_rays("scene.rad", {{org, dir, 0}}, st)[0].value[0];
  }
  double meter(const std::string& scene, int ab, double z, double nz) {
    return trace(scene, ab, {0, 0, z}, {0, 0, nz});
  }
};

// A 2 m square illum 1 m above the meter, facing down at it, the glow just behind it.
std::string covered(const std::string& illum) {
  return std::string(kGlow) + illum +
         "port polygon p 0 0 12 -1 -1 1  -1 1 1  1 1 1  1 -1 1\n"
         "bright polygon lid 0 0 12 -1 -1 1.01  -1 1 1.01  1 1 1.01  1 -1 1.01\n";
}

// The illum's direct light: pi x its radiance (1) x the square's form factor from the meter,
// four times that of a unit square seen from above its corner.
double square_direct() {
  const double q = 2 * (1 / std::sqrt(2.0)) * std::atan(1 / std::sqrt(2.0)) / (2 * kPi);
  return kPi * 4 * q;
}

} // namespace

TEST_F(SourceVisibility, FrontWithoutAlternateIsBlack) {
  const std::string s = covered("void illum port 0 0 3 1 1 1\n");
  const double direct = meter(s, 0, 0, 1);
  EXPECT_NEAR(direct, square_direct(), 0.01 * square_direct()); // Radiance: 1.7481
  EXPECT_NEAR(meter(s, 1, 0, 1), direct, 1e-4 * direct);        // not the glow's light through it
  EXPECT_NEAR(meter(s, 3, 0, 1), direct, 1e-4 * direct);
}

TEST_F(SourceVisibility, FrontWithAlternateIsBlack) {
  // A floor below the meter, lit by the illum, would light the white alternate.
  const std::string s =
      covered("void plastic white 0 0 5 0.8 0.8 0.8 0 0\nvoid illum port 1 white 0 3 1 1 1\n") +
      "white polygon floor 0 0 12 -10 -10 -0.5  10 -10 -0.5  10 10 -0.5  -10 10 -0.5\n";
  const double direct = meter(s, 0, 0, 1);
  EXPECT_NEAR(direct, square_direct(), 0.01 * square_direct());
  EXPECT_NEAR(meter(s, 2, 0, 1), direct, 1e-4 * direct); // not the white alternate's light
}

// From behind an illum is passed: a meter above it, facing down, sees the glow below through
// it (all its ambient samples bring 10 W/sr/m²) and nothing from the illum.
TEST_F(SourceVisibility, BackIsPassed) {
  const std::string s =
      std::string(kGlow) + "void illum port 0 0 3 1 1 1\n" +
      "port polygon p 0 0 12 -1000 -1000 1  -1000 1000 1  1000 1000 1  1000 -1000 1\n"
      "bright polygon floor 0 0 12 -1000 -1000 0  1000 -1000 0  1000 1000 0  -1000 1000 0\n";
  EXPECT_NEAR(meter(s, 0, 1.5, -1), 0.0, 1e-9);
  EXPECT_NEAR(meter(s, 1, 1.5, -1), 10 * kPi, 1e-3 * 10 * kPi);
}

// A glow of negative radius takes no part in illumination: black to ambient rays (it was
// seen as a radius-0 glow is). Radiance 2fcca99ac: 0 and 17.57 for these two.
TEST_F(SourceVisibility, NegativeRadiusGlowIsBlackToAmbientRays) {
  auto lid = [](const std::string& radius) {
    return "void glow g 0 0 4 10 10 10 " + radius +
           "\ng polygon lid 0 0 12 -1 -1 1  -1 1 1  1 1 1  1 -1 1\n";
  };
  EXPECT_EQ(meter(lid("-1"), 1, 0, 1), 0.0);
  EXPECT_NEAR(meter(lid("0"), 1, 0, 1), 10 * square_direct(), 0.03 * 10 * square_direct());
  // Seen directly it is as bright as any glow.
  EXPECT_NEAR(trace(lid("-1"), 0, {0, 0, 0}, {0, 0, 1}, false), 10.0, 1e-5);
}

// -dv-: a light is black to a view ray and to its mirror reflection; a glow is seen only
// beyond its radius of influence, measured along the whole path (here 1 m), so a radius-0
// glow (a sky) stays visible. Radiance 2fcca99ac gives the same for each.
TEST_F(SourceVisibility, DvOffHidesSourcesButFarGlows) {
  const std::string lid = " polygon lid 0 0 12 -1 -1 1  -1 1 1  1 1 1  1 -1 1\n";
  auto up = [&](const std::string& mat, bool dv) {
    return trace(mat + "\ns" + lid, 0, {0, 0, 0}, {0, 0, 1}, false, dv);
  };
  EXPECT_NEAR(up("void light s 0 0 3 10 10 10", true), 10.0, 1e-5);
  EXPECT_EQ(up("void light s 0 0 3 10 10 10", false), 0.0);
  EXPECT_NEAR(up("void glow s 0 0 4 10 10 10 0", false), 10.0, 1e-5);
  EXPECT_NEAR(up("void glow s 0 0 4 10 10 10 0.5", false), 10.0, 1e-5);
  EXPECT_EQ(up("void glow s 0 0 4 10 10 10 5", false), 0.0);
  EXPECT_EQ(up("void glow s 0 0 4 10 10 10 -1", false), 0.0);
  const std::string mirrored = "void light s 0 0 3 10 10 10\ns" + lid +
                               "void mirror mr 0 0 3 0.8 0.8 0.8\n"
                               "mr polygon fl 0 0 12 -5 -5 0  5 -5 0  5 5 0  -5 5 0\n";
  EXPECT_NEAR(trace(mirrored, 0, {0, -0.2, 0.5}, {0, 0.2, -0.5}, false, true), 8.0, 1e-4);
  EXPECT_EQ(trace(mirrored, 0, {0, -0.2, 0.5}, {0, 0.2, -0.5}, false, false), 0.0);
}
