// Issue 8, case 6: extreme settings give finite values, exit 0 and the right answer where
// there is one. The scene is the reference integrating sphere (radius 1 m, a light sphere of
// radius 0.02 m and radiance 1000 at its centre) with the wall's reflectance raised to 0.95:
// the wall irradiance after N bounces is exactly Ed (1 - rho^(N+1)) / (1 - rho) with
// Ed = pi L (r/R)^2, which converges slowly (25.1 W/m2 after infinitely many bounces). Runs
// the built rtrace with -I on six of the reference wall sensors, seeded through RADCL_SEED.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "reference_data.h"
#include "temp_dir.h"
#include "test_env.h"

using radcl::test::run_command;

namespace {

constexpr double kRho = 0.95;
const double kEd = M_PI * 1000 * 0.02 * 0.02;

double exact(int bounces) {
  return kEd * (1 - std::pow(kRho, bounces + 1)) / (1 - kRho);
}

class StabilityExtremeSettings : public radcl::test::TempDir {
protected:
  void SetUp() override {
    TempDir::SetUp();
    std::ofstream(dir / "sphere95.rad") << "void plastic wall\n0\n0\n5 0.95 0.95 0.95 0 0\n"
                                        << "void light emitter\n0\n0\n3 1000 1000 1000\n"
                                        << "wall bubble shell\n0\n0\n4 0 0 0 1\n"
                                        << "emitter sphere lamp\n0\n0\n4 0 0 0 0.02\n";
    std::ofstream pts(dir / "wall.pts");
    auto rays = radcl::test::read_rays(radcl::test::data("scenes/sphere_wall.pts"));
    for (std::size_t i = 0; i < 6; ++i)
      pts << rays[i * 4][0] << " " << rays[i * 4][1] << " " << rays[i * 4][2] << " "
          << rays[i * 4][3] << " " << rays[i * 4][4] << " " << rays[i * 4][5] << "\n";
  }

  // rtrace -I's first channel per sensor (the scene is grey); every value finite, exit 0.
  std::vector<double> run(const std::string& opts, unsigned seed = 1) {
    std::string out = (dir / "out.txt").string(), log;
    std::string cmd = "cd " + dir.string() + " && RADCL_SEED=" + std::to_string(seed) + " " +
                      radcl::test::bin_dir() + "/rtrace -h -I -u+ " + opts +
                      " sphere95.rad < wall.pts > " + out;
    EXPECT_EQ(run_command(cmd, &log), 0) << cmd << "\n" << log;
    std::vector<double> v;
    for (const auto& row : radcl::test::read_table(out)) {
      EXPECT_EQ(row.size(), 3u);
      for (double y : row)
        EXPECT_TRUE(std::isfinite(y)) << opts;
      if (!row.empty()) v.push_back(row[0]);
    }
    EXPECT_EQ(v.size(), 6u) << opts;
    return v;
  }

  // Mean relative error within `mean_tol` and RMS relative error within `rms_tol` of `want`.
  static void expect_near(const std::vector<double>& v, double want, double mean_tol,
                          double rms_tol, const std::string& what) {
    double mean = 0, rms = 0;
    for (double y : v) {
      mean += (y - want) / want / v.size();
      rms += (y - want) * (y - want) / (want * want) / v.size();
    }
    rms = std::sqrt(rms);
    std::printf("%s: mean %+.4f rms %.4f (exact %.4f)\n", what.c_str(), mean, rms, want);
    EXPECT_LE(std::fabs(mean), mean_tol) << what << ": mean " << mean << " (exact " << want << ")";
    EXPECT_LE(rms, rms_tol) << what << ": rms " << rms;
  }
};

} // namespace

// -ab 20 -lw 1e-9 with rtrace's default -lr -10: Russian roulette below the weight limit, and
// no ray past 10 reflections, so ten bounces count. Measured: mean -0.33%, RMS 0.66% of
// exact(10).
TEST_F(StabilityExtremeSettings, TwentyBouncesTinyWeightDefaultLimit) {
  expect_near(run("-ab 20 -lw 1e-9 -aa 0 -ad 16"), exact(10), 0.02, 0.05, "-lr -10");
}

// -lr 0 (roulette with no depth limit) and -lr -1000 (a limit never reached): all twenty
// bounces. Measured: mean -0.76%, RMS 1.2% of exact(20), for both.
TEST_F(StabilityExtremeSettings, TwentyBouncesRouletteWithoutLimit) {
  expect_near(run("-ab 20 -lw 1e-9 -lr 0 -aa 0 -ad 16"), exact(20), 0.02, 0.05, "-lr 0");
  expect_near(run("-ab 20 -lw 1e-9 -lr -1000 -aa 0 -ad 16"), exact(20), 0.02, 0.05, "-lr -1000");
}

