// The anisotropic materials (plastic2, metal2, trans2, ashik2) on the reference scene `aniso`,
// against Radiance 5.4a's stored outputs (tests/data/README.md). Their specular rays are
// random even at -ab 0, with heavy tails (a sample that finds the ground glow or the bulb is
// 30x the rest), so every radcl figure here is the mean over repetitions of the input (each
// repetition draws other numbers), and Radiance's are means where the reference has them.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

#include "golden_draws.h"
#include "golden_scene.h"
#include "radcl/device/context.h"
#include "radcl/image/picture.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/util/error.h"
#include "reference_data.h"
#include "temp_dir.h"
#include "test_env.h"

using namespace radcl;
using namespace radcl::test::golden;
namespace fs = std::filesystem;

namespace {} // namespace

// -ab 0: rays the reference finds noiseless (8 equal runs: they meet no specular lobe, or every
// sample of it sees the same sky) agree to 1e-4, all but a rare few; on the noisy ones radcl's
// mean of 8 lies within 3 standard deviations of Radiance's for 90%, and the whole image's
// light within 2%.
TEST(GoldenAniso, CameraRaysAb0) {
  auto ours = mean_run("aniso.oct", "scenes/aniso_rays.txt", ab0_settings(), 8);
  auto ref = lums("results/aniso_rays_ab0.txt");
  auto sd = lums("results/aniso_rays_ab0_sd.txt");
  ASSERT_EQ(ours.size(), ref.size());
  RayAgreement a = ray_agreement(ours, ref, sd, std::sqrt(1.0 / 8 + 1.0 / 8));
  // One "noiseless" ray (109, on ak_metal) is a rare event: 1 in 5 of Radiance's own runs
  // there finds the ground glow, none of the reference's 8 did.
  EXPECT_GE(a.quiet_ok, a.quiet - 2) << a.quiet << " noiseless rays";
  EXPECT_GE(a.noisy_ok, 0.9 * a.noisy) << a.noisy << " noisy rays";
  EXPECT_NEAR(sum(ours), sum(ref), 0.02 * sum(ref));
}

// -ab 1 -aa 0 -ad 2048 on the camera rays against one Radiance run: the total within 3% and
// the median ray within 1% (the mean of per-ray errors is that one run's noise).
TEST(GoldenAniso, CameraRaysAa0) {
  render::RenderSettings st = aa0_settings();
  auto ours = mean_run("aniso.oct", "scenes/aniso_rays.txt", st, 8);
  auto ref = lums("results/aniso_rays_aa0.txt");
  ASSERT_EQ(ours.size(), ref.size());
  EXPECT_LE(median_error(ours, ref), 0.01);
  EXPECT_NEAR(sum(ours), sum(ref), 0.03 * sum(ref));
}

// The sensors at -ab 1 -aa 0 -ad 4096 against the mean of 4 Radiance runs: mean relative error
// within 3%, 90% within 3 standard deviations of the difference. A run's deviation is the
// larger of the reference's and radcl's own over its 8 repetitions: the reference's comes from
// 4 runs and can be a third of the true one (64 runs of Radiance on sensor 5 give 0.62% where
// the file says 0.23%; those 64 agree with radcl's mean within 0.1%).
TEST(GoldenAniso, GridAb1) {
  render::RenderSettings st = grid_ab1_settings();
  std::vector<double> own;
  auto ours = mean_run("aniso.oct", "scenes/aniso_grid.pts", st, 8, &own);
  auto ref = lums("results/aniso_grid_ab1.txt");
  auto sd = lums("results/aniso_grid_ab1_sd.txt");
  ASSERT_EQ(ours.size(), ref.size());
  double err = 0;
  int within = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    err += std::fabs(ours[i] - ref[i]) / ref[i];
    double s = std::max(sd[i], own[i]);
    within += std::fabs(ours[i] - ref[i]) <= 3.0 * s * std::sqrt(1.0 / 4 + 1.0 / 8);
  }
  EXPECT_LE(err / ref.size(), 0.03);
  EXPECT_GE(within, 0.9 * ref.size());
}

