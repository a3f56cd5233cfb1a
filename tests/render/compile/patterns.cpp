// Patterns and textures on a test scene, against hand-computed values: a grey plastic floor
// (z = 0) under a sun straight above; a pattern's effect is the ratio of the floor's radiance
// with it to the radiance without it.
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

const char* kCal = R"(
{ test patterns }
pr = Px;  pg = Py * A1;  pb = 1;
bright = Rdot;
zero = 1 / (Px - Px);
tilt = 0.5;
glowing = if(Dx, 2, 3);
)";

// Radiance of the floor seen from above at (x, y), optionally seen along `dir`.
class Patterns : public radcl::test::SceneDir {
protected:
  void SetUp() override {
    SceneDir::SetUp();
    std::ofstream(dir / "pat.cal") << kCal;
  }
  // `mods`: pattern primitives; `chain`: the floor material's modifier.
  std::vector<std::array<double, 3>> render(const std::string& mods, const std::string& chain,
                                            const std::vector<std::array<double, 6>>& rays) {
    std::ofstream(dir / "scene.rad")
        << "void light sunmat 0 0 3 1000 1000 1000\n"
        << "sunmat source sun 0 0 4 0 0 1 1\n"
        << mods << "\n"
        << chain << " plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
        << "grey polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    std::vector<render::PrimaryRay> pr;
    for (const auto& v : rays)
      pr.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, 0});
    return render_values("scene.rad", pr, st);
  }
  std::array<double, 6> down(double x, double y) { return {x, y, 1, 0, 0, -1}; }
};

} // namespace

// colorfunc with a transform: function coordinates are world minus (1, 0, 0); A1 = 0.5.
TEST_F(Patterns, ColorfuncWithTranslation) {
  auto plain = render("", "void", {down(3, 2)});
  auto pat = render("void colorfunc cf 8 pr pg pb pat.cal -t 1 0 0 0 1 0.5", "cf", {down(3, 2)});
  ASSERT_GT(plain[0][0], 0);
  EXPECT_NEAR(pat[0][0] / plain[0][0], 2.0, 1e-4);
  EXPECT_NEAR(pat[0][1] / plain[0][1], 1.0, 1e-4);
  EXPECT_NEAR(pat[0][2] / plain[0][2], 1.0, 1e-4);
}

// A rotation about z by 90 degrees: world (3, 2) is function (2, -3).
TEST_F(Patterns, ColorfuncWithRotation) {
  auto plain = render("", "void", {down(3, 2)});
  auto pat = render("void colorfunc cf 6 pr pg pb pat.cal -rz 90 0 1 1", "cf", {down(3, 2)});
  EXPECT_NEAR(pat[0][0] / plain[0][0], 2.0, 1e-4);
  EXPECT_NEAR(pat[0][1] / plain[0][1], -3.0, 1e-4); // pg = Py * A1, A1 = 1
}

// brightfunc of Rdot: the cosine between the view ray and the normal (60 degrees here).
TEST_F(Patterns, BrightfuncSeesTheRay) {
  double s = std::sin(M_PI / 3), c = std::cos(M_PI / 3);
  std::array<double, 6> slant = {0, -s, c, 0, s, -c};
  auto plain = render("", "void", {slant});
  auto pat = render("void brightfunc bf 2 bright pat.cal 0 0", "bf", {slant});
  EXPECT_NEAR(pat[0][0] / plain[0][0], c, 1e-4);
}

// A pattern before the material and one modifying the material multiply.
TEST_F(Patterns, PatternsAlongTheChainMultiply) {
  auto plain = render("", "void", {down(3, 2)});
  auto pat = render("void brightfunc bf 2 bright pat.cal 0 0\n"
                    "bf colorfunc cf 8 pr pg pb pat.cal -t 1 0 0 0 1 0.5",
                    "cf", {down(3, 2)});
  EXPECT_NEAR(pat[0][0] / plain[0][0], 2.0, 1e-4); // Rdot = 1 straight down
}

// texfunc tilts the normal by (0.5, 0, 0): the sun overhead meets it at cos = 1/sqrt(1.25).
TEST_F(Patterns, TexfuncTiltsTheShadingNormal) {
  auto plain = render("", "void", {down(3, 2)});
  auto pat = render("void texfunc tf 4 tilt 0 0 pat.cal 0 0", "tf", {down(3, 2)});
  EXPECT_NEAR(pat[0][0] / plain[0][0], 1 / std::sqrt(1.25), 1e-3);
}

// Division by zero while shading: Radiance warns and leaves the colour as it was.
TEST_F(Patterns, ComputeErrorLeavesTheColour) {
  auto plain = render("", "void", {down(3, 2)});
  auto pat = render("void brightfunc bf 2 zero pat.cal 0 0", "bf", {down(3, 2)});
  EXPECT_NEAR(pat[0][0] / plain[0][0], 1.0, 1e-6);
}

// Patterns also modulate what light materials emit toward the viewer.
TEST_F(Patterns, PatternOnAGlow) {
  std::ofstream(dir / "glow.rad") << "void brightfunc g 2 glowing pat.cal 0 0\n"
                                  << "g glow warm 0 0 4 1 1 1 0\n"
                                  << "warm sphere ball 0 0 4 0 0 0 1\n";
  render::RenderSettings st;
  st.ab = 0;
  const auto res =
      render_rays("glow.rad", {{{-5, 0, 0}, {1, 0, 0}, 0}, {{5, 0, 0}, {-1, 0, 0}, 0}}, st);
  EXPECT_NEAR(res[0].value[0], 2.0, 1e-5);
  EXPECT_NEAR(res[1].value[0], 3.0, 1e-5);
}

// Errors name the primitive: an undefined variable, a missing function file, a bad transform.
TEST_F(Patterns, ErrorsNameThePattern) {
  auto fails = [&](const std::string& mods, const std::string& chain, const std::string& want) {
    try {
      render(mods, chain, {down(0, 0)});
      ADD_FAILURE() << "no error for " << mods;
    } catch (const FatalError& e) {
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
    }
  };
  fails("void brightfunc bf 2 nosuch pat.cal 0 0", "bf", "brightfunc \"bf\"");
  fails("void brightfunc bf 2 bright missing.cal 0 0", "bf", "missing.cal");
  fails("void brightfunc bf 4 bright pat.cal -t 1 0 0", "bf", "bad transform");
  // A mixture among the material's own modifiers names sides defined before it.
  fails("void mixfunc mf 4 grey grey 0.5 . 0 0", "mf",
        "mixfunc \"mf\": undefined modifier \"grey\"");
}
