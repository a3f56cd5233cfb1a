// Issue 8 case 3 through the rtrace program: degenerate surfaces give Radiance 5.4a's warnings
// (the surface is ignored, the run goes on, exit status 0) and a negative ring radius its fatal
// error (exit status 1, nothing written).
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

namespace {

struct Result {
  int rc;
  std::string out, log;
};

// rtrace `opts` on the scene text `scene` (s.rad in a folder of its own) with input `input`.
Result rtrace(const std::string& opts, const std::string& scene, const std::string& input) {
  const radcl::test::TempFolder dir("degenerate");
  radcl::test::write_file(dir / "s.rad", scene);
  const radcl::test::ProgramRun r =
      radcl::test::Program("rtrace").input(input).in(dir.str()).run("-h " + opts + " s.rad");
  return {r.rc, r.out, r.err};
}

const char* kLamp = "void light lm 0 0 3 100 100 100\nlm sphere lamp 0 0 4 0 0 3 0.1\n"
                    "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                    "grey polygon floor 0 0 12 -9 -9 0 9 -9 0 9 9 0 -9 9 0\n";

} // namespace

TEST(StabilityDegenerateScene, WarningsAndTheRunGoesOn) {
  const std::string scene = std::string(kLamp) + "grey polygon line 0 0 9 0 0 1 1 1 1 2 2 1\n"
                                                 "grey polygon dot 0 0 9 1 1 1 1 1 1 1 1 1\n"
                                                 "grey cone pin 0 0 8 0 0 1 0 0 2 0 0\n"
                                                 "grey cylinder wire 0 0 7 0 0 1 0 0 2 0\n"
                                                 "grey ring flat 0 0 8 0 0 1 0 0 1 0.5 0.5\n"
                                                 "grey sphere nil 0 0 4 0 0 1 0\n";
  Result r = rtrace("-I -ab 0 -dj 0 -ds 0 -dt 0 -ov", scene, "0 0 0 0 0 1\n");
  EXPECT_EQ(r.rc, 0) << r.log;
  for (const char* w : {"rtrace: warning - zero area for polygon \"line\"",
                        "rtrace: warning - zero area for polygon \"dot\"",
                        "rtrace: warning - illegal radii for cone \"pin\"",
                        "rtrace: warning - illegal radii for cylinder \"wire\"",
                        "rtrace: warning - illegal radii for ring \"flat\"",
                        "rtrace: warning - zero radius for sphere \"nil\""})
    EXPECT_NE(r.log.find(w), std::string::npos) << w << "\n" << r.log;
  // The ignored surfaces block nothing: the floor's sensor reads the lamp's exact irradiance.
  std::istringstream s(r.out);
  double v = 0;
  ASSERT_TRUE(s >> v) << r.out;
  const double want = 3.14159265358979 * 100 * 0.01 / ((3 - 1e-4) * (3 - 1e-4));
  EXPECT_NEAR(v, want, 1e-4 * want);
}

TEST(StabilityDegenerateScene, NegativeRingRadiusIsFatal) {
  Result r = rtrace("-ab 0 -ov", std::string(kLamp) + "grey ring neg 0 0 8 0 0 1 0 0 1 -1 0\n",
                    "0 0 1 0 0 -1\n");
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.log.find("rtrace: fatal - negative radii for ring \"neg\""), std::string::npos)
      << r.log;
  EXPECT_EQ(r.out, "");
}
