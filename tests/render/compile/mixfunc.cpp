// mixfunc (scene-format.md §4, Radiance's raymixture) on a test scene under a sun straight
// above, against renders of its sides alone: a mixture of two materials returns the blend of
// what each returns, a void side lets its share of the ray (and of the sunlight) through.
// Radiance evaluates both sides with scaled weights, so with -ab 0 and -dj 0 the blend is exact
// for every ray, not only on average.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/util/error.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;

namespace {

const char* kMaterials = "void plastic red 0 0 5 0.6 0.2 0.2 0 0\n"
                         "void plastic blue 0 0 5 0.1 0.1 0.5 0 0\n"
                         "void plastic grey 0 0 5 0.4 0.4 0.4 0 0\n";

using Rgb = std::array<double, 3>;

class Mixfunc : public radcl::test::SceneDir {
protected:
  void SetUp() override {
    SceneDir::SetUp();
    std::ofstream(dir / "mix.cal") << "sel = if(Px, 1, 0);\n";
  }
  // The radiance seen straight down from z = 2 at (x, y) in a scene of the sun, the test
  // materials and `rest`.
  std::vector<Rgb> render(const std::string& rest, const std::vector<std::array<double, 2>>& at) {
    std::ofstream(dir / "scene.rad") << "void light sunmat 0 0 3 1000 1000 1000\n"
                                     << "sunmat source sun 0 0 4 0 0 1 1\n"
                                     << kMaterials << rest << "\n";
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    return render_values("scene.rad", rays_down(at, 2), st);
  }
  static std::string floor(const std::string& mod) {
    return mod + " polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
  }
  static std::string screen(const std::string& mod) {
    return mod + " polygon screen 0 0 12 -10 -10 1 10 -10 1 10 10 1 -10 10 1\n";
  }
  static std::vector<std::array<double, 2>> grid() {
    std::vector<std::array<double, 2>> g;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        g.push_back({-7 + 2.0 * i, -7 + 2.0 * j});
    return g;
  }
  static void expect_rgb(const Rgb& got, const Rgb& want, double rel) {
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c], want[c], rel * std::abs(want[c]) + 1e-12) << "channel " << c;
  }
};

} // namespace

// A constant coefficient of 0.3: every ray sees 0.3 red + 0.7 blue.
TEST_F(Mixfunc, ConstantCoefficientBlendsTheMaterials) {
  auto at = grid();
  Rgb red = render(floor("red"), {{0, 0}})[0], blue = render(floor("blue"), {{0, 0}})[0];
  ASSERT_GT(red[0], 0);
  ASSERT_GT(blue[2], 0);
  auto mix = render("void mixfunc m 4 red blue 0.3 . 0 0\n" + floor("m"), at);
  Rgb mean{};
  for (const Rgb& v : mix) {
    expect_rgb(
        v,
        {0.3 * red[0] + 0.7 * blue[0], 0.3 * red[1] + 0.7 * blue[1], 0.3 * red[2] + 0.7 * blue[2]},
        1e-5);
    for (int c = 0; c < 3; ++c)
      mean[c] += v[c] / mix.size();
  }
  expect_rgb(
      mean,
      {0.3 * red[0] + 0.7 * blue[0], 0.3 * red[1] + 0.7 * blue[1], 0.3 * red[2] + 0.7 * blue[2]},
      1e-5);
}

// Coefficients 0 and 1 (and beyond, clamped) give exactly one of the materials.
TEST_F(Mixfunc, CoefficientsZeroAndOneChooseOneMaterial) {
  Rgb red = render(floor("red"), {{3, 2}})[0], blue = render(floor("blue"), {{3, 2}})[0];
  expect_rgb(render("void mixfunc m 4 red blue 0 . 0 0\n" + floor("m"), {{3, 2}})[0], blue, 1e-6);
  expect_rgb(render("void mixfunc m 4 red blue 1 . 0 0\n" + floor("m"), {{3, 2}})[0], red, 1e-6);
  expect_rgb(render("void mixfunc m 4 red blue 2.5 . 0 0\n" + floor("m"), {{3, 2}})[0], red, 1e-6);
  expect_rgb(render("void mixfunc m 4 red blue -1 . 0 0\n" + floor("m"), {{3, 2}})[0], blue, 1e-6);
}

