// rpict's sequence mode (-S, one view line per frame from standard input), motion blur (-pm),
// the octree on standard input, and persistent rpict's argument checks.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "files.h"
#include "temp_dir.h"
#include "test_env.h"

using radcl::test::read_file;
using radcl::test::run_command;
namespace fs = std::filesystem;

namespace {

// Small and direct-light only: deterministic with -u-, quick on two cores.
const std::string kOpts = "-u- -ab 0 -x 32 -y 24 -vf cornell.vf ";
const char* kViews = "VIEW= -vp 0.45 0.05 0.5\n"
                     "this line is no view\n"
                     "rpict -vp 0.5 0.05 0.5 -vd 0.1 1 0\n"
                     "rpict -vp 0.55 0.05 0.45\n";

class RpictSequence : public radcl::test::TempDir {
protected:
  void SetUp() override {
    TempDir::SetUp();
    std::ofstream(dir / "views") << kViews;
  }

  int rpict(const std::string& args, std::string* log = nullptr) {
    std::string l;
    int rc = run_command("cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                             "/rpict " + args,
                         log ? log : &l);
    return rc;
  }
  std::string frame(int n) const {
    char b[32];
    std::snprintf(b, sizeof b, "f%03d.hdr", n);
    return (dir / b).string();
  }
};

// The header lines (up to the empty line) and the rest (resolution and pixels).
std::pair<std::string, std::string> split(const std::string& pic) {
  std::size_t e = pic.find("\n\n");
  if (e == std::string::npos) return {pic, ""};
  return {pic.substr(0, e + 1), pic.substr(e + 2)};
}

std::string line_of(const std::string& header, const std::string& key) {
  std::istringstream in(header);
  std::string l;
  while (std::getline(in, l))
    if (l.rfind(key, 0) == 0) return l;
  return "";
}

TEST_F(RpictSequence, FramesFromViewLinesEqualSingleRenders) {
  std::string log;
  ASSERT_EQ(rpict(kOpts + "-S 1 -o " + (dir / "f%03d.hdr").string() + " -t 60 cornell.oct < " +
                      (dir / "views").string(),
                  &log),
            0)
      << log;
  // -t reports each frame's view as rpict does.
  EXPECT_NE(log.find("FRAME 2: -vtv -vp 0.5 0.05 0.5 -vd 0.1 1 0 -vu 0 0 1"), std::string::npos)
      << log;
  const char* single[] = {"-vp 0.45 0.05 0.5", "-vp 0.5 0.05 0.5 -vd 0.1 1 0",
                          "-vp 0.55 0.05 0.45 -vd 0.1 1 0"};
  for (int n = 1; n <= 3; ++n) {
    ASSERT_TRUE(fs::exists(frame(n))) << n;
    auto [head, data] = split(read_file(frame(n)));
    EXPECT_EQ(head.rfind("#?RADIANCE\n", 0), 0u);
    EXPECT_EQ(line_of(head, "FRAME="), "FRAME=" + std::to_string(n));
    fs::path one = dir / ("single" + std::to_string(n) + ".hdr");
    ASSERT_EQ(rpict(kOpts + single[n - 1] + " -o " + one.string() + " cornell.oct", &log), 0)
        << log;
    auto [head1, data1] = split(read_file(one.string()));
    EXPECT_EQ(line_of(head, "VIEW="), line_of(head1, "VIEW=")) << n;
    EXPECT_EQ(line_of(head1, "FRAME="), "");
    EXPECT_FALSE(data.empty());
    EXPECT_EQ(data, data1) << "frame " << n << " differs from a single render of its view";
  }
  EXPECT_FALSE(fs::exists(frame(4)));
}

TEST_F(RpictSequence, ExistingFramesAreSkippedNeverOverwritten) {
  std::ofstream(frame(2)) << "keep me";
  std::string log;
  ASSERT_EQ(rpict(kOpts + "-S 1 -o " + (dir / "f%03d.hdr").string() + " cornell.oct < " +
                      (dir / "views").string(),
                  &log),
            0)
      << log;
  EXPECT_EQ(read_file(frame(2)), "keep me");
  ASSERT_TRUE(fs::exists(frame(3)));
  // Frame 3 still gets the view as changed by frame 2's line.
  EXPECT_NE(read_file(frame(3)).find("VIEW= -vtv -vp 0.55 0.05 0.45 -vd 0.1 1 0 "),
            std::string::npos);
}

TEST_F(RpictSequence, StdoutSequenceSharesTheLeadingHeaderLines) {
  std::string out = (dir / "all.hdr").string();
  std::string log;
  ASSERT_EQ(rpict(kOpts + "-S 7 cornell.oct < " + (dir / "views").string() + " > " + out, &log), 0)
      << log;
  std::string all = read_file(out);
  EXPECT_EQ(all.rfind("#?RADIANCE\n", 0), 0u);
  // One id line, one command line; FRAME=7, 8, 9 in order.
  EXPECT_EQ(all.find("#?RADIANCE", 1), std::string::npos);
  // Later frames start right after the previous frame's pixels.
  std::size_t f7 = all.find("\nFRAME=7\n"), f8 = all.find("FRAME=8\n"), f9 = all.find("FRAME=9\n");
  ASSERT_NE(f7, std::string::npos);
  ASSERT_NE(f8, std::string::npos);
  ASSERT_NE(f9, std::string::npos);
  EXPECT_LT(f7, f8);
  EXPECT_LT(f8, f9);
  EXPECT_EQ(all.find("SOFTWARE=", f7), std::string::npos);
}

TEST_F(RpictSequence, RecoverFrameSkipsEarlierViews) {
  // -r 2: frame 1's view line is skipped; frame 2 (not there yet) is a new output file.
  std::string log;
  ASSERT_EQ(rpict(kOpts + "-S 1 -r 2 -o " + (dir / "f%03d.hdr").string() + " cornell.oct < " +
                      (dir / "views").string(),
                  &log),
            0)
      << log;
  EXPECT_NE(log.find("new output file"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(frame(1)));
  EXPECT_TRUE(fs::exists(frame(2)));
  EXPECT_TRUE(fs::exists(frame(3)));
  EXPECT_NE(rpict(kOpts + "-S 3 -r 2 -o " + (dir / "f%03d.hdr").string() + " cornell.oct < " +
                      (dir / "views").string(),
                  &log),
            0);
  EXPECT_NE(log.find("recover frame less than start frame"), std::string::npos) << log;
}

TEST_F(RpictSequence, MotionBlurBlendsWithThePreviousView) {
  // A camera turning between two frames: -pm blurs frame 2 towards frame 1's view.
  std::ofstream(dir / "turn") << "VIEW= -vd 0 1 0\nVIEW= -vd 0.4 1 0\n";
  auto render = [&](const std::string& pm, const std::string& sub) {
    fs::create_directories(dir / sub);
    std::string log;
    EXPECT_EQ(rpict(kOpts + pm + "-S 1 -o " + (dir / sub / "f%d.hdr").string() + " cornell.oct < " +
                        (dir / "turn").string(),
                    &log),
              0)
        << log;
    return split(read_file((dir / sub / "f2.hdr").string())).second;
  };
  std::string none = render("", "none"), zero = render("-pm 0 ", "zero"),
              blur = render("-pm 1 ", "blur"), again = render("-pm 1 ", "again");
  ASSERT_FALSE(none.empty());
  EXPECT_EQ(zero, none);
  EXPECT_NE(blur, none);
  EXPECT_EQ(blur, again); // -u-: the blur's random numbers repeat
}

TEST_F(RpictSequence, OctreeFromStandardInput) {
  fs::path a = dir / "file.hdr", b = dir / "stdin.hdr";
  std::string log;
  ASSERT_EQ(rpict(kOpts + "-o " + a.string() + " cornell.oct", &log), 0) << log;
  ASSERT_EQ(rpict(kOpts + "-o " + b.string() + " < cornell.oct", &log), 0) << log;
  auto [ha, da] = split(read_file(a.string()));
  auto [hb, db] = split(read_file(b.string()));
  EXPECT_FALSE(da.empty());
  EXPECT_EQ(da, db);
  EXPECT_EQ(line_of(hb, "oconv"), line_of(ha, "oconv")); // its header is still copied
  // A frozen octree as well.
  ASSERT_EQ(
      rpict(kOpts + "-o " + (dir / "frozen.hdr").string() + " < office_clear_frozen.oct", &log), 0)
      << log;
}

// Every line but the command line and the dates.
std::string without_dates(const std::string& pic) {
  std::istringstream in(pic);
  std::string l, out;
  while (std::getline(in, l))
    if (l.rfind("CAPDATE=", 0) && l.rfind("GMT=", 0) && l.find("rpict ") == std::string::npos)
      out += l + "\n";
  return out;
}

TEST_F(RpictSequence, PersistentServerRendersLaterSequences) {
  std::string pf = (dir / "pfile").string(), log;
  std::ofstream(dir / "one") << "VIEW= -vp 0.45 0.05 0.5\n";
  ASSERT_EQ(rpict(kOpts + "-S 1 -P " + pf + " cornell.oct < " + (dir / "one").string() + " > " +
                      (dir / "first.hdr").string(),
                  &log),
            0)
      << log;
  ASSERT_EQ(
      rpict("-P " + pf + " < " + (dir / "views").string() + " > " + (dir / "attached.hdr").string(),
            &log),
      0)
      << log;
  ASSERT_EQ(rpict(kOpts + "-S 1 cornell.oct < " + (dir / "views").string() + " > " +
                      (dir / "plain.hdr").string(),
                  &log),
            0)
      << log;
  std::string attached = read_file((dir / "attached.hdr").string());
  EXPECT_NE(attached.find("FRAME=3\n"), std::string::npos);
  EXPECT_EQ(without_dates(attached), without_dates(read_file((dir / "plain.hdr").string())));
  fs::remove(pf); // ends the server
}

TEST_F(RpictSequence, PersistArgumentErrors) {
  std::string pf = (dir / "pfile").string(), log;
  EXPECT_NE(rpict(kOpts + "-P " + pf + " cornell.oct < /dev/null", &log), 0);
  EXPECT_NE(log.find("persist option only for sequences"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(pf));
  EXPECT_NE(rpict(kOpts + "-S 1 -r x.hdr -P " + pf + " cornell.oct < /dev/null", &log), 0);
  EXPECT_NE(log.find("persist option used with recover file"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(pf));
  EXPECT_NE(rpict(kOpts + "-S 1 < /dev/null", &log), 0);
  EXPECT_NE(log.find("missing octree argument"), std::string::npos) << log;
}

} // namespace
