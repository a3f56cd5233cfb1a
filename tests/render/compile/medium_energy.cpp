// The global medium in a furnace: inside a bubble of uniform glow (radiance L, no light source)
// with -av L, a ray that travels d through a medium of extinction e and albedo a brings back
// L exp(-e d) + a L (1 - exp(-e d)). With a = 1 that is L whatever e and d: a medium that only
// scatters neither makes nor loses light (energy conservation, exact up to float rounding).
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "files.h"
#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

namespace {

// rtrace's values for rays from the centre of a bubble of radius 10 (L = .3 .5 .7).
std::vector<std::array<double, 3>> furnace(const std::string& medium) {
  const radcl::test::TempFolder dir("furnace");
  radcl::test::write_file(dir / "furnace.rad",
                          "void glow g\n0\n0\n4 .3 .5 .7 0\ng bubble b\n0\n0\n4 0 0 0 10\n");
  const radcl::test::ProgramRun r =
      radcl::test::Program("rtrace")
          .input("0 0 0 1 0 0\n0 0 0 0 0 -1\n3 4 0 0.6 -0.8 0\n-5 1 2 1 1 1\n")
          .in(dir.str())
          .merge_err()
          .run("-h -ab 0 -av .3 .5 .7 " + medium + " furnace.rad");
  const std::string& out = r.out;
  EXPECT_EQ(r.rc, 0) << out;
  std::vector<std::array<double, 3>> v;
  std::istringstream in(out);
  std::array<double, 3> c;
  while (in >> c[0] >> c[1] >> c[2])
    v.push_back(c);
  return v;
}

} // namespace

TEST(MediumEnergy, AlbedoOneNeitherMakesNorLosesLight) {
  for (const char* me : {"0.01 0.01 0.01", "0.1 0.2 0.3", "2 2 2"}) {
    auto v = furnace(std::string("-me ") + me + " -ma 1 1 1 -mg 0.5");
    ASSERT_EQ(v.size(), 4u) << me;
    for (const auto& c : v) {
      EXPECT_NEAR(c[0], 0.3, 1e-5) << me;
      EXPECT_NEAR(c[1], 0.5, 1e-5) << me;
      EXPECT_NEAR(c[2], 0.7, 1e-5) << me;
    }
  }
}

TEST(MediumEnergy, AbsorptionTakesItsShare) {
  // From the centre every ray travels 10: transmittance exp(-1) at extinction .1.
  auto v = furnace("-me .1 .1 .1 -ma .5 .5 .5");
  ASSERT_EQ(v.size(), 4u);
  const double t = std::exp(-1.0), k = t + 0.5 * (1 - t);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(v[i][0], 0.3 * k, 1e-5);
    EXPECT_NEAR(v[i][1], 0.5 * k, 1e-5);
    EXPECT_NEAR(v[i][2], 0.7 * k, 1e-5);
  }
  // Without albedo only exp(-e d) of the glow arrives.
  v = furnace("-me .1 .1 .1");
  ASSERT_EQ(v.size(), 4u);
  EXPECT_NEAR(v[0][1], 0.5 * t, 1e-5);
}