// A coefficient from a function file: if(Px, 1, 0) paints x > 0 red and x < 0 blue.
TEST_F(Mixfunc, SpatialCoefficientSplitsTheFloor) {
  Rgb red = render(floor("red"), {{3, 2}})[0], blue = render(floor("blue"), {{3, 2}})[0];
  auto v = render("void mixfunc m 4 red blue sel mix.cal 0 0\n" + floor("m"),
                  {{3, 2}, {-3, 2}, {0.5, -6}, {-0.5, -6}});
  expect_rgb(v[0], red, 1e-6);
  expect_rgb(v[1], blue, 1e-6);
  expect_rgb(v[2], red, 1e-6);
  expect_rgb(v[3], blue, 1e-6);
}

// The material reported for a surface (rtrace -om) is the void mixture, as findmaterial().
TEST_F(Mixfunc, ReportsTheMixtureAsMaterial) {
  std::ofstream(dir / "scene.rad") << kMaterials << "void mixfunc m 4 red blue 0.5 . 0 0\n"
                                   << floor("m");
  scene::LoadedScene ls = scene::load_scene({"scene.rad"});
  render::RenderSettings st;
  render::Renderer r(ls, st, device::default_context());
  const render::CompiledScene& cs = r.compiled();
  ASSERT_EQ(cs.material_names.size(), cs.surfaces.size());
  bool found = false;
  for (std::size_t i = 0; i < cs.surfaces.size(); ++i)
    if (cs.surface_names[i] == "floor") {
      EXPECT_EQ(cs.material_names[i], "m");
      EXPECT_EQ(cs.materials[cs.surfaces[i].material].type, RC_OBJ_MIXFUNC);
      found = true;
    }
  EXPECT_TRUE(found);
}

// A pattern before the mixture applies to both sides; a side's material keeps its own.
TEST_F(Mixfunc, PatternsReachEachSide) {
  Rgb red = render(floor("red"), {{3, 2}})[0], blue = render(floor("blue"), {{3, 2}})[0];
  auto v = render("void brightfunc half 2 0.5 . 0 0\n"
                  "half plastic red2 0 0 5 0.6 0.2 0.2 0 0\n"
                  "void mixfunc m 4 red2 blue 0.3 . 0 0\n"
                  "m brightfunc dim 2 0.5 . 0 0\n" +
                      floor("dim"),
                  {{3, 2}})[0];
  expect_rgb(v,
             {0.3 * 0.25 * red[0] + 0.7 * 0.5 * blue[0], 0.3 * 0.25 * red[1] + 0.7 * 0.5 * blue[1],
              0.3 * 0.25 * red[2] + 0.7 * 0.5 * blue[2]},
             1e-5);
}

// A screen above a blue floor, mixing grey with void at 1/4 grey: the view sees 1/4 of the
// screen and 3/4 of the floor, which gets 3/4 of the sunlight through the screen.
TEST_F(Mixfunc, VoidSideLetsTheLightBehindThrough) {
  Rgb scr = render(screen("grey") + floor("blue"), {{3, 2}})[0];
  Rgb flo = render(floor("blue"), {{3, 2}})[0];
  Rgb want{0.25 * scr[0] + 0.5625 * flo[0], 0.25 * scr[1] + 0.5625 * flo[1],
           0.25 * scr[2] + 0.5625 * flo[2]};
  expect_rgb(
      render("void mixfunc m 4 grey void 0.25 . 0 0\n" + screen("m") + floor("blue"), {{3, 2}})[0],
      want, 1e-5);
  expect_rgb(
      render("void mixfunc m 4 void grey 0.75 . 0 0\n" + screen("m") + floor("blue"), {{3, 2}})[0],
      want, 1e-5);
  // All void in front: the floor in full sun.
  expect_rgb(
      render("void mixfunc m 4 grey void 0 . 0 0\n" + screen("m") + floor("blue"), {{3, 2}})[0],
      flo, 1e-6);
}

// What Radiance refuses (nested, pattern and light sides: tests/render/compile/mixtures.cpp).
TEST_F(Mixfunc, Errors) {
  auto fails = [&](const std::string& rest, const std::string& want) {
    try {
      render(rest, {{0, 0}});
      ADD_FAILURE() << "no error for " << rest;
    } catch (const FatalError& e) {
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
    }
  };
  fails("void mixfunc m 4 red nosuch 0.5 . 0 0\n" + floor("m"), "undefined modifier \"nosuch\"");
  fails("void brightfunc b 2 0.5 . 0 0\nb mixfunc m 4 red blue 0.5 . 0 0\n" + floor("m"),
        "mixfunc \"m\": inappropriate modifier");
  fails("void mixfunc m 3 red blue 0.5\n0\n0\n" + floor("m"), "bad # arguments");
}
