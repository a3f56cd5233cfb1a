// mist volumes on small scenes whose answers are known exactly: a furnace (a bubble of uniform
// glow) where a scattering-only mist neither makes nor loses light, the medium a ray that
// starts inside a mist learns on leaving it (as Radiance's), and the sun scattered into a ray
// crossing a slab of mist, against the single-scattering integral.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

using Rgb = std::array<double, 3>;

namespace {

struct Traced {
  int rc = 0;
  std::string log; // stdout and stderr
  std::vector<Rgb> values;
};

// rtrace -h <options> on scene text `rad` with the ray lines `rays`.
Traced rtrace(const std::string& rad, const std::string& rays, const std::string& options) {
  const radcl::test::TempFolder dir("mist");
  radcl::test::write_file(dir / "s.rad", rad);
  Traced r;
  const radcl::test::ProgramRun run =
      radcl::test::Program("rtrace").input(rays).in(dir.str()).merge_err().run("-h " + options +
                                                                               " s.rad");
  r.rc = run.rc;
  r.log = run.out;
  std::istringstream in(r.log);
  for (std::string line; std::getline(in, line);) { // the values, not the messages
    std::istringstream l(line);
    Rgb c;
    if (l >> c[0] >> c[1] >> c[2]) r.values.push_back(c);
  }
  return r;
}

// A bubble of radius 10 glowing .3 .5 .7, a mist ball of radius 1 at the origin made of `mist`
// (its material line's arguments), and a sun outside that the bubble hides.
std::string furnace(const std::string& mist) {
  return "void glow g\n0\n0\n4 .3 .5 .7 0\ng bubble b\n0\n0\n4 0 0 0 10\n"
         "void light solar\n0\n0\n3 1e6 1e6 1e6\nsolar source sun\n0\n0\n4 0 0 1 0.5\n"
         "void mist m\n" +
         mist + "\nm sphere ball\n0\n0\n4 0 0 0 1\n";
}

} // namespace

// With -av equal to the glow and albedo 1, every ray brings back the glow whatever extinction it
// crosses: through the ball, starting inside it, missing it.
TEST(MistMedia, AlbedoOneNeitherMakesNorLosesLight) {
  const std::string rays = "-5 0 0 1 0 0\n-5 0.5 0.3 1 0 0\n0 0 0 0 0 1\n-5 3 0 1 0 0\n";
  for (const char* ext : {"0.1 0.2 0.3", "2 2 2"}) {
    Traced r = rtrace(furnace("1 sun\n0\n7 " + std::string(ext) + " 1 1 1 0.5"), rays,
                      "-ab 0 -av .3 .5 .7 -ms 0.1");
    ASSERT_EQ(r.rc, 0) << r.log;
    ASSERT_EQ(r.values.size(), 4u) << r.log;
    for (const Rgb& c : r.values) {
      EXPECT_NEAR(c[0], 0.3, 1e-5) << ext;
      EXPECT_NEAR(c[1], 0.5, 1e-5) << ext;
      EXPECT_NEAR(c[2], 0.7, 1e-5) << ext;
    }
  }
}

// Extinction .5, albedo .5, no ambient value: a ray through the centre loses exp(-.5 x 2); one
// that starts at the centre knows it is inside only on leaving, and only if the mist lists a
// source that exists (then its own segment gains the mist: exp(-.5)); otherwise it sees the
// glow unchanged. Leaving a mist never takes away more than it added.
TEST(MistMedia, RayStartingInsideLearnsOnLeaving) {
  const std::string rays = "-5 0 0 1 0 0\n0 0 0 0 0 1\n";
  Traced known = rtrace(furnace("1 sun\n0\n6 .5 .5 .5 .5 .5 .5"), rays, "-ab 0");
  ASSERT_EQ(known.rc, 0) << known.log;
  ASSERT_EQ(known.values.size(), 2u) << known.log;
  EXPECT_NEAR(known.values[0][1], 0.5 * std::exp(-1.0), 1e-5);
  EXPECT_NEAR(known.values[1][1], 0.5 * std::exp(-0.5), 1e-5);
  Traced unknown = rtrace(furnace("1 moon\n0\n6 .5 .5 .5 .5 .5 .5"), rays, "-ab 0");
  ASSERT_EQ(unknown.rc, 0) << unknown.log;
  EXPECT_NE(unknown.log.find("warning - unknown source \"moon\" for mist \"m\""), std::string::npos)
      << unknown.log;
  ASSERT_EQ(unknown.values.size(), 2u) << unknown.log;
  EXPECT_NEAR(unknown.values[0][1], 0.5 * std::exp(-1.0), 1e-5);
  EXPECT_NEAR(unknown.values[1][1], 0.5, 1e-5);
}

