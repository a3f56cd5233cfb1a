// rtrace's and rpict's command-line conventions as Radiance's (rtmain.c, rpmain.c, error.c,
// expandarg.c): -version and -defaults answer on standard output with status 0; a bad option
// is "<name>: fatal - command line error at '<word>'" with status 1; an option file that cannot
// be read is a system error (status 2) with the system's reason; messages name the program as
// it was called (the last path component, less any extension, in lower case). Option files
// expand to any number of words over any number of lines, nested, in either program.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::bin_dir;
using radcl::test::run_command;

namespace {

class CommandConventions : public radcl::test::TempDir {
protected:
  // Status of `cmd` (stderr kept apart when `err` is given).
  int run(const std::string& cmd, std::string* out, std::string* err = nullptr) {
    if (!err) return run_command(cmd, out);
    const std::string e = (dir / "stderr.txt").string();
    int rc = run_command("(" + cmd + " 2>" + e + ")", out);
    std::ifstream in(e);
    err->assign(std::istreambuf_iterator<char>(in), {});
    fs::remove(e);
    return rc;
  }
};

} // namespace

TEST_F(CommandConventions, VersionAndDefaults) {
  for (const char* prog : {"rtrace", "rpict"}) {
    std::string out, err;
    ASSERT_EQ(run(bin_dir() + "/" + prog + " -version", &out, &err), 0) << err;
    // Tools read Radiance's release from the second word ("RADIANCE 5.4a ...").
    EXPECT_EQ(out.rfind("RADIANCE 5.4a radcl ", 0), 0u) << out;
    EXPECT_NE(out.find(std::string("(") + prog + ")"), std::string::npos) << out;
    EXPECT_EQ(err, "");
    out.clear();
    ASSERT_EQ(run(bin_dir() + "/" + prog + " -defaults", &out, &err), 0) << err;
    EXPECT_NE(out.find("\n-ab 0 "), std::string::npos) << out;
    EXPECT_NE(out.find("# ambient bounces"), std::string::npos) << out;
  }
}

TEST_F(CommandConventions, BadOptionsAndFilesAsRadiance) {
  std::string out, err;
  EXPECT_EQ(run(bin_dir() + "/rtrace -zz x.oct", &out, &err), 1);
  EXPECT_EQ(err, "rtrace: fatal - command line error at '-zz'\n");
  EXPECT_EQ(run(bin_dir() + "/rpict -vf", &out, &err), 1);
  EXPECT_EQ(err, "rpict: fatal - command line error at '-vf'\n");
  EXPECT_EQ(run(bin_dir() + "/rtrace @/nonexistent/opts x.oct", &out, &err), 2);
  EXPECT_EQ(err,
            "rtrace: system - cannot expand '@/nonexistent/opts': No such file or directory\n");
  unsetenv("RADCL_SURELY_UNSET");
  EXPECT_EQ(run(bin_dir() + "/rpict '$RADCL_SURELY_UNSET' x.oct", &out, &err), 2);
  EXPECT_EQ(err, "rpict: system - cannot expand '$RADCL_SURELY_UNSET'\n");
  // An option file naming itself: an error, not a hang.
  const std::string self = (dir / "self.opt").string();
  std::ofstream(self) << "@" << self << "\n";
  EXPECT_EQ(run("timeout 20 " + bin_dir() + "/rtrace @" + self + " x.oct", &out, &err), 1);
  EXPECT_NE(err.find("rtrace: fatal - cannot expand '@" + self + "': more than"), std::string::npos)
      << err;
}

