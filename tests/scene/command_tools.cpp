// Scene commands find radcl's own gensky/gendaylit even where no Radiance is on PATH.
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "temp_dir.h"
#include "test_env.h"

using radcl::test::run_command;

TEST(CommandTools, GenskyRunsWithoutRadianceOnPath) {
  const radcl::test::TempFolder dir("command_tools");
  const std::string file = (dir / "sky.rad").string();
  std::ofstream(file) << "!gensky 3 21 12 +s\n";
  std::string out;
  int rc = run_command(
      "env PATH=/usr/bin:/bin " + radcl::test::bin_dir() + "/radcl scene --list " + file, &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("source\tsun\tsolar"), std::string::npos) << out;
  EXPECT_NE(out.find("brightfunc\tskyfunc"), std::string::npos) << out;
}
