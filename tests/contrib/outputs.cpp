// rcontrib's output streams, byte for byte: files per modifier and per bin, shared files,
// standard output, the four formats, -c scaling, pictures, "!command" pipes and the errors.
// (The expected bytes were checked against Radiance 5.4a's rcontrib on the same settings.)
#include "radcl/contrib/output.h"
#include "radcl/util/error.h"

#include "files.h"
#include "temp_dir.h"
#include "warnings.h"

#include <bit>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdexcept>
#include <unistd.h>

using namespace radcl::contrib;
using radcl::test::read_file;

namespace {

const std::string kEndian =
    std::endian::native == std::endian::big ? "BigEndian=1\n" : "BigEndian=0\n";

// The header every stream of these tests starts with, around the stream's own lines.
std::string header(char format, const std::string& info) {
  std::string h = "#?RADIANCE\noconv scene.rad\nrcontrib -m sky\nSOFTWARE= radcl 1.2.3\n"
                  "CAPDATE= 2023:11:14 22:13:20\nGMT= 2023:11:14 22:13:20\nNCOMP=3\n" +
                  info;
  if (format == 'f' || format == 'd') h += kEndian;
  switch (format) {
  case 'a':
    return h + "FORMAT=ascii\n\n";
  case 'f':
    return h + "FORMAT=float\n\n";
  case 'd':
    return h + "FORMAT=double\n\n";
  default:
    return h + "FORMAT=32-bit_rle_rgbe\n\n";
  }
}

std::string floats(std::initializer_list<float> v) {
  return {reinterpret_cast<const char*>(std::data(v)), v.size() * sizeof(float)};
}
std::string doubles(std::initializer_list<double> v) {
  return {reinterpret_cast<const char*>(std::data(v)), v.size() * sizeof(double)};
}
std::string bytes(std::initializer_list<int> v) {
  std::string s;
  for (int b : v)
    s += static_cast<char>(b);
  return s;
}

void record(Outputs& out, const std::vector<double>& v, int rays = 0) {
  out.write_record(v, rays);
  out.end_record();
}

// Standard output goes to a file while this lives.
class StdoutToFile {
public:
  explicit StdoutToFile(const std::filesystem::path& path) {
    std::fflush(stdout);
    saved_ = dup(1);
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    close(fd);
  }
  ~StdoutToFile() { restore(); }
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stdout);
    dup2(saved_, 1);
    close(saved_);
    saved_ = -1;
  }

private:
  int saved_ = -1;
};

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const radcl::SystemError& e) {
    return std::string("system - ") + e.what();
  } catch (const radcl::FatalError& e) {
    return std::string("fatal - ") + e.what();
  }
  return "(no error)";
}

} // namespace

class ContribOutputs : public radcl::test::TempDir {
protected:
  void SetUp() override {
    TempDir::SetUp();
    setenv("TZ", "UTC", 1);
    tzset();
  }
  OutputSettings settings(char format) const {
    OutputSettings s;
    s.format = format;
    s.octree_header = {"#?RADIANCE", "oconv scene.rad", "FORMAT=Radiance_octree"};
    s.command = {"rcontrib", "-m", "sky"};
    s.software = "radcl 1.2.3";
    s.time = 1700000000;
    return s;
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  radcl::test::CapturedWarnings warnings;
};

TEST_F(ContribOutputs, AsciiFilePerModifier) {
  {
    Outputs out(settings('a'));
    EXPECT_EQ(out.add_modifier(path("%s.txt"), "sky", 2), 0);
    EXPECT_EQ(out.add_modifier(path("%s.txt"), "sun", 1), 1);
    EXPECT_EQ(out.bin0(0), 0);
    EXPECT_EQ(out.bin0(1), 0);
    record(out, {1, 2, 3, 0.5, 0.25, 0.125, 0, 0, 1e-7});
    record(out, {-1, 0, 0, 0, 0, 0, 123456789, 0, 0});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "sky.txt"), header('a', "MODIFIER=sky\nNCOLS=2\n") +
                                            "1.000000e+00\t2.000000e+00\t3.000000e+00\t"
                                            "5.000000e-01\t2.500000e-01\t1.250000e-01\t\n"
                                            "-1.000000e+00\t0.000000e+00\t0.000000e+00\t"
                                            "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n");
  EXPECT_EQ(read_file(dir / "sun.txt"), header('a', "MODIFIER=sun\nNCOLS=1\n") +
                                            "0.000000e+00\t0.000000e+00\t1.000000e-07\t\n"
                                            "1.234568e+08\t0.000000e+00\t0.000000e+00\t\n");
  EXPECT_TRUE(warnings.list().empty());
}

