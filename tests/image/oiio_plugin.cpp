// OpenImageIO is a module rpict opens only when it writes TIFF or PNG (src/image/oiio_io.cpp):
// a run that writes a Radiance picture never loads its libraries, a PNG run does, and a
// missing module is a clear error with a non-zero exit.
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

#include "reference_data.h"
#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::run_command;

namespace {

struct RpictRun {
  int rc = 0;
  std::string log;
};

// rpict on the Cornell box at 8 x 8 without bounces, `env` before the command, ld.so's list of
// the files it loads in the log.
RpictRun rpict(const std::string& env, const std::string& out) {
  RpictRun r;
  r.rc = run_command("cd " + radcl::test::data("scenes") + " && " + env + " LD_DEBUG=files " +
                         radcl::test::bin_dir() + "/rpict -vf cornell.vf -x 8 -y 8 -ab 0 -o " +
                         out + " cornell.oct 2>&1",
                     &r.log);
  return r;
}

fs::path temp(const std::string& name) {
  static const radcl::test::TempFolder d("oiio_plugin"); // removed at exit
  fs::remove(d / name);
  return d / name;
}

} // namespace

TEST(OiioPlugin, LoadedOnlyForTiffAndPng) {
  const fs::path hdr = temp("a.hdr"), png = temp("a.png");
  RpictRun a = rpict("", hdr.string());
  ASSERT_EQ(a.rc, 0) << a.log;
  EXPECT_TRUE(fs::exists(hdr));
  EXPECT_EQ(a.log.find("libOpenImageIO"), std::string::npos) << "a Radiance picture loaded it";
  RpictRun b = rpict("", png.string());
  ASSERT_EQ(b.rc, 0) << b.log;
  EXPECT_GT(fs::file_size(png), 8u);
  EXPECT_NE(b.log.find("libradcl_oiio"), std::string::npos);
}

TEST(OiioPlugin, MissingModuleIsAnError) {
  const fs::path png = temp("b.png");
  RpictRun r = rpict("RADCL_OIIO_PLUGIN=/nonexistent/libradcl_oiio.so", png.string());
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.log.find("cannot load OpenImageIO support"), std::string::npos) << r.log;
  EXPECT_NE(r.log.find(png.string()), std::string::npos) << r.log;
}
