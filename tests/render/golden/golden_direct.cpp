// Direct light (-ab 0), deterministic settings, against Radiance 5.4a's stored outputs and the
// integrating sphere's exact answer.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "reference_data.h"
#include "test_env.h"

using namespace radcl;

namespace {

// Runs the sensors of `pts` through `scene_file` in -I mode with Radiance's -ab 0 settings.
std::vector<std::array<double, 3>> irradiance(const std::string& scene_file, const std::string& pts,
                                              double ds) {
  std::string dir = test::data("scenes");
  char cwd[4096];
  EXPECT_NE(getcwd(cwd, sizeof cwd), nullptr);
  EXPECT_EQ(chdir(dir.c_str()), 0);
  scene::LoadedScene ls = scene::load_scene({scene_file});
  render::RenderSettings st;
  st.ab = 0;
  st.dj = 0;
  st.ds = ds;
  st.dt = 0;
  st.dc = 1;
  st.irradiance_I = true;
  render::Renderer r(ls, st, device::default_context());
  std::vector<render::PrimaryRay> rays;
  for (const auto& s : test::read_rays(pts))
    rays.push_back({{s[0], s[1], s[2]}, {s[3], s[4], s[5]}, 0});
  std::vector<render::PrimaryResult> res(rays.size());
  r.render(rays, res);
  EXPECT_EQ(chdir(cwd), 0);
  std::vector<std::array<double, 3>> out;
  for (const auto& p : res)
    out.push_back(p.value);
  return out;
}

} // namespace

TEST(GoldenDirect, LuminairesAb0WithinOnePercent) {
  auto ours = irradiance("luminaires.oct", test::data("scenes/luminaires_grid.pts"), 0.01);
  auto ref = test::read_rgb(test::data("results/luminaires_ab0.txt"));
  ASSERT_EQ(ours.size(), ref.size());
  double maxlux = 0;
  for (const auto& r : ref)
    maxlux = std::max(maxlux, test::lux(r));
  int bad = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    double a = test::lux(ours[i]), b = test::lux(ref[i]);
    // Points in shadow compare against the grid's largest value (issue 4's rule).
    double scale = std::max(b, 0.05 * maxlux);
    double err = std::fabs(a - b) / scale;
    if (err > 0.01) ++bad;
    EXPECT_LE(err, 0.01) << "sensor " << i << ": radcl " << a << " lux, Radiance " << b;
  }
  EXPECT_EQ(bad, 0);
}

TEST(GoldenDirect, IntegratingSphereAb0IsExact) {
  auto ours = irradiance("sphere.oct", test::data("scenes/sphere_wall.pts"), 0.02);
  double exact = test::read_table(test::data("results/sphere_exact.txt"))[0][1];
  double mean = 0;
  for (const auto& v : ours)
    mean += v[0] / ours.size();
  EXPECT_NEAR(mean, exact, 0.005 * exact);
  for (const auto& v : ours)
    EXPECT_NEAR(v[0], exact, 0.01 * exact);
}