// One file per bin with -x -y: each a picture with its resolution string.
TEST_F(ContribOutputs, PicturePerBin) {
  OutputSettings s = settings('c');
  s.xres = 2;
  s.yres = 1;
  {
    Outputs out(s);
    out.add_modifier(path("%s_%02d.hdr"), "sky", 2);
    record(out, {1, 2, 3, 0, 0, 0});
    record(out, {0.5, 0.25, 0.125, 1, 2, 3});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "sky_00.hdr"), header('c', "MODIFIER=sky\nBIN=0\nNROWS=2\n") +
                                               "-Y 1 +X 2\n" +
                                               bytes({64, 128, 192, 130, 128, 64, 32, 128}));
  EXPECT_EQ(read_file(dir / "sky_01.hdr"), header('c', "MODIFIER=sky\nBIN=1\nNROWS=2\n") +
                                               "-Y 1 +X 2\n" +
                                               bytes({0, 0, 0, 0, 64, 128, 192, 130}));
}

// Pictures named by bin only: a later modifier's bins follow the earlier one's.
TEST_F(ContribOutputs, PictureBinsContinueAcrossModifiers) {
  OutputSettings s = settings('c');
  s.xres = 1;
  s.yres = 1;
  {
    Outputs out(s);
    out.add_modifier(path("p%d.hdr"), "sky", 2);
    out.add_modifier(path("p%d.hdr"), "sun", 1);
    EXPECT_EQ(out.bin0(1), 2);
    record(out, {0, 0, 0, 0, 0, 0, 1, 2, 3});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "p2.hdr"), header('c', "MODIFIER=sun\nBIN=2\nNROWS=1\n") +
                                           "-Y 1 +X 1\n" + bytes({64, 128, 192, 130}));
  EXPECT_TRUE(std::filesystem::exists(dir / "p0.hdr"));
  EXPECT_TRUE(warnings.list().empty());
}

// Without a picture, the same bin names are shared: each record has both modifiers' values.
TEST_F(ContribOutputs, BinFilesSharedWithoutPicture) {
  {
    Outputs out(settings('d'));
    out.add_modifier(path("b%d.dat"), "sky", 2);
    out.add_modifier(path("b%d.dat"), "sun", 1);
    EXPECT_EQ(out.bin0(1), 0);
    record(out, {1, 2, 3, 4, 5, 6, 7, 8, 9});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "b0.dat"),
            header('d', "BIN=0\nNCOLS=2\n") + doubles({1, 2, 3, 7, 8, 9}));
  EXPECT_EQ(read_file(dir / "b1.dat"),
            header('d', "MODIFIER=sky\nBIN=1\nNCOLS=1\n") + doubles({4, 5, 6}));
}

TEST_F(ContribOutputs, SharedFileKeepsRegistrationOrder) {
  {
    Outputs out(settings('f'));
    out.add_modifier(path("all.dat"), "sky", 2);
    out.add_modifier(path("all.dat"), "sun", 1);
    record(out, {1, 2, 3, 4, 5, 6, 7, 8, 9});
    record(out, {-1, -2, -3, -4, -5, -6, -7, -8, -9});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "all.dat"), header('f', "NCOLS=3\n") +
                                            floats({1, 2, 3, 4, 5, 6, 7, 8, 9}) +
                                            floats({-1, -2, -3, -4, -5, -6, -7, -8, -9}));
}

// A -fc picture given two values per pixel is still written, as a plain table, with a warning
// per extra value.
TEST_F(ContribOutputs, NotAValidPicture) {
  OutputSettings s = settings('c');
  s.xres = 2;
  s.yres = 1;
  {
    Outputs out(s);
    out.add_modifier(path("one.hdr"), "sky", 3);
    record(out, {1, 2, 3, 0, 0, 0, 0.5, 0.25, 0.125});
    out.finish();
  }
  const std::string msg = "output '" + path("one.hdr") + "' not a valid picture";
  EXPECT_EQ(warnings.list(), (std::vector<std::string>{msg, msg}));
  EXPECT_EQ(read_file(dir / "one.hdr"),
            header('c', "NROWS=2\nNCOLS=3\n") +
                bytes({64, 128, 192, 130, 0, 0, 0, 0, 128, 64, 32, 128}));
}

