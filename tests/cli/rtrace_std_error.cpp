// rtrace -oe end to end: six numbers per sensor with -ove (the value, then its standard error),
// NCOMP=6 in the header, the same values as -ov, in every output format, and the word in
// -defaults.
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "run_program.h"
#include "test_env.h"

namespace {

const std::string kRun = "-n 2 -I -ab 1 -aa 0 -ad 256 -as 0 ";

std::string rtrace(const std::string& args) {
  const radcl::test::ProgramRun r =
      radcl::test::Program("rtrace")
          .env("RADCL_SEED=4 ")
          .input(radcl::test::read_file(radcl::test::data("scenes/office_grid.pts")))
          .run(args + " office_clear.oct");
  EXPECT_EQ(r.rc, 0) << r.err;
  return r.out;
}

std::vector<std::vector<double>> numbers(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream w(line);
    rows.emplace_back();
    for (double x; w >> x;)
      rows.back().push_back(x);
  }
  return rows;
}

} // namespace

TEST(RtraceStdError, ValueThenItsError) {
  const auto with = numbers(rtrace("-h " + kRun + "-ove"));
  const auto without = numbers(rtrace("-h " + kRun + "-ov"));
  ASSERT_EQ(with.size(), 77u);
  ASSERT_EQ(without.size(), 77u);
  for (std::size_t i = 0; i < with.size(); ++i) {
    ASSERT_EQ(with[i].size(), 6u);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(with[i][c], without[i][c], 1e-5 * without[i][c]) << i;
      EXPECT_GT(with[i][3 + c], 0) << i; // every sensor here gets light from its hemisphere
    }
  }
  // Binary output carries the six numbers too.
  const std::string f = rtrace("-h " + kRun + "-ove -faf");
  EXPECT_EQ(f.size(), 77u * 6 * sizeof(float));
}

TEST(RtraceStdError, HeaderAndDefaults) {
  const std::string h = rtrace(kRun + "-ove");
  EXPECT_NE(h.find("NCOMP=6"), std::string::npos) << h.substr(0, 400);
  const radcl::test::ProgramRun d = radcl::test::Program("rtrace").run("-ove -defaults");
  EXPECT_EQ(d.rc, 0);
  EXPECT_NE(d.out.find("# output value std_error"), std::string::npos) << d.out;
}