// A weight limit that bites. With roulette (-lr 0) the light of the rays it kills is carried by
// the survivors, so the answer stays exact(20). With a depth limit instead (-lr 30), rays below
// -lw are not traced, and Radiance's rule for -aa 0 (a hemisphere's weight is first cut to
// 0.8 max(coef) rweight / (ad lw), then n = floor(sqrt(ad w) + 0.5) divisions a side) fixes how
// many bounces count. The -I meter is Radiance's Lambertian of reflectance pi:
// - -ad 64 -lw 0.02: 8 x 8 samples of weight pi/64 = 0.049, then one sample a hemisphere, each
//   bounce x 0.95, above 0.02 for 18 bounces: exact(18).
// - -ad 16 -lw 0.05: 4 x 4 samples of weight 0.196; the next hemisphere's cut weight 0.187
//   rounds up to 2 x 2 divisions, samples of weight 0.047 < 0.05: one bounce, exact(1).
// Measured: mean -0.02%, RMS 0.16% of exact(20); -0.07% of exact(18); +0.11% of exact(1).
TEST_F(StabilityExtremeSettings, RouletteUnbiasedWeightLimitNot) {
  expect_near(run("-ab 20 -lw 0.02 -lr 0 -aa 0 -ad 64"), exact(20), 0.02, 0.05, "-lw 0.02 -lr 0");
  expect_near(run("-ab 20 -lw 0.02 -lr 30 -aa 0 -ad 64"), exact(18), 0.01, 0.02, "-lw 0.02 -lr 30");
  expect_near(run("-ab 20 -lw 0.05 -lr 30 -aa 0 -ad 16"), exact(1), 0.01, 0.02, "-lw 0.05 -lr 30");
}

// The same with the irradiance cache (records at every one of the 20 levels). Measured: mean
// +0.07%, RMS 0.08% of exact(20), 13 s.
TEST_F(StabilityExtremeSettings, TwentyBouncesRouletteWithCache) {
  expect_near(run("-ab 20 -lw 1e-9 -lr 0 -aa 0.2 -ad 16 -as 0"), exact(20), 0.02, 0.05,
              "-lr 0 -aa 0.2");
}

// -lr 0 needs a positive -lw: Radiance stops with "zero ray weight in Russian roulette".
TEST_F(StabilityExtremeSettings, RouletteWithZeroWeightIsFatal) {
  for (const std::string prog : {"rtrace -h -I -ab 2 -aa 0", "rpict -x 8 -y 8 -vp 0 0 0"}) {
    std::string log;
    std::string cmd = "(cd " + dir.string() + " && " + radcl::test::bin_dir() + "/" + prog +
                      " -lr 0 -lw 0 sphere95.rad < wall.pts > out.bin)";
    EXPECT_NE(run_command(cmd, &log), 0) << cmd;
    EXPECT_NE(log.find("fatal - zero ray weight in Russian roulette"), std::string::npos) << log;
  }
  // -lr > 0 with -lw 0 is fine: only the depth limit applies (measured: mean +0.11%).
  expect_near(run("-ab 1 -lr 1 -lw 0 -aa 0 -ad 256"), exact(1), 0.03, 0.08, "-lr 1 -lw 0");
}

// -ad 1: one sample per hemisphere without the cache (an unbiased, noisy estimate), Radiance's
// minimum of 7x7 divisions with it. -ad 0: no ambient computation, the -av constant (0):
// direct light only. Measured: -ab 2 mean +0.08% (-aa 0), +0.06% (-aa 0.1); -ad 0 +0.22%.
// (The sphere's wall is uniformly bright, so a hemisphere's samples barely vary: this checks
// bias, not noise.)
TEST_F(StabilityExtremeSettings, OneAndZeroDivisions) {
  expect_near(run("-ab 2 -ad 1 -aa 0"), exact(2), 0.03, 0.08, "-ad 1 -aa 0");
  expect_near(run("-ab 2 -ad 1 -aa 0.1"), exact(2), 0.03, 0.08, "-ad 1 -aa 0.1");
  expect_near(run("-ab 2 -ad 0 -aa 0"), exact(0), 0.01, 0.02, "-ad 0");
}

// -ad 65536: 256 x 256 strata per hemisphere. Measured: mean +0.11% (-aa 0), +0.09% (cache).
TEST_F(StabilityExtremeSettings, ManyDivisions) {
  expect_near(run("-ab 1 -ad 65536 -aa 0"), exact(1), 0.005, 0.01, "-ad 65536 -aa 0");
  expect_near(run("-ab 1 -ad 65536 -aa 0.1 -as 0"), exact(1), 0.005, 0.01, "-ad 65536 -aa 0.1");
}

// -aa 0.001: records cover almost nothing, nearly every point makes its own.
// Measured: -ab 1 mean +0.11%, -ab 2 mean +0.07%.
TEST_F(StabilityExtremeSettings, TinyAccuracy) {
  expect_near(run("-ab 1 -aa 0.001 -ad 256"), exact(1), 0.02, 0.05, "-aa 0.001 -ab 1");
  expect_near(run("-ab 2 -aa 0.001 -ad 64 -as 0"), exact(2), 0.02, 0.05, "-aa 0.001 -ab 2");
}