TEST_F(ContribOutputs, StandardOutput) {
  OutputSettings s = settings('a');
  s.yres = 2; // NROWS= with -y alone
  {
    StdoutToFile redirect(dir / "stdout");
    Outputs out(s);
    out.add_modifier(std::nullopt, "sky", 2);
    out.add_modifier(path("sun.txt"), "sun", 1);
    out.add_modifier(std::nullopt, "moon", 1);
    record(out, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
    record(out, {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "stdout"),
            header('a', "NROWS=2\nNCOLS=3\n") +
                "1.000000e+00\t2.000000e+00\t3.000000e+00\t4.000000e+00\t5.000000e+00\t"
                "6.000000e+00\t1.000000e+01\t1.100000e+01\t1.200000e+01\t\n"
                "0.000000e+00\t0.000000e+00\t0.000000e+00\t0.000000e+00\t0.000000e+00\t"
                "0.000000e+00\t0.000000e+00\t0.000000e+00\t1.000000e+00\t\n");
  EXPECT_EQ(read_file(dir / "sun.txt"), header('a', "MODIFIER=sun\nNROWS=2\nNCOLS=1\n") +
                                            "7.000000e+00\t8.000000e+00\t9.000000e+00\t\n"
                                            "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n");
}

// One value per record on standard output with -x -y: a picture.
TEST_F(ContribOutputs, StandardOutputPicture) {
  OutputSettings s = settings('c');
  s.xres = 2;
  s.yres = 1;
  {
    StdoutToFile redirect(dir / "stdout");
    Outputs out(s);
    out.add_modifier(std::nullopt, "sky", 1);
    record(out, {1, 2, 3});
    record(out, {0, 0, 0});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "stdout"),
            header('c', "NROWS=2\n") + "-Y 1 +X 2\n" + bytes({64, 128, 192, 130, 0, 0, 0, 0}));
}

TEST_F(ContribOutputs, NoHeader) {
  OutputSettings s = settings('d');
  s.header = false;
  s.xres = 1;
  s.yres = 2; // the resolution string comes all the same
  {
    Outputs out(s);
    out.add_modifier(path("sky.dat"), "sky", 1);
    record(out, {1, 2, 3});
    record(out, {4, 5, 6});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "sky.dat"), "-Y 2 +X 1\n" + doubles({1, 2, 3, 4, 5, 6}));
}

// -c: records hold sums over the rays, written divided by their count.
TEST_F(ContribOutputs, AccumulatedRecordsAreAveraged) {
  for (char format : {'a', 'f', 'd', 'c'}) {
    OutputSettings s = settings(format);
    s.accumulate = 3;
    s.header = false;
    const std::string file = path(std::string("avg_") + format);
    {
      Outputs out(s);
      out.add_modifier(file, "sky", 1);
      record(out, {3, 6, 0.3});
      record(out, {1, 2, 3}, 2); // a final partial record: divided by its 2 rays
      out.finish();
    }
    const double third = 1.0 / 3;
    std::string expected;
    switch (format) {
    case 'a':
      expected = "1.000000e+00\t2.000000e+00\t1.000000e-01\t\n"
                 "5.000000e-01\t1.000000e+00\t1.500000e+00\t\n";
      break;
    case 'f': // rounded to float, then scaled in float
      expected = floats({1, 2, static_cast<float>(static_cast<float>(0.3) * third), 0.5f, 1, 1.5f});
      break;
    case 'd':
      expected = doubles({3 * third, 6 * third, 0.3 * third, 0.5, 1, 1.5});
      break;
    case 'c':
      expected = bytes({64, 128, 6, 130, 64, 128, 192, 129});
      break;
    }
    EXPECT_EQ(read_file(file), expected) << format;
  }
}

// -c 0: one record of everything, so no -x -y (Radiance's override_options()).
TEST_F(ContribOutputs, SingleRecordIgnoresResolution) {
  OutputSettings s = settings('a');
  s.accumulate = 0;
  s.xres = 2;
  s.yres = 2;
  {
    Outputs out(s);
    out.add_modifier(path("sky.txt"), "sky", 1);
    record(out, {4, 5, 6});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "sky.txt"), header('a', "MODIFIER=sky\nNCOLS=1\n") +
                                            "4.000000e+00\t5.000000e+00\t6.000000e+00\t\n");
}

