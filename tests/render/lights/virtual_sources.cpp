// Virtual light sources: a mirror relays a light to a point that cannot see it directly; the
// point's irradiance must be the mirror's reflectance times the irradiance from the light's
// mirror image.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "temp_dir.h"

using namespace radcl;

namespace {

constexpr double kRefl = 0.9;

// A mirror in the plane x = 1 facing -x, a sensor at P facing up whose direct view of the light
// (upper left) a black plate blocks while the way through the mirror (upper right) is open.
const std::string kRoom = "void mirror glass_mirror 0 0 3 0.9 0.9 0.9\n"
                          "glass_mirror polygon mirror 0 0 12  1 2 0  1 -2 0  1 -2 4  1 2 4\n"
                          "void plastic black 0 0 5 0 0 0 0 0\n"
                          "black polygon plate 0 0 12  0.1 -0.5 0.3  0.45 -0.5 0.3  "
                          "0.45 0.5 0.3  0.1 0.5 0.3\n"
                          "void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
                          "grey polygon floor 0 0 12  -3 -3 0  3 -3 0  3 3 0  -3 3 0\n";
const std::array<double, 3> kP{0.5, 0, 0};

struct Scene {
  explicit Scene(const std::string& light, const std::string& more = "") {
    std::ofstream(path) << light << kRoom << more;
  }
  // Irradiance at the sensor (green) and the renderer's shadow-ray count.
  std::pair<double, std::uint64_t> irradiance(int dr, int dp = 512) {
    scene::LoadedScene ls = scene::load_scene({path});
    render::RenderSettings st;
    st.ab = 0;
    st.dr = dr;
    st.dp = dp;
    st.irradiance_I = true;
    render::Renderer r(ls, st, device::default_context());
    render::PrimaryRay ray{kP, {0, 0, 1}, 0};
    std::vector<render::PrimaryResult> res(1);
    r.render(std::span(&ray, 1), res);
    return {res[0].value[1], r.stats().shadow};
  }
  radcl::test::TempFolder dir{"virtual_sources"};
  std::string path = (dir / "s.rad").string();
};

} // namespace

TEST(VirtualSources, MirrorRelaysALocalLight) {
  // A sphere light at (-0.3, 0, 1.5): its image is at (2.3, 0, 1.5).
  const double L = 100, r = 0.05;
  Scene s("void light bulb 0 0 3 100 100 100\nbulb sphere lamp 0 0 4 -0.3 0 1.5 0.05\n");
  const double z = 1e-4; // where the -I meter sits
  const double dx = 2.3 - kP[0], dz = 1.5 - z, d2 = dx * dx + dz * dz;
  // A uniform sphere above the horizon lights a point as a point source at its centre.
  const double expect = kRefl * L * M_PI * r * r / d2 * (dz / std::sqrt(d2));
  EXPECT_NEAR(s.irradiance(2).first, expect, 1e-3 * expect);
  EXPECT_NEAR(s.irradiance(2, 0).first, expect, 1e-3 * expect); // no pretest: always followed
  EXPECT_EQ(s.irradiance(0).first, 0);                          // -dr 0: no virtual sources
}

TEST(VirtualSources, MirrorRelaysTheSun) {
  // Sun towards (-1, 0, 1): the mirror sends it down along (-1, 0, -1), so the sensor sees the
  // sun's image in direction (1, 0, 1).
  const double L = 1e6, angle = 0.5;
  Scene s("void light solar 0 0 3 1e6 1e6 1e6\nsolar source sun 0 0 4 -1 0 1 0.5\n");
  const double omega = 2 * M_PI * (1 - std::cos(angle * M_PI / 360));
  const double expect = kRefl * L * omega * std::sqrt(0.5);
  EXPECT_NEAR(s.irradiance(1).first, expect, 1e-3 * expect);
  EXPECT_EQ(s.irradiance(0).first, 0);
}

TEST(VirtualSources, BlockedMirrorMakesNoSource) {
  // A wall in front of the whole mirror: the pretest finds the light never reaches it, so no
  // virtual source is made and no shadow rays are spent on it.
  Scene s("void light bulb 0 0 3 100 100 100\nbulb sphere lamp 0 0 4 -0.3 0 1.5 0.05\n",
          "black polygon wall 0 0 12  0.9 -3 0  0.9 3 0  0.9 3 5  0.9 -3 5\n");
  auto [with, rays_with] = s.irradiance(2);
  auto [without, rays_without] = s.irradiance(0);
  EXPECT_EQ(with, 0);
  EXPECT_EQ(without, 0);
  EXPECT_EQ(rays_with, rays_without);
}
