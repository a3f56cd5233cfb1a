// -dt/-dc: testing only the strongest source samples and estimating the rest must stay close to
// testing every one (-dt 0) while tracing fewer shadow rays.
#include <cmath>
#include <gtest/gtest.h>
#include <unistd.h>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "reference_data.h"
#include "test_env.h"

using namespace radcl;

namespace {

struct Lit {
  std::vector<double> lux;
  std::uint64_t shadow_rays = 0;
};

Lit luminaires(double dt, double dc) {
  std::string dir = test::data("scenes");
  char cwd[4096];
  EXPECT_NE(getcwd(cwd, sizeof cwd), nullptr);
  EXPECT_EQ(chdir(dir.c_str()), 0);
  scene::LoadedScene ls = scene::load_scene({"luminaires.oct"});
  render::RenderSettings st;
  st.ab = 0;
  st.dj = 0;
  st.ds = 0.01;
  st.dt = dt;
  st.dc = dc;
  st.irradiance_I = true;
  render::Renderer r(ls, st, device::default_context());
  std::vector<render::PrimaryRay> rays;
  for (const auto& s : test::read_rays(test::data("scenes/luminaires_grid.pts")))
    rays.push_back({{s[0], s[1], s[2]}, {s[3], s[4], s[5]}, 0});
  std::vector<render::PrimaryResult> res(rays.size());
  r.render(rays, res);
  EXPECT_EQ(chdir(cwd), 0);
  Lit out;
  for (const auto& p : res)
    out.lux.push_back(test::lux(p.value));
  out.shadow_rays = r.stats().shadow;
  return out;
}

} // namespace

TEST(DirectThreshold, EstimatesCloseToTestingEverySample) {
  Lit all = luminaires(0, 1);
  Lit sel = luminaires(0.03, 0.75);
  ASSERT_EQ(all.lux.size(), sel.lux.size());
  double sa = 0, ss = 0, maxdiff = 0, maxlux = 0;
  for (std::size_t i = 0; i < all.lux.size(); ++i) {
    sa += all.lux[i];
    ss += sel.lux[i];
    maxlux = std::max(maxlux, all.lux[i]);
  }
  for (std::size_t i = 0; i < all.lux.size(); ++i)
    maxdiff = std::max(maxdiff, std::fabs(sel.lux[i] - all.lux[i]) / maxlux);
  std::printf("mean %g lux (-dt 0) vs %g lux (-dt 0.03 -dc 0.75), largest point difference %.2f%% "
              "of the peak; shadow rays %llu vs %llu\n",
              sa / all.lux.size(), ss / sel.lux.size(), 100 * maxdiff,
              static_cast<unsigned long long>(all.shadow_rays),
              static_cast<unsigned long long>(sel.shadow_rays));
  EXPECT_NEAR(ss, sa, 0.03 * sa);
  EXPECT_LT(maxdiff, 0.10);
  EXPECT_LT(sel.shadow_rays, all.shadow_rays);
}

TEST(DirectThreshold, ZeroThresholdTestsEverySample) {
  Lit a = luminaires(0, 1), b = luminaires(0, 0.5);
  EXPECT_EQ(a.lux, b.lux); // -dc has no effect without a threshold
  EXPECT_EQ(a.shadow_rays, b.shadow_rays);
}