// A slab of mist (extinction s, albedo a, eccentricity g), 2 m long along the rays and reaching
// h = 1 m above them, under a sun straight overhead (radiance L, solid angle W) at 90 degrees to
// the rays: each ray gains a P(90) L W / (4 pi) exp(-s (1 - a) h) (1 - exp(-2 s)), P the
// Henyey-Greenstein phase, the shadow rays losing only what the mist absorbs. The mean of 64
// rays (16 stratified samples each) within 1%.
TEST(MistMedia, SunScatteredAsSingleScattering) {
  const double s = 0.5, a = 0.7, g = 0.3, L = 1e5, h = 1.0, D = 2.0;
  const double W = 2 * std::numbers::pi * (1 - std::cos(0.25 * std::numbers::pi / 180));
  std::string rad = "void light solar\n0\n0\n3 1e5 1e5 1e5\nsolar source sun\n0\n0\n4 0 0 1 0.5\n"
                    "void mist slab\n1 sun\n0\n7 .5 .5 .5 .7 .7 .7 .3\n";
  // genbox slab: x 0..2, y -50..50, z -50..0, normals outward
  const char* faces[] = {"0 -50 -50  0 -50 0  0 50 0  0 50 -50",     // x = 0
                         "2 -50 -50  2 50 -50  2 50 0  2 -50 0",     // x = 2
                         "0 -50 0  2 -50 0  2 50 0  0 50 0",         // top
                         "0 -50 -50  0 50 -50  2 50 -50  2 -50 -50", // bottom
                         "0 -50 -50  2 -50 -50  2 -50 0  0 -50 0",   // y = -50
                         "0 50 -50  0 50 0  2 50 0  2 50 -50"};      // y = 50
  for (int i = 0; i < 6; ++i)
    rad += "slab polygon f" + std::to_string(i) + "\n0\n0\n12 " + faces[i] + "\n";
  std::string rays;
  for (int i = 0; i < 64; ++i)
    rays += "-1 " + std::to_string(0.1 * i - 3.2) + " -1 1 0 0\n";
  Traced r = rtrace(rad, rays, "-ab 0 -u+ -ms 0.05");
  ASSERT_EQ(r.rc, 0) << r.log;
  ASSERT_EQ(r.values.size(), 64u) << r.log;
  double mean = 0;
  for (const Rgb& c : r.values)
    mean += c[1] / 64;
  const double phase = (1 - g * g) / std::pow(1 + g * g, 1.5);
  const double want = a * phase * L * W / (4 * std::numbers::pi) * std::exp(-s * (1 - a) * h) *
                      (1 - std::exp(-s * D));
  EXPECT_NEAR(mean, want, 0.01 * want);
}

// More than 7 real arguments is Radiance's "bad arguments": fatal, naming the mist.
TEST(MistMedia, BadArgumentsAreFatal) {
  Traced r = rtrace(furnace("1 sun\n0\n8 .1 .1 .1 .5 .5 .5 .3 1"), "0 0 0 1 0 0\n", "-ab 0");
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.log.find("\"m\""), std::string::npos) << r.log;
  EXPECT_EQ(r.log.find("internal error"), std::string::npos) << r.log;
}
