// rcontrib end to end beyond the numbers' agreement with Radiance (golden_rcontrib.cpp): the
// same bytes for one seed whatever -n and the pipeline's sizes, -o files per modifier with
// their headers, -c records, pictures with -x -y, -r recovery of a cut file, and bad input.
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "reference_data.h"
#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

namespace {

namespace t = radcl::test;
using Rows = std::vector<std::vector<double>>;

Rows numbers(const std::string& text) {
  return t::parse_table(text);
}

t::ProgramRun rcontrib(const std::string& args, const std::string& env = "RADCL_SEED=3 ") {
  return t::Program("rcontrib")
      .env(env)
      .input(t::read_file(t::data("rcontrib/office_sensors12.pts")))
      .run(args);
}

const std::string kSuns = " -I -ab 0 -dc 1 -dt 0 -dj 0 -M office_suns.mod office_suns.oct";
const std::string kDome =
    " -I -ab 2 -ad 128 -lw 1e-4 -e MF:1 -f reinhart.cal -b rbin -bn Nrbins -m skyglow "
    "office_dome.oct";

} // namespace

TEST(RcontribOutputs, SameBytesWhateverTheSplit) {
  const t::ProgramRun a = rcontrib("-n 1 -h -faf" + kDome);
  ASSERT_EQ(a.rc, 0) << a.err;
  ASSERT_EQ(a.out.size(), 12u * 146 * 3 * sizeof(float));
  const t::ProgramRun b = rcontrib("-n 2 -h -faf" + kDome);
  const t::ProgramRun c = rcontrib("-n 2 -h -faf" + kDome,
                                   "RADCL_SEED=3 RADCL_CHUNK_RAYS=512 RADCL_GENERATION_RAYS=4096 ");
  // The GPU's path (the device's own memory) on PoCL.
  const t::ProgramRun g =
      rcontrib("-n 2 -h -faf" + kDome, "RADCL_SEED=3 RADCL_DEVICE_MEMORY=separate ");
  EXPECT_TRUE(a.out == b.out);
  EXPECT_TRUE(a.out == c.out);
  EXPECT_TRUE(a.out == g.out);
  const t::ProgramRun d = rcontrib("-n 2 -h -faf" + kDome, "RADCL_SEED=4 ");
  EXPECT_FALSE(a.out == d.out); // another seed, other draws
}

TEST(RcontribOutputs, FilePerModifierWithHeader) {
  t::TempFolder dir("rcontrib");
  const t::ProgramRun all = rcontrib("-h" + kSuns);
  ASSERT_EQ(all.rc, 0) << all.err;
  const Rows whole = numbers(all.out);
  ASSERT_EQ(whole.size(), 12u);
  const t::ProgramRun r = rcontrib("-o " + (dir.path() / "sun_%s.txt").string() + kSuns);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  for (int k = 1; k <= 6; ++k) {
    const std::string f = t::read_file(dir.path() / ("sun_solar" + std::to_string(k) + ".txt"));
    EXPECT_NE(f.find("MODIFIER=solar" + std::to_string(k) + "\n"), std::string::npos) << k;
    EXPECT_NE(f.find("NCOLS=1\n"), std::string::npos) << k;
    EXPECT_NE(f.find("NCOMP=3\n"), std::string::npos) << k;
    const Rows v = numbers(f);
    ASSERT_EQ(v.size(), 12u) << k;
    for (std::size_t i = 0; i < v.size(); ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(v[i][c], whole[i][3 * (k - 1) + c]) << k << " " << i;
  }
  // An existing file is not overwritten without -fo, as in Radiance.
  const t::ProgramRun again = rcontrib("-o " + (dir.path() / "sun_%s.txt").string() + kSuns);
  EXPECT_NE(again.rc, 0);
  EXPECT_NE(again.err.find("cannot open"), std::string::npos) << again.err;
}

TEST(RcontribOutputs, RecordsOfThreeRaysAreTheirMean) {
  const Rows one = numbers(rcontrib("-h" + kSuns).out);
  const t::ProgramRun r = rcontrib("-h -c 3" + kSuns);
  ASSERT_EQ(r.rc, 0) << r.err;
  const Rows three = numbers(r.out);
  ASSERT_EQ(three.size(), 4u);
  for (std::size_t rec = 0; rec < 4; ++rec)
    for (std::size_t j = 0; j < three[rec].size(); ++j) {
      const double mean = (one[3 * rec][j] + one[3 * rec + 1][j] + one[3 * rec + 2][j]) / 3;
      EXPECT_NEAR(three[rec][j], mean, 1e-6 * mean + 1e-12) << rec << " " << j;
    }
}

TEST(RcontribOutputs, PicturesWithResolution) {
  t::TempFolder dir("rcontrib");
  const t::ProgramRun r =
      rcontrib("-fac -x 4 -y 3 -o " + (dir.path() / "pic_%s.hdr").string() + kSuns);
  ASSERT_EQ(r.rc, 0) << r.err;
  const std::string p = t::read_file(dir.path() / "pic_solar1.hdr");
  const std::size_t end = p.find("\n\n-Y 3 +X 4\n");
  ASSERT_NE(end, std::string::npos) << p.substr(0, 400);
  EXPECT_NE(p.find("FORMAT=32-bit_rle_rgbe\n"), std::string::npos);
  EXPECT_EQ(p.size() - (end + 12), 12u * 4); // one RGBE pixel per sensor
}

TEST(RcontribOutputs, RecoversACutFile) {
  t::TempFolder dir("rcontrib");
  const std::string out = (dir.path() / "dc.f32").string();
  ASSERT_EQ(rcontrib("-faf -o " + out + kDome).rc, 0);
  const std::string full = t::read_file(out);
  const std::size_t record = 146 * 3 * sizeof(float);
  const std::size_t head = full.size() - 12 * record;
  t::write_file(out, full.substr(0, head + 5 * record + 100)); // cut inside the sixth record
  const t::ProgramRun r = rcontrib("-r -faf -o " + out + kDome);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(t::read_file(out) == full);
}

TEST(RcontribOutputs, BadInput) {
  t::ProgramRun r = rcontrib("-I office_dome.oct");
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("missing required modifier argument"), std::string::npos) << r.err;
  r = rcontrib("-b rbin -m skyglow office_dome.oct");
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("bin count"), std::string::npos) << r.err;
  r = rcontrib("-V+ -m wall_mat office_dome.oct");
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("-V+ for modifier 'wall_mat'"), std::string::npos) << r.err;
  r = rcontrib("-bn 4 -b 'undefined_thing' -m skyglow office_dome.oct");
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("undefined_thing"), std::string::npos) << r.err;
  r = rcontrib("-M no_such_file.mod office_dome.oct");
  EXPECT_NE(r.rc, 0);
  EXPECT_NE(r.err.find("cannot find modifier file"), std::string::npos) << r.err;
  r = rcontrib("-m skyglow");
  EXPECT_EQ(r.rc, 1);
  EXPECT_NE(r.err.find("missing octree argument"), std::string::npos) << r.err;
}

// -p before -f: reinhart.cal folds its constants from MF as it loads, and rbin sees MF=2.
TEST(RcontribOutputs, ParametersBeforeTheirFile) {
  const t::ProgramRun r = rcontrib("-h -I -ab 1 -ad 64 -p MF=2 -f reinhart.cal -bn Nrbins -b rbin "
                                   "-m skyglow office_dome.oct");
  ASSERT_EQ(r.rc, 0) << r.err;
  const Rows v = numbers(r.out);
  ASSERT_EQ(v.size(), 12u);
  EXPECT_EQ(v[0].size(), 578u * 3);
}