// The default settings with the irradiance cache: no farther from the converged answer
// (Radiance's mean of 30 -aa 0 runs) than Radiance's own default run is. rtrace's default is
// -u+, so a run's error is a draw (Radiance's 12 stored runs: 3.7-5.1%, both programs about
// 4.5% low on average from the cache's interpolation, 20% at the grid's worst sensors): radcl's
// mean error over six seeds against the mean over Radiance's runs, with three standard errors
// of that difference, estimated from the runs themselves, as the noise of the comparison.
TEST(GoldenAniso, GridDefaultNoFartherThanRadiance) {
  auto c = test::default_grid_draws("-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3", "aniso.oct",
                                    "aniso_grid.pts", "aniso_grid_mc5.txt", "aniso_default", 6, 12);
  EXPECT_TRUE(no_farther_than_radiance(c));
}

// rpict's view (four renders averaged) against the mean of 16 Radiance renders: the mean
// within 5%, the 8x-reduced picture within 5% RMS (one render of either program is 5-7%).
TEST(GoldenAniso, ViewMeanAndReducedPicture) {
  const int w = 256, h = 192, reps = 4;
  std::string log;
  auto ours = mean_view("-vf aniso.vf -x 256 -y 192 -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 64 -ps 1",
                        "aniso.oct", reps, w, h, &log);
  ASSERT_FALSE(ours.empty()) << log;
  image::Picture ref = image::read_picture(test::data("results/aniso_view_u16.hdr"));
  ASSERT_EQ(ref.width, w);
  ASSERT_EQ(ref.height, h);
  auto rc = ref.colors();
  double sa = 0, sb = 0, se = 0;
  int blocks = 0;
  for (int by = 0; by < h / 8; ++by)
    for (int bx = 0; bx < w / 8; ++bx) {
      double a = 0, b = 0;
      for (int y = by * 8; y < by * 8 + 8; ++y)
        for (int x = bx * 8; x < bx * 8 + 8; ++x) {
          std::size_t i = std::size_t(y) * w + x;
          a += ours[i];
          b += lum({rc[i][0], rc[i][1], rc[i][2]});
        }
      sa += a;
      sb += b;
      if (b > 0) {
        se += (a - b) * (a - b) / (b * b);
        ++blocks;
      }
    }
  EXPECT_NEAR(sa, sb, 0.05 * sb);
  EXPECT_LE(std::sqrt(se / blocks), 0.05) << blocks << " blocks";
}

// Radiance's refusals, as fatal errors naming the material.
TEST(GoldenAniso, BadArgumentsAreFatal) {
  auto fails = [](const std::string& mat, const std::string& what) {
    const test::TempFolder dir("aniso_bad");
    const fs::path rad = dir / "bad.rad";
    {
      std::FILE* f = std::fopen(rad.c_str(), "w");
      ASSERT_NE(f, nullptr);
      std::fprintf(f, "%s\nm sphere s\n0\n0\n4 0 0 0 1\n", mat.c_str());
      std::fclose(f);
    }
    std::string log;
    int rc = test::run_command(
        "echo '0 0 5 0 0 -1' | " + test::bin_dir() + "/rtrace -h " + rad.string(), &log);
    EXPECT_NE(rc, 0) << mat;
    EXPECT_NE(log.find(what), std::string::npos) << log;
    EXPECT_EQ(log.find("internal error"), std::string::npos) << log;
  };
  fails("void plastic2 m\n4 0 0 1 .\n0\n6 .5 .5 .5 .05 0 .1",
        "plastic2 \"m\": roughness too small");
  fails("void metal2 m\n4 0 0 1 .\n0\n5 .5 .5 .5 .05 .1", "m");
  fails("void ashik2 m\n4 0 0 1 nowhere.cal\n0\n8 .5 .5 .5 .1 .1 .1 10 10", "nowhere.cal");
  fails("void trans2 m\n3 0 0 1\n0\n8 .5 .5 .5 .05 .1 .1 .5 .5", "m");
}
