// mist objects on the reference scene `mist` (tests/data/README.md): a closed dark room lit by two
// spotlights and a low sun through a window, with three mist volumes — a box filling most of the
// room (7 real arguments, source list `sun`), a cone around spotlight A's beam (no real
// arguments, list `spot_a`) and a denser ball inside the box (extinction only, list `spot_b`).
// Every run adds -ms 0.05 (one in-scattering sample per 5 cm and listed source, at most 16), as
// the reference's did. The camera and sensors lie outside every volume.
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <string>

#include "golden_draws.h"
#include "golden_scene.h"
#include "test_env.h"

using namespace radcl;
using namespace radcl::test::golden;

namespace {

render::RenderSettings with_ms(render::RenderSettings st) {
  st.ms = 0.05;
  return st;
}

// -ab 0 camera rays (one radcl run) against the mean of Radiance's 8 runs: the rays the
// reference finds noiseless agree to 1e-4, but for `quiet_misses` of them; 90% within 3
// standard deviations; the whole within 2%.
void check_ab0(const std::vector<double>& ours, const std::vector<double>& ref,
               const std::vector<double>& sd, int quiet_misses) {
  ASSERT_EQ(ours.size(), ref.size());
  int quiet = 0, quiet_ok = 0, within = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    double d = std::fabs(ours[i] - ref[i]);
    if (sd[i] == 0) {
      ++quiet;
      quiet_ok += d <= 1e-4 * std::fabs(ref[i]) + 1e-9;
    }
    within += d <= 3.0 * sd[i] * std::sqrt(1.0 + 1.0 / 8) + 1e-4 * std::fabs(ref[i]) + 1e-9;
  }
  EXPECT_GE(quiet_ok, quiet - quiet_misses) << quiet << " noiseless rays";
  EXPECT_GE(within, 0.9 * ref.size());
  EXPECT_NEAR(sum(ours), sum(ref), 0.02 * sum(ref));
}

} // namespace

// The beams and the sun shaft are seen where they cross the mists.
TEST(GoldenMist, CameraRaysAb0) {
  auto ours = mean_run("mist.oct", "scenes/mist_rays.txt", with_ms(ab0_settings()), 1);
  check_ab0(ours, lums("results/mist_rays_ab0.txt"), lums("results/mist_rays_ab0_sd.txt"), 0);
}

// The same in a global medium as well (-me .03 .03 .04 -ma .8 .8 .8 -mg .3): the mists add to
// its extinction, the box's albedo and g replace the global ones inside it, leaving restores
// them. Two noiseless rays may miss, as in golden_medium: a floor point on the edge of spotlight
// A's cone, where Radiance's source partition decides.
TEST(GoldenMist, CameraRaysAb0InGlobalMedium) {
  render::RenderSettings st = with_ms(ab0_settings());
  st.me = {0.03, 0.03, 0.04};
  st.ma = {0.8, 0.8, 0.8};
  st.mg = 0.3;
  auto ours = mean_run("mist.oct", "scenes/mist_rays.txt", st, 1);
  check_ab0(ours, lums("results/mist_me_rays_ab0.txt"), lums("results/mist_me_rays_ab0_sd.txt"), 2);
}

// -ab 1 -aa 0 -ad 2048 on the camera rays against one Radiance run: the total within 3%.
TEST(GoldenMist, CameraRaysAa0) {
  auto ours = mean_run("mist.oct", "scenes/mist_rays.txt", with_ms(aa0_settings()), 2);
  auto ref = lums("results/mist_rays_aa0.txt");
  ASSERT_EQ(ours.size(), ref.size());
  EXPECT_NEAR(sum(ours), sum(ref), 0.03 * sum(ref));
}

// The sensors at -ab 1 -aa 0 -ad 4096 against the mean of 4 Radiance runs: the total within 3%,
// 90% within 3 standard deviations of the difference.
TEST(GoldenMist, GridAb1) {
  std::vector<double> own;
  auto ours = mean_run("mist.oct", "scenes/mist_grid.pts", with_ms(grid_ab1_settings()), 8, &own);
  auto ref = lums("results/mist_grid_ab1.txt");
  auto sd = lums("results/mist_grid_ab1_sd.txt");
  ASSERT_EQ(ours.size(), ref.size());
  int within = 0;
  for (std::size_t i = 0; i < ref.size(); ++i)
    within +=
        std::fabs(ours[i] - ref[i]) <= 3.0 * std::sqrt(sd[i] * sd[i] / 4 + own[i] * own[i] / 8);
  EXPECT_GE(within, 0.9 * ref.size());
  EXPECT_NEAR(sum(ours), sum(ref), 0.03 * sum(ref));
}

// The default settings with the irradiance cache against the converged answer (the mean of 30
// Radiance runs at -ab 5 -aa 0): radcl's mean error over four seeds no farther than the mean over
// Radiance's 12 default runs, with three standard errors of the difference as the noise.
TEST(GoldenMist, GridDefaultNoFartherThanRadiance) {
  auto c = test::default_grid_draws("-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3 -ms 0.05",
                                    "mist.oct", "mist_grid.pts", "mist_grid_mc5.txt",
                                    "mist_default", 4, 12);
  EXPECT_TRUE(no_farther_than_radiance(c));
}

// rpict's view (two renders averaged) against the mean of 16 Radiance renders: the mean within
// 5%, the 8x-reduced picture within 5% RMS on the blocks the reference knows to 2%.
TEST(GoldenMist, ViewMeanAndReducedPicture) {
  auto st =
      view_against_radiance("-vf mist.vf -x 256 -y 192 -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 64 -ps 1 "
                            "-ms 0.05",
                            "mist.oct", 2, "mist_view_u16");
  ASSERT_TRUE(st.ok) << st.log;
  EXPECT_NEAR(st.mean_ratio, 1.0, 0.05);
  EXPECT_GE(st.blocks, 0.75 * st.lit);
  EXPECT_LE(st.rms, 0.05);
}
