// rcontrib against Radiance's own rcontrib on office_clear's room (tests/data/rcontrib, made by
// its make_reference.sh): a direct-sun matrix of six suns with -M (deterministic: every number
// within float rounding), and daylight coefficients of a unit sky dome in Reinhart's MF:1 and
// MF:2 bins, where each bin's mean over independent radcl runs must lie within the combined
// noise of both sides' means. And the check that needs no Radiance: the -V+ contributions of
// every bin add up to rtrace's value for the same rays and seed. And the command line Radiance's
// rfluxmtx makes for a view matrix to the window in Klems' full basis, run unchanged on the
// octree it would build (given as a command, as rfluxmtx gives it).
#include <cmath>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "reference_data.h"
#include "run_program.h"
#include "test_env.h"

namespace {

using Rows = std::vector<std::vector<double>>;
namespace t = radcl::test;

Rows numbers(const std::string& text) {
  return t::parse_table(text);
}

std::string sensors() {
  return t::read_file(t::data("rcontrib/office_sensors12.pts"));
}

Rows run(const std::string& program, const std::string& args, int seed = 1,
         const std::string& input = sensors()) {
  const t::ProgramRun r = t::Program(program)
                              .env("RADCL_SEED=" + std::to_string(seed) + " ")
                              .input(input)
                              .run("-n 2 " + args);
  EXPECT_EQ(r.rc, 0) << r.err;
  return numbers(r.out);
}

// Mean and standard error over independent runs (seeds 1..k).
void draws(const std::string& args, int k, Rows& mean, Rows& se,
           const std::string& input = sensors()) {
  std::vector<Rows> runs;
  for (int s = 1; s <= k; ++s)
    runs.push_back(run("rcontrib", args, s, input));
  mean = se = runs[0];
  for (std::size_t i = 0; i < mean.size(); ++i)
    for (std::size_t j = 0; j < mean[i].size(); ++j) {
      double s = 0, q = 0;
      for (const Rows& r : runs) {
        s += r[i][j];
        q += r[i][j] * r[i][j];
      }
      const double m = s / k;
      mean[i][j] = m;
      se[i][j] = std::sqrt(std::max(0.0, (q - k * m * m) / (k - 1)) / k);
    }
}

// Every bin within the combined noise: at most 3% of the numbers beyond 3 standard errors and
// none beyond 6; each sensor's sum over the bins within 3.5. A bin that few samples reach has
// a nearly fixed count in a stratified hemisphere (Radiance's 8 runs may all put exactly one
// sample in it), so the spread of a few runs underrates its error; each side's error is at
// least that of independent samples, whose variance per run is at most the largest single
// sample's contribution (`quantum`: pi/-ad of a unit sky) times the bin's mean. Stratification
// only lowers the variance, so this bound holds for both renderers.
void expect_within_noise(const Rows& m, const Rows& se, int k, const Rows& rm, const Rows& rse,
                         int rk, double quantum) {
  ASSERT_EQ(m.size(), rm.size());
  std::size_t n = 0, over3 = 0;
  double worst = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    ASSERT_EQ(m[i].size(), rm[i].size()) << i;
    double sum = 0, rsum = 0, var = 0;
    for (std::size_t j = 0; j < m[i].size(); ++j) {
      sum += m[i][j];
      rsum += rm[i][j];
      const double v = std::max(se[i][j] * se[i][j], quantum * std::fabs(m[i][j]) / k) +
                       std::max(rse[i][j] * rse[i][j], quantum * std::fabs(rm[i][j]) / rk);
      var += v;
      if (v <= 0) {
        // No spread on either side: a fixed coefficient (a pixel seeing the sky through glass).
        EXPECT_NEAR(m[i][j], rm[i][j], 1e-5 * std::fabs(rm[i][j]) + 1e-9)
            << "sensor " << i << " number " << j;
        continue;
      }
      const double z = std::fabs(m[i][j] - rm[i][j]) / std::sqrt(v);
      ++n;
      over3 += z > 3;
      worst = std::max(worst, z);
    }
    EXPECT_LE(std::fabs(sum - rsum), 3.5 * std::sqrt(var))
        << "sensor " << i << ": " << sum << " against " << rsum;
  }
  ASSERT_GT(n, 50u);
  EXPECT_LE(over3, n * 3 / 100) << "of " << n;
  EXPECT_LE(worst, 6.0);
}

const std::string kDome = " -f reinhart.cal -b rbin -bn Nrbins -m skyglow office_dome.oct";

} // namespace

TEST(GoldenRcontrib, SunMatrixIsRadiances) {
  const Rows r =
      run("rcontrib", "-h -I -ab 0 -dc 1 -dt 0 -dj 0 -M office_suns.mod office_suns.oct");
  const Rows ref = numbers(t::read_file(t::data("rcontrib/suns_radiance.txt")));
  ASSERT_EQ(r.size(), 12u);
  ASSERT_EQ(r.size(), ref.size());
  std::size_t lit = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    ASSERT_EQ(r[i].size(), 18u);
    for (std::size_t j = 0; j < r[i].size(); ++j) {
      EXPECT_NEAR(r[i][j], ref[i][j], 1e-4 * ref[i][j] + 1e-12) << i << " " << j;
      lit += ref[i][j] > 0;
    }
  }
  EXPECT_GT(lit, 30u); // the window lets some suns in at most sensors
}

