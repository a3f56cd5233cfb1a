// rpict end to end against Radiance 5.4a's pictures: deterministic direct-light views compared
// on 8x8-pixel blocks (sub-pixel jitter makes edges differ), and the header lines.
#include "radcl/luminance.h"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "radcl/image/picture.h"
#include "temp_dir.h"
#include "test_env.h"

using radcl::test::run_command;
namespace fs = std::filesystem;

namespace {

struct Rendered {
  radcl::image::Picture ours, ref;
};

// `seed` > 0: RADCL_SEED for -u+ renders.
Rendered render(const std::string& args, const std::string& octree, const std::string& ref,
                int seed = 0) {
  const radcl::test::TempFolder tmp("rpict");
  const fs::path out = tmp / (octree + ".hdr");
  std::string log;
  std::string env = seed > 0 ? "RADCL_SEED=" + std::to_string(seed) + " " : "";
  int rc = run_command("cd " + radcl::test::data("scenes") + " && " + env + radcl::test::bin_dir() +
                           "/rpict " + args + " -o " + out.string() + " " + octree,
                       &log);
  EXPECT_EQ(rc, 0) << log;
  Rendered r{radcl::image::read_picture(out.string()),
             radcl::image::read_picture(radcl::test::data("results/" + ref))};
  return r;
}

double lum(const radcl::image::Color& c) {
  return radcl::bright(c);
}

// Mean luminance of each 8x8 block.
std::vector<double> blocks(const std::vector<radcl::image::Color>& c, int width, int height) {
  std::vector<double> out;
  for (int by = 0; by + 8 <= height; by += 8)
    for (int bx = 0; bx + 8 <= width; bx += 8) {
      double s = 0;
      for (int y = by; y < by + 8; ++y)
        for (int x = bx; x < bx + 8; ++x)
          s += lum(c[std::size_t(y) * width + x]);
      out.push_back(s / 64);
    }
  return out;
}

// Relative block differences of `ours` (colours of a picture as large as the reference).
// Blocks in shadow (below a tenth of the picture's mean block) are compared relative to that
// mean, as the issue compares shadowed sensors relative to the grid's largest value (stricter
// here).
std::vector<double> block_errors(const std::vector<radcl::image::Color>& ours,
                                 const radcl::image::Picture& ref) {
  EXPECT_EQ(ours.size(), std::size_t(ref.width) * ref.height);
  std::vector<double> a = blocks(ours, ref.width, ref.height),
                      b = blocks(ref.colors(), ref.width, ref.height);
  double mean = 0;
  for (double v : b)
    mean += v / b.size();
  std::vector<double> err;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    err.push_back(std::fabs(a[i] - b[i]) / (b[i] >= 0.1 * mean ? b[i] : mean));
  return err;
}

std::vector<double> block_errors(const Rendered& r) {
  EXPECT_EQ(r.ours.width, r.ref.width);
  EXPECT_EQ(r.ours.height, r.ref.height);
  return block_errors(r.ours.colors(), r.ref);
}

double mean_of(const std::vector<double>& e) {
  double m = 0;
  for (double v : e)
    m += v / e.size();
  return m;
}

double fraction_within(const std::vector<double>& e, double tol) {
  return double(std::count_if(e.begin(), e.end(), [&](double v) { return v <= tol; })) / e.size();
}

} // namespace

TEST(GoldenRpict, CornellDirect) {
  Rendered r = render("-vf cornell.vf -x 256 -y 256 -ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ps 1",
                      "cornell.oct", "cornell_ab0_view.hdr");
  std::vector<double> e = block_errors(r);
  EXPECT_LE(mean_of(e), 0.01);
  EXPECT_GE(fraction_within(e, 0.03), 0.95);
}

TEST(GoldenRpict, MaterialsPlainDirectMean) {
  Rendered r = render("-vf materials.vf -x 384 -y 256 -ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ps 1",
                      "materials_plain.oct", "materials_plain_view_ab0.hdr");
  std::vector<double> e = block_errors(r);
  EXPECT_LE(mean_of(e), 0.01);
  RecordProperty("within3", std::to_string(fraction_within(e, 0.03)));
}

// Blocks against Radiance's expected picture. The shipped reference is one jittered ray per
// pixel (rpict -ps 1), so its edge blocks carry coin-toss noise: the mean of 16 Radiance 5.4a
// renders of the same command (-u+, tests/data/README.md) agrees with it on only 95.0% of blocks
// within 3%, and two single Radiance renders on 93-95%. The bounds are applied to that
// mean instead; against it no block of radcl's mean of 16 renders differs by more than 3.5
// standard errors (closing note of session 3).
TEST(GoldenRpict, MaterialsPlainDirectBlocks) {
  Rendered r = render("-vf materials.vf -x 384 -y 256 -ab 0 -dj 0 -ds 0.02 -dt 0 -dc 1 -ps 1",
                      "materials_plain.oct", "materials_plain_view_ab0_u16.hdr");
  std::vector<double> e = block_errors(r);
  EXPECT_LE(mean_of(e), 0.01);
  EXPECT_GE(fraction_within(e, 0.03), 0.95);
  RecordProperty("within3", std::to_string(fraction_within(e, 0.03)));
}

TEST(GoldenRpict, HeaderLinesAsRadiance) {
  Rendered r =
      render("-vf cornell.vf -x 64 -y 48 -ab 0 -ps 1", "cornell.oct", "cornell_ab0_view.hdr");
  // -vh 70 -vv 70 with -x 64 -y 48: square, 48 x 48.
  EXPECT_EQ(r.ours.width, 48);
  EXPECT_EQ(r.ours.height, 48);
  auto views = r.ours.header.views(), ref_views = r.ref.header.views();
  ASSERT_EQ(views.size(), 1u);
  EXPECT_EQ(views[0], ref_views.at(0));
  EXPECT_EQ(r.ours.header.format(), r.ref.header.format());
  EXPECT_EQ(r.ours.header.lines.at(0), "#?RADIANCE");
  EXPECT_EQ(r.ours.header.lines.at(1), r.ref.header.lines.at(1)); // oconv line from the octree
}