TEST_F(ContribOutputs, PipeToCommand) {
  const std::string target = path("piped.txt");
  {
    Outputs out(settings('a'));
    out.add_modifier("!cat > " + path("%s.txt"), "piped", 1);
    record(out, {1, 2, 3});
    out.finish(); // pclose() waits for cat
  }
  EXPECT_EQ(read_file(target), header('a', "MODIFIER=piped\nNCOLS=1\n") +
                                   "1.000000e+00\t2.000000e+00\t3.000000e+00\t\n");
}

TEST_F(ContribOutputs, ExistingFileRefused) {
  radcl::test::write_file(dir / "sky.dat", "old");
  Outputs out(settings('a'));
  EXPECT_EQ(error_of([&] { out.add_modifier(path("%s.dat"), "sky", 1); }),
            "system - cannot open '" + path("sky.dat") + "' for writing: File exists");
}

TEST_F(ContribOutputs, ForceOpenOverwrites) {
  radcl::test::write_file(dir / "sky.dat", "old contents, longer than the new");
  OutputSettings s = settings('d');
  s.force_open = true;
  s.header = false;
  {
    Outputs out(s);
    out.add_modifier(path("sky.dat"), "sky", 1);
    record(out, {1, 2, 3});
    out.finish();
  }
  EXPECT_EQ(read_file(dir / "sky.dat"), doubles({1, 2, 3}));
}

// Neither -r (the files are to be recovered) nor a command checks for an existing file.
TEST_F(ContribOutputs, ExistingFileAllowedForRecoverAndCommands) {
  radcl::test::write_file(dir / "sky.dat", "old");
  OutputSettings s = settings('f');
  s.recover = true;
  EXPECT_NO_THROW(Outputs(s).add_modifier(path("sky.dat"), "sky", 1));
  const std::string cwd = std::filesystem::current_path().string();
  std::filesystem::current_path(dir);
  radcl::test::write_file(dir / "!cat", "a file named like the command");
  EXPECT_EQ(error_of([&] { Outputs(settings('a')).add_modifier("!cat", "sky", 1); }), "(no error)");
  std::filesystem::current_path(cwd);
}

// Files open on first use: a name that cannot be created fails at the first record.
TEST_F(ContribOutputs, CannotOpen) {
  Outputs out(settings('a'));
  const std::string name = path("missing/sky.txt");
  out.add_modifier(path("missing/%s.txt"), "sky", 1);
  EXPECT_EQ(error_of([&] {
              out.write_record(std::vector<double>{1, 2, 3});
            }),
            "system - cannot open '" + name + "' for writing: No such file or directory");
}

TEST_F(ContribOutputs, WriteError) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  OutputSettings s = settings('a');
  s.force_open = true;
  s.xres = 1; // flush every record
  Outputs out(s);
  out.add_modifier("/dev/full", "sky", 1);
  EXPECT_EQ(error_of([&] {
              record(out, {1, 2, 3});
            }),
            "system - write error on file '/dev/full': No space left on device");
}

TEST_F(ContribOutputs, CommandFailureOnClose) {
  {
    Outputs out(settings('a'));
    out.add_modifier("!cat > /dev/null; exit 3", "sky", 1);
    record(out, {1, 2, 3});
    EXPECT_EQ(error_of([&] { out.finish(); }), "system - error closing output stream");
  }
  EXPECT_TRUE(warnings.list().empty()); // closed once, by finish()
  {
    Outputs out(settings('a'));
    out.add_modifier("!cat > /dev/null; exit 3", "sky", 1);
    record(out, {1, 2, 3});
  } // without finish(): the destructor closes and warns
  EXPECT_EQ(warnings.list(), std::vector<std::string>{"error closing output stream"});
}

TEST_F(ContribOutputs, MisuseIsAnInternalError) {
  OutputSettings s = settings('x');
  EXPECT_THROW(Outputs{s}, std::invalid_argument);
  Outputs out(settings('a'));
  EXPECT_THROW(out.add_modifier(path("a"), "sky", 0), std::invalid_argument);
  out.add_modifier(path("a"), "sky", 2);
  EXPECT_THROW(out.write_record(std::vector<double>{1, 2, 3}), std::invalid_argument);
}
