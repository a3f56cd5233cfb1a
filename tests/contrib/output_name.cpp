// rcontrib's output names (ofname()) and the header every output starts with (printheader()).
#include "radcl/contrib/output.h"
#include "radcl/util/error.h"

#include <bit>
#include <cstdlib>
#include <ctime>
#include <gtest/gtest.h>

using namespace radcl::contrib;

namespace {

std::string name_of(const std::string& spec, const std::string& modifier, int bin, int& flags) {
  std::string name = "(untouched)";
  flags = output_name(spec, modifier, bin, name);
  return name;
}

} // namespace

TEST(OutputName, ModifierAndBinFields) {
  int flags;
  EXPECT_EQ(name_of("out.dat", "sky", 3, flags), "out.dat");
  EXPECT_EQ(flags, 0);
  EXPECT_EQ(name_of("%s.dat", "sky", 3, flags), "sky.dat");
  EXPECT_EQ(flags, kNamesModifier);
  EXPECT_EQ(name_of("bin%03d.dat", "sky", 3, flags), "bin003.dat");
  EXPECT_EQ(flags, kNamesBin);
  EXPECT_EQ(name_of("%s_%d.dat", "sky", 12, flags), "sky_12.dat");
  EXPECT_EQ(flags, kNamesModifier | kNamesBin);
  // The bin may come first: the arguments follow the fields' order.
  EXPECT_EQ(name_of("%d_%s.dat", "sky", 12, flags), "12_sky.dat");
  EXPECT_EQ(flags, kNamesModifier | kNamesBin);
}

TEST(OutputName, BinConversionsWidthsAndPercent) {
  int flags;
  EXPECT_EQ(name_of("b%i", "m", 26, flags), "b26");
  EXPECT_EQ(name_of("b%o", "m", 26, flags), "b32");
  EXPECT_EQ(name_of("b%x", "m", 26, flags), "b1a");
  EXPECT_EQ(name_of("b%X", "m", 26, flags), "b1A");
  EXPECT_EQ(name_of("b%4x", "m", 26, flags), "b  1a");
  EXPECT_EQ(name_of("[%6s]", "sky", 0, flags), "[   sky]");
  EXPECT_EQ(name_of("100%%_%s", "sky", 0, flags), "100%_sky");
  EXPECT_EQ(flags, kNamesModifier);
  EXPECT_EQ(name_of("!cat > %s.txt", "sun", 0, flags), "!cat > sun.txt");
}

TEST(OutputName, BadSpecs) {
  // Only width digits may sit between '%' and the conversion; one field of each kind.
  for (const char* spec : {"%s%s", "%d_%x", "%f", "out%", "%-3d", "%.2d", "%ld", "%c", "a%%%"}) {
    int flags;
    EXPECT_EQ(name_of(spec, "sky", 1, flags), "(untouched)") << spec;
    EXPECT_EQ(flags, -1) << spec;
  }
}

TEST(OutputName, BadSpecIsFatalAtRegistration) {
  Outputs out(OutputSettings{});
  try {
    out.add_modifier("x%q.dat", "sky", 1);
    FAIL() << "no error";
  } catch (const radcl::SystemError&) {
    FAIL() << "a user error, not a system error";
  } catch (const radcl::FatalError& e) {
    EXPECT_STREQ(e.what(), "bad output format 'x%q.dat'");
  }
}

class Header : public ::testing::Test {
protected:
  void SetUp() override {
    setenv("TZ", "UTC", 1); // CAPDATE= is local time
    tzset();
    s.octree_header = {"#?RADIANCE", "oconv scene.rad", "FORMAT=Radiance_octree"};
    s.command = {"rcontrib", "-o", "out %s.dat", "-e", "a=\"x\"", "-m", "sky"};
    s.software = "radcl 1.2.3";
    s.time = 1700000000; // 2023-11-14 22:13:20 UTC
  }
  OutputSettings s;
};

TEST_F(Header, AsciiWithStreamLines) {
  s.format = 'a';
  EXPECT_EQ(format_header(s, "MODIFIER=sky\nNCOLS=2\n"),
            "#?RADIANCE\n"
            "oconv scene.rad\n"
            "rcontrib -o \"out %s.dat\" -e 'a=\"x\"' -m sky\n"
            "SOFTWARE= radcl 1.2.3\n"
            "CAPDATE= 2023:11:14 22:13:20\n"
            "GMT= 2023:11:14 22:13:20\n"
            "NCOMP=3\n"
            "MODIFIER=sky\n"
            "NCOLS=2\n"
            "FORMAT=ascii\n"
            "\n");
}

TEST_F(Header, BinaryFormats) {
  const std::string endian =
      std::endian::native == std::endian::big ? "BigEndian=1\n" : "BigEndian=0\n";
  const std::string common = "#?RADIANCE\noconv scene.rad\n"
                             "rcontrib -o \"out %s.dat\" -e 'a=\"x\"' -m sky\n"
                             "SOFTWARE= radcl 1.2.3\n"
                             "CAPDATE= 2023:11:14 22:13:20\nGMT= 2023:11:14 22:13:20\n"
                             "NCOMP=3\nNROWS=4\n";
  s.format = 'f';
  EXPECT_EQ(format_header(s, "NROWS=4\n"), common + endian + "FORMAT=float\n\n");
  s.format = 'd';
  EXPECT_EQ(format_header(s, "NROWS=4\n"), common + endian + "FORMAT=double\n\n");
  s.format = 'c'; // pictures have no byte order
  EXPECT_EQ(format_header(s, "NROWS=4\n"), common + "FORMAT=32-bit_rle_rgbe\n\n");
}

// The stream's lines follow rcontrib's NCOMP=3 even when the octree's header has an NCOMP= line.
TEST_F(Header, OctreeHeaderWithNcomp) {
  s.octree_header = {"#?RADIANCE", "NCOMP=3"};
  s.command = {"rcontrib"};
  EXPECT_EQ(format_header(s, "NCOLS=1\n"), "#?RADIANCE\nNCOMP=3\nrcontrib\n"
                                           "SOFTWARE= radcl 1.2.3\n"
                                           "CAPDATE= 2023:11:14 22:13:20\n"
                                           "GMT= 2023:11:14 22:13:20\n"
                                           "NCOMP=3\nNCOLS=1\nFORMAT=ascii\n\n");
}
