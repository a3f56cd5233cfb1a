// The radcl executable: its kernels are embedded (a copy moved elsewhere still builds and checks
// its programs), and bad usage is a Radiance-style fatal error with a non-zero exit.
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::run_command;

TEST(RadclTool, MovedBinaryChecksItsDevice) {
  const radcl::test::TempFolder tmp("moved");
  const fs::path& dir = tmp.path();
  fs::copy_file(radcl::test::bin_dir() + "/radcl", dir / "radcl",
                fs::copy_options::overwrite_existing);
  std::string out;
  // Run from an empty folder with a fresh program cache: nothing but the binary is available.
  int rc = run_command("cd " + dir.string() + " && RADCL_CACHE_DIR=" + dir.string() +
                           "/cache ./radcl devices --check",
                       &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("struct layout: ok"), std::string::npos) << out;
  EXPECT_NE(out.find("random numbers: ok"), std::string::npos) << out;
  EXPECT_NE(out.find("* "), std::string::npos) << "a device is marked as selected:\n" << out;
}

TEST(RadclTool, UnknownCommandIsFatal) {
  std::string out;
  EXPECT_EQ(run_command(radcl::test::bin_dir() + "/radcl frobnicate", &out), 1);
  EXPECT_NE(out.find("radcl: fatal - unknown command \"frobnicate\""), std::string::npos) << out;
  out.clear();
  EXPECT_EQ(run_command(radcl::test::bin_dir() + "/radcl devices --bogus", &out), 1);
  EXPECT_NE(out.find("radcl: fatal - devices: unknown option"), std::string::npos) << out;
}

TEST(RadclTool, BadDeviceChoiceIsFatal) {
  std::string out;
  EXPECT_EQ(
      run_command("RADCL_DEVICE=no-such-device " + radcl::test::bin_dir() + "/radcl devices", &out),
      1);
  EXPECT_NE(out.find("RADCL_DEVICE=no-such-device: no device matches"), std::string::npos) << out;
}

TEST(RadclTool, Version) {
  std::string out;
  EXPECT_EQ(run_command(radcl::test::bin_dir() + "/radcl version", &out), 0);
  EXPECT_EQ(out.rfind("radcl ", 0), 0u) << out;
}
