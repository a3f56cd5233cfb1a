// gensky and gendaylit against Radiance 5.4a: every command line of tests/data/skies/cases.tsv
// runs through the built executable (found on PATH, so that the command echoed in the first
// comment line reads as in Radiance's output) and stdout and stderr must match byte for byte.
#include "files.h"
#include "temp_dir.h"
#include "test_env.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using radcl::test::read_file;

namespace {

struct Case {
  std::string id, command;
};

std::vector<Case> load_cases() {
  std::ifstream in(radcl::test::data("skies/cases.tsv"));
  std::vector<Case> cases;
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab != std::string::npos) cases.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return cases;
}

TEST(GoldenSkies, AllReferenceCasesMatchExactly) {
  const std::vector<Case> cases = load_cases();
  ASSERT_EQ(cases.size(), 41u);
  const radcl::test::TempFolder tmp("golden_skies");
  const std::string err_file = (tmp / "err").string();
  int exact = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.id + ": " + c.command);
    std::string out;
    const int rc = radcl::test::run_command("( PATH='" + radcl::test::bin_dir() + "':\"$PATH\" " +
                                                c.command + " 2>'" + err_file + "' )",
                                            &out);
    EXPECT_EQ(rc, 0);
    const std::string want_out = read_file(radcl::test::data("skies/" + c.id + ".rad"));
    const std::string want_err = read_file(radcl::test::data("skies/" + c.id + ".err"));
    const std::string err = read_file(err_file);
    EXPECT_EQ(out, want_out);
    EXPECT_EQ(err, want_err);
    exact += out == want_out && err == want_err;
  }
  RecordProperty("exact_matches", exact);
  EXPECT_EQ(exact, 41);
}

} // namespace