// The global participating medium's options take effect (tests/render/golden/golden_medium.cpp checks
// the values); its albedo, eccentricity and sampling distance do nothing without extinction, as
// in Radiance.
TEST_F(CommandConventions, MediumOptionsTakeEffect) {
  const std::string cd = "cd " + radcl::test::data("scenes") + " && ", oct = "office_clear.oct";
  std::string out, err;
  const std::string ray = "echo 1 1 1 0 0 1 | ";
  EXPECT_EQ(run(cd + ray + bin_dir() + "/rtrace -h -av 1 1 1 " + oct, &out, &err), 0) << err;
  const std::string clear = out;
  out.clear();
  EXPECT_EQ(run(cd + ray + bin_dir() + "/rtrace -h -av 1 1 1 -me 0.03 0.03 0.04 -ma 0.8 0.8 0.8 " +
                    "-mg 0.3 " + oct,
                &out, &err),
            0)
      << err;
  EXPECT_NE(out, clear);
  out.clear();
  EXPECT_EQ(run(cd + bin_dir() + "/rpict -x 8 -y 8 -me 0.01 0 0 " + oct, &out, &err), 0) << err;
  EXPECT_EQ(out.rfind("#?RADIANCE", 0), 0u);
  out.clear();
  EXPECT_EQ(
      run(cd + ray + bin_dir() + "/rtrace -h -me 0 0 0 -ma 0.8 0.8 0.8 -mg " + "0.3 -ms 0.1 " + oct,
          &out, &err),
      0)
      << err;
  EXPECT_EQ(out, "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n");
}

TEST_F(CommandConventions, ProgramNamedAsCalled) {
  fs::create_symlink(fs::absolute(bin_dir() + "/rtrace"), dir / "My_RTrace.exe");
  std::string out, err;
  EXPECT_EQ(run((dir / "My_RTrace.exe").string() + " -zz x.oct", &out, &err), 1);
  EXPECT_EQ(err, "my_rtrace: fatal - command line error at '-zz'\n");
  EXPECT_EQ(run((dir / "My_RTrace.exe").string() + " -h nothing.oct < /dev/null", &out, &err), 1);
  EXPECT_EQ(err.rfind("my_rtrace: fatal - ", 0), 0u) << err;
}

// The issue's crash: rpict with an option file of three or more words (rad's `render =`).
TEST_F(CommandConventions, OptionFilesAnyLength) {
  const std::string src = radcl::test::source_dir();
  const std::string opt = (dir / "o.opt").string(), inner = (dir / "inner.opt").string();
  std::ofstream(inner) << "-u+\n-dj 0\n";
  std::ofstream(opt) << "-ab 0\n@" << inner << "\n-lr 6 -lw .002\n";
  for (const char* prog : {"rpict", "rtrace"}) {
    std::string out, err;
    std::string cmd = std::string(prog) == "rpict"
                          ? bin_dir() + "/rpict @" + opt + " -vf " + src +
                                "/scenes/room.vf -x 16 -y 16 " + src + "/scenes/room.rad > " +
                                (dir / "o.hdr").string()
                          : "echo '0.5 2.5 0.8 0 0 -1' | " + bin_dir() + "/rtrace -h @" + opt +
                                " -ov " + src + "/scenes/room.rad > " + (dir / "o.txt").string();
    ASSERT_EQ(run(cmd, &out, &err), 0) << prog << ": " << err;
  }
  std::ifstream pic(dir / "o.hdr");
  std::string line, header;
  while (std::getline(pic, line) && !line.empty())
    header += line + "\n";
  // The header's command line holds the expanded words, as Radiance's printargs() writes them.
  EXPECT_NE(header.find("\nrpict -ab 0 -u+ -dj 0 -lr 6 -lw .002 -vf "), std::string::npos)
      << header;
  std::getline(pic, line);
  EXPECT_EQ(line, "-Y 12 +X 16"); // room.vf is 70 x 55 degrees
  std::ifstream txt(dir / "o.txt");
  double r = -1, g = -1, b = -1;
  txt >> r >> g >> b;
  EXPECT_GT(g, 0.0);
}

// radcl's own commands expand option files the same way.
TEST_F(CommandConventions, RadclToolExpandsOptionFiles) {
  const std::string room = radcl::test::source_dir() + "/scenes/room.rad";
  const std::string opt = (dir / "scene.opt").string();
  std::ofstream(opt) << "scene\n" << room << "\n";
  std::string direct, expanded, err;
  ASSERT_EQ(run(bin_dir() + "/radcl scene " + room, &direct, &err), 0) << err;
  ASSERT_EQ(run(bin_dir() + "/radcl @" + opt, &expanded, &err), 0) << err;
  EXPECT_EQ(expanded, direct);
  EXPECT_NE(direct.find("polygon"), std::string::npos) << direct;
}
