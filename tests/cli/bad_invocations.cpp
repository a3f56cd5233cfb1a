// Bad invocations of rtrace and rpict, as users make them (issue 34): missing, unreadable and
// directory files for the file options, non-numeric and out-of-range values, broken views,
// option files that cannot be expanded (binary or huge ones too), odd ray input. Each gives its
// Radiance-style message and exit status (1 for a fatal error, 2 for a system error, 0 where
// Radiance carries on), never an internal error, a crash or a hang, and leaves no half-written
// output behind.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include <cstdint>

#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::run_command;

namespace {

struct Case {
  const char* cmd;         // run in tests/data/scenes; @B@ = build/bin, @T@ = a scratch folder
  const char* input;       // standard input
  int rc;                  // expected exit status
  const char* says;        // part of the expected message ("" for none)
  const char* absent = ""; // a file that must not exist afterwards (@T@-relative)
};

const Case kCases[] = {
    // octree and scene files
    {"@B@/rtrace -h nosuch.oct", "", 1, "cannot open octree file \"nosuch.oct\""},
    {"@B@/rtrace -h @T@", "", 1, "cannot open scene file"},
    {"@B@/rtrace -h", "", 1, "missing octree argument"},
    {"@B@/rpict -x 8 -y 8 nosuch.rad", "", 1, "cannot open scene file \"nosuch.rad\""},
    {"@B@/rtrace -h mist.vf", "", 1, "mist.vf"},
    // numbers
    {"@B@/rtrace -h -ab x office_clear.oct", "", 1, "command line error at '-ab'"},
    {"@B@/rtrace -h -aa nan office_clear.oct", "", 1, "command line error at '-aa'"},
    {"@B@/rtrace -h -ad 1e99x office_clear.oct", "", 1, "command line error at '-ad'"},
    {"@B@/rtrace -h -n 0 office_clear.oct", "", 1, "bad number of processes"},
    {"@B@/rtrace -h -n abc office_clear.oct", "", 1, "command line error at '-n'"},
    {"@B@/rtrace -h -me 1 2 office_clear.oct", "", 1, "command line error at '-me'"},
    {"@B@/rtrace -h -av 1 1 office_clear.oct", "", 1, "command line error at '-av'"},
    {"@B@/rtrace -h -dj x office_clear.oct", "", 1, "command line error at '-dj'"},
    {"@B@/rtrace -h -lw -1 office_clear.oct", "", 1, "zero ray weight in Russian roulette"},
    {"@B@/rpict -x abc office_clear.oct", "", 1, "command line error at '-x'"},
    {"@B@/rpict -ps abc office_clear.oct", "", 1, "command line error at '-ps'"},
    {"@B@/rpict -S abc office_clear.oct", "", 1, "command line error at '-S'"},
    {"@B@/rpict -vp 1 2 office_clear.oct", "", 1, "command line error at '-vp'"},
    // options that are not options
    {"@B@/rtrace -h -f office_clear.oct", "", 1, "command line error at '-f'"},
    {"@B@/rtrace -h -fz office_clear.oct", "", 1, "command line error at '-fz'"},
    {"@B@/rtrace -h -ozz office_clear.oct", "", 1, "unrecognized output option 'z'"},
    {"@B@/rtrace -h -ab 1 -ove office_clear.oct", "", 1, "-oe requires -aa 0"},
    {"@B@/rtrace -h -ab 1 -aa 0 -ovte office_clear.oct", "", 1, "-oe is not a traced ray's output"},
    {"@B@/rtrace -h -ap x.pm office_clear.oct", "", 1, ""},
    // views
    {"@B@/rpict -vf nosuch.vf office_clear.oct", "", 1, "cannot open view file \"nosuch.vf\""},
    {"@B@/rpict -vf @T@ office_clear.oct", "", 1, "bad view file"},
    {"@B@/rpict -vf office_clear.oct office_clear.oct", "", 1, "bad view file"},
    {"@B@/rpict -vtz office_clear.oct", "", 1, "unknown view type"},
    {"@B@/rpict -vh 200 -vtv office_clear.oct", "", 1, "illegal horizontal view size"},
    {"@B@/rpict -vd 0 0 0 -x 8 -y 8 office_clear.oct", "", 1, "zero view direction"},
    {"@B@/rpict -vu 0 0 0 -vd 0 0 1 -x 8 -y 8 office_clear.oct", "", 1, "zero view up vector"},
    // option files and variables
    {"@B@/rtrace -h @nosuch.opt office_clear.oct", "", 2, "cannot expand '@nosuch.opt'"},
    {"@B@/rtrace -h @@T@ office_clear.oct", "", 2, "Is a directory"},
    {"@B@/rtrace -h @@T@/self.opt office_clear.oct", "", 1, "nested expansions"},
    {"@B@/rpict @@T@/self.opt office_clear.oct", "", 1, "nested expansions"},
    {"@B@/rtrace -h @@T@/ping.opt office_clear.oct", "", 1, "expansions in one command line"},
    {"@B@/rtrace -h '$RADCL_NO_SUCH_VARIABLE' office_clear.oct", "", 2, "cannot expand"},
    {"@B@/rtrace -h @@T@/binary.opt office_clear.oct", "", 1, "must be the only scene input"},
    {"@B@/rtrace -h @@T@/huge.opt -ov office_clear.oct", "1 1 1 0 0 1\n", 0,
     "\t"}, // 4 M words: a value
    // name and ambient files
    {"@B@/rtrace -h -aI /nonexistent office_clear.oct", "", 1,
     "cannot open ambient include file \"/nonexistent\""},
    {"@B@/rtrace -h -aE @T@ office_clear.oct", "", 1, "cannot open ambient exclude file"},
    {"@B@/rtrace -h -ab 1 -af @T@ office_clear.oct", "1 1 1 0 0 1\n", 1, "bad ambient file"},
    {"@B@/rtrace -h -ab 1 -af /nonexistent/dir/x.amb office_clear.oct", "1 1 1 0 0 1\n", 1,
     "cannot open ambient file"},
    {"@B@/rtrace -h -ab 1 -af @T@/new.amb -ab x office_clear.oct", "", 1,
     "command line error at '-ab'", "new.amb"},
    // output files
    {"@B@/rpict -o @T@ office_clear.oct", "", 1, "cannot open output file"},
    {"@B@/rpict -o /nonexistent/x.hdr office_clear.oct", "", 1, "cannot open output file"},
    {"@B@/rpict -o @T@/out.hdr -vtz office_clear.oct", "", 1, "unknown view type", "out.hdr"},
    // ray input
    {"@B@/rtrace -h office_clear.oct", "", 0, ""},
    {"@B@/rtrace -h office_clear.oct", "1 2 3\n", 0, ""},
    {"@B@/rtrace -h office_clear.oct", "nan nan nan 0 0 1\ninf 0 0 1 0 0\n", 0, ""},
    {"@B@/rtrace -h office_clear.oct", "1 1 1 0 0 0\n1 1 1 0 0 1\n", 0, ""},
    {"@B@/rtrace -h -fff office_clear.oct", "not floats at all\n", 0, ""},
    {"@B@/rtrace -h -fdd office_clear.oct", "123", 0, ""},
    {"@B@/rtrace -h -x 2 -y 2 office_clear.oct", "1 1 1 0 0 1\n", 0, ""},
    {"@B@/rtrace -h office_clear.oct", "1 1 1 0 0 1 junk\n", 0, ""}, // as Radiance: input ends
    // pictures too wide for memory: refused before a pixel, the output file removed
    {"@B@/rpict -pa 0 -x 200000000 -y 10 -ps 16 -o @T@/big.hdr office_clear.oct", "", 1,
     "of memory for its rows at -ps 16", "big.hdr"},
    // empty pictures
    {"@B@/rpict -x 0 -y 0 office_clear.oct", "", 0, "empty output picture"},
};

std::string filled(std::string s, const std::string& tmp) {
  for (auto [key, value] : {std::pair<std::string, std::string>{"@B@", radcl::test::bin_dir()},
                            std::pair<std::string, std::string>{"@T@", tmp}})
    for (std::size_t at; (at = s.find(key)) != std::string::npos;)
      s.replace(at, key.size(), value);
  return s;
}

class BadInvocations : public ::testing::TestWithParam<int> {
protected:
  void SetUp() override {
    std::ofstream(tmp_ / "self.opt") << "@" << (tmp_ / "self.opt").string() << "\n";
    // Two files that name each other after other words: the line grows without end.
    std::ofstream(tmp_ / "ping.opt") << "-aa .1 @" << (tmp_ / "pong.opt").string() << "\n";
    std::ofstream(tmp_ / "pong.opt") << "@" << (tmp_ / "ping.opt").string() << "\n";
    const std::string cmd = kCases[GetParam()].cmd;
    if (cmd.find("binary.opt") != std::string::npos) { // 64 KB of fixed pseudo-random bytes
      std::ofstream f(tmp_ / "binary.opt", std::ios::binary);
      std::uint32_t x = 12345;
      for (int i = 0; i < 65536; ++i) {
        x = x * 1664525u + 1013904223u;
        f.put(static_cast<char>(x >> 24));
      }
    }
    if (cmd.find("huge.opt") != std::string::npos) { // 12 MB: the command line it makes works
      std::ofstream f(tmp_ / "huge.opt");
      for (int i = 0; i < 2000000; ++i)
        f << "-ab 0 ";
    }
  }
  radcl::test::TempFolder folder_{"bad_invocation"};
  const fs::path& tmp_ = folder_.path();
};

TEST_P(BadInvocations, ClearMessageAndStatus) {
  const Case& c = kCases[GetParam()];
  const std::string cmd = filled(c.cmd, tmp_.string());
  std::ofstream(tmp_ / "stdin.txt") << c.input;
  std::string out;
  int rc = run_command("cd " + radcl::test::data("scenes") + " && timeout 120 " + cmd + " < " +
                           (tmp_ / "stdin.txt").string(),
                       &out);
  SCOPED_TRACE(cmd);
  EXPECT_NE(rc, 124) << "hung";
  EXPECT_EQ(rc, c.rc) << out.substr(0, 2000);
  EXPECT_NE(out.find(c.says), std::string::npos) << out.substr(0, 2000);
  EXPECT_EQ(out.find("internal error"), std::string::npos) << out.substr(0, 2000);
  if (*c.absent) {
    EXPECT_FALSE(fs::exists(tmp_ / c.absent)) << c.absent;
  }
}

INSTANTIATE_TEST_SUITE_P(Table, BadInvocations,
                         ::testing::Range(0, static_cast<int>(std::size(kCases))));

} // namespace
