// Patterns on light sources modulate the direct calculation, as in Radiance (the shadow ray
// meets the source's surface and its material's patterns see that ray): a grey plastic floor
// (z = 0) lit only by a small light sphere or panel above it; a pattern's effect is the ratio
// of the floor's radiance with it to the radiance without it, at chosen floor points.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;

namespace {

const char* kCal = R"(
{ source patterns: Dx, Dy, Dz are the shadow ray's direction (floor towards the light) }
side = if(Dx, 2, 0.5);
up = if(Dz, 3, 0.25);
scaled = A1;
noop(v) = v;
red = 1; green = 0.5; blue = if(Dx, 0.2, 0.1);
)";

// A 1-D distribution over Dx from -1 to 1: 4 at -1, 1 at 0, 2 at 1.
const char* kData = "1\n-1 1 3\n4 1 2\n";

class SourcePatterns : public radcl::test::SceneDir {
protected:
  void SetUp() override {
    SceneDir::SetUp();
    std::ofstream(dir / "src.cal") << kCal;
    std::ofstream(dir / "dist.dat") << kData;
  }
  // `mods`: pattern primitives; `chain`: the light material's modifier; `lamp`: the light's
  // surface (modifier `lampmat`).
  std::vector<std::array<double, 3>> render(const std::string& mods, const std::string& chain,
                                            const std::string& lamp,
                                            const std::vector<double>& xs) {
    std::ofstream(dir / "scene.rad")
        << mods << "\n"
        << chain << " " << lamp << "\n"
        << "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
        << "grey polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    st.ds = 0; // one sample per source: its centre
    std::vector<render::PrimaryRay> pr;
    for (double x : xs)
      pr.push_back({{x, 0, 1}, {0, 0, -1}, 0});
    return render_values("scene.rad", pr, st);
  }
};

const std::string kSphere =
    "light lampmat 0 0 3 1000 1000 1000\nlampmat sphere lamp 0 0 4 0 0 2 0.05";

} // namespace

TEST_F(SourcePatterns, ConstantBrightfuncScalesTheLight) {
  auto plain = render("", "void", kSphere, {0, 1});
  auto pat = render("void brightfunc bf 2 scaled src.cal 0 1 0.25", "bf", kSphere, {0, 1});
  for (int i = 0; i < 2; ++i) {
    ASSERT_GT(plain[i][0], 0);
    EXPECT_NEAR(pat[i][0] / plain[i][0], 0.25, 1e-5);
  }
}

// The pattern sees the shadow ray's direction: towards +x from x = -1, towards -x from x = 1.
TEST_F(SourcePatterns, DirectionOfTheShadowRay) {
  auto plain = render("", "void", kSphere, {-1, 1, 0.5});
  auto pat = render("void brightfunc bf 2 side src.cal 0 0", "bf", kSphere, {-1, 1});
  EXPECT_NEAR(pat[0][1] / plain[0][1], 2.0, 1e-5);
  EXPECT_NEAR(pat[1][1] / plain[1][1], 0.5, 1e-5);
  auto up = render("void brightfunc bf 2 up src.cal 0 0", "bf", kSphere, {0.5});
  EXPECT_NEAR(up[0][2] / plain[2][2], 3.0, 1e-5);
}

// brightdata: the IES-like case (a distribution looked up by the shadow ray's direction).
TEST_F(SourcePatterns, BrightdataDistribution) {
  auto plain = render("", "void", kSphere, {-1, 1, 0});
  auto pat = render("void brightdata bd 4 noop dist.dat src.cal Dx 0 0", "bd", kSphere, {-1, 1, 0});
  const double dx = 1 / std::sqrt(5.0);
  const double want[3] = {1 + dx, 1 + 3 * dx, 1}; // Dx = dx, -dx, 0
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(pat[i][1] / plain[i][1], want[i], 1e-4) << i;
}

// colorfunc on a light panel facing down: each channel scaled by its own function.
TEST_F(SourcePatterns, ColorfuncOnPanel) {
  const std::string panel = "light lampmat 0 0 3 100 100 100\n"
                            "lampmat polygon lamp 0 0 12 -0.05 -0.05 2 -0.05 0.05 2 0.05 0.05 2 "
                            "0.05 -0.05 2";
  auto plain = render("", "void", panel, {-1, 1});
  auto pat = render("void colorfunc cf 4 red green blue src.cal 0 0", "cf", panel, {-1, 1});
  const double want[2][3] = {{1, 0.5, 0.2}, {1, 0.5, 0.1}};
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < 3; ++c) {
      ASSERT_GT(plain[i][c], 0);
      EXPECT_NEAR(pat[i][c] / plain[i][c], want[i][c], 1e-5) << i << " " << c;
    }
}

// An illum window with a distribution (what mkillum writes): it modulates the light it relays.
TEST_F(SourcePatterns, IllumWithBrightfunc) {
  const std::string window = "illum lampmat 0 0 3 100 100 100\n"
                             "lampmat polygon lamp 0 0 12 -0.05 -0.05 2 -0.05 0.05 2 0.05 0.05 2 "
                             "0.05 -0.05 2";
  auto plain = render("", "void", window, {-1, 1});
  auto pat = render("void brightfunc bf 2 side src.cal 0 0", "bf", window, {-1, 1});
  EXPECT_NEAR(pat[0][0] / plain[0][0], 2.0, 1e-5);
  EXPECT_NEAR(pat[1][0] / plain[1][0], 0.5, 1e-5);
}