TEST(GoldenRcontrib, DomeReinhartMF1WithinNoise) {
  Rows m, se;
  draws("-h -I -ab 1 -ad 2048 -lw 1e-5 -e MF:1" + kDome, 4, m, se);
  expect_within_noise(m, se, 4, numbers(t::read_file(t::data("rcontrib/dome_mf1_mean.txt"))),
                      numbers(t::read_file(t::data("rcontrib/dome_mf1_se.txt"))), 8, M_PI / 2048);
  ASSERT_EQ(m[0].size(), 146u * 3);
}

TEST(GoldenRcontrib, DomeReinhartMF2WithinNoise) {
  Rows m, se;
  draws("-h -I -ab 2 -ad 512 -lw 1e-5 -e MF:2" + kDome, 4, m, se);
  expect_within_noise(m, se, 4, numbers(t::read_file(t::data("rcontrib/dome_mf2_mean.txt"))),
                      numbers(t::read_file(t::data("rcontrib/dome_mf2_se.txt"))), 8, M_PI / 512);
  ASSERT_EQ(m[0].size(), 578u * 3);
}

// The bins split rtrace's value: the same rays, shaded the same way, added per bin.
TEST(GoldenRcontrib, BinsAddUpToRtrace) {
  const std::string o = "-h -u- -I -ab 2 -ad 256 -lw 1e-5 -dj 0 -st .02 -dt 0 -aa 0 -as 0 -dr 3 ";
  const Rows v = run("rtrace", o + "office_dome.oct");
  const Rows c = run("rcontrib", o + "-V+ -e MF:1" + kDome);
  ASSERT_EQ(v.size(), 12u);
  ASSERT_EQ(c.size(), 12u);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      double sum = 0;
      for (std::size_t j = ch; j < c[i].size(); j += 3)
        sum += c[i][j];
      EXPECT_NEAR(sum, v[i][ch], 1e-5 * v[i][ch] + 1e-9) << i;
      EXPECT_GT(v[i][ch], 0) << i;
    }
}

// rfluxmtx -v -ab 1 -ad 2048 -lw 1e-4 -I - office_window_kf.rad -i office_open.oct prints this
// command; its octree argument '!oconv -f -i office_open.oct office_window_kf.rad' is stored as
// office_vmx.oct, read here through a command as rfluxmtx passes it.
TEST(GoldenRcontrib, RfluxmtxViewMatrixWithinNoise) {
  const std::string cmd = "-fo+ -ab 1 -ad 2048 -lw 1e-4 -I -faa -c 1 -f klems_full.cal -p RHS=+1 "
                          "-bn Nkbins -b 'kbin(0,1,0,0,0,1)' -m windowglow '!cat office_vmx.oct'";
  const t::ProgramRun r = t::Program("rcontrib").input(sensors()).run(cmd);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("NCOLS=145\n"), std::string::npos) << r.out.substr(0, 600);
  EXPECT_NE(r.out.find("FORMAT=ascii\n"), std::string::npos);
  Rows m, se;
  draws("-h " + cmd, 4, m, se);
  ASSERT_EQ(m.size(), 12u);
  ASSERT_EQ(m[0].size(), 145u * 3);
  expect_within_noise(m, se, 4, numbers(t::read_file(t::data("rcontrib/vmx_kf_mean.txt"))),
                      numbers(t::read_file(t::data("rcontrib/vmx_kf_se.txt"))), 8, M_PI / 2048);
}

// Per-pixel contributions: a 16 x 12 view's rays (vwrays -ff, stored), -x -y with its header
// and resolution string, each pixel's sky coefficient within the noise of Radiance's.
TEST(GoldenRcontrib, PictureOfSkyCoefficientsWithinNoise) {
  const std::string rays = t::read_file(t::data("rcontrib/office_view_rays.f32"));
  const std::string args =
      "-ffa -x 16 -y 12 -ld- -ab 1 -ad 256 -lw 1e-4 -m skyglow office_dome.oct";
  const t::ProgramRun r = t::Program("rcontrib").input(rays).run(args);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("NROWS=192\nFORMAT=ascii\n\n-Y 12 +X 16\n"), std::string::npos)
      << r.out.substr(0, 500);
  Rows m, se;
  draws("-h " + args, 4, m, se, rays);
  ASSERT_EQ(m.size(), 192u);
  // A wall's sample adds at most its reflectance (< 1) over -ad.
  expect_within_noise(m, se, 4, numbers(t::read_file(t::data("rcontrib/view_sky_mean.txt"))),
                      numbers(t::read_file(t::data("rcontrib/view_sky_se.txt"))), 8, 1.0 / 256);
}
