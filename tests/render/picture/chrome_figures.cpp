// Chrome figures reflecting a luminaire (issue 54 point 4): lathed smooth meshes (vertex
// normals) of mirror-like metal around a cylindrical view, lit by a fixture whose light follows
// an asymmetric brightdata distribution (scenes/chrome_figures.rad). The fixture's reflections
// land where Radiance's rpict puts them only if each triangle is shaded with its interpolated
// normal, as Radiance's o_mesh does: with the facets' own normals the picture's relative RMS
// difference from Radiance's is 38 (the reflections spread over whole facets).
#include "radcl/luminance.h"
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "radcl/image/picture.h"
#include "temp_dir.h"
#include "test_env.h"

using namespace radcl;
namespace fs = std::filesystem;

namespace {

std::vector<double> luminance(const image::Picture& p) {
  std::vector<double> v;
  for (const auto& c : p.colors())
    v.push_back(radcl::bright(c));
  return v;
}

} // namespace

// Deterministic settings (no jitter, one ray a pixel, sources unsplit): Radiance's picture
// (results/chrome_figures_vtc.hdr) and radcl's agree pixel for pixel; the bound leaves room
// for float rounding only.
TEST(ChromeFigures, ReflectionsOfTheFixtureAsRadiance) {
  const test::TempFolder tmp("chrome");
  const fs::path out = tmp / "out.hdr";
  std::string log;
  const int rc = test::run_command(
      "cd " + test::data("scenes") + " && " + test::bin_dir() +
          "/rpict -vtc -vp 0 0 0.5 -vd 1 0 0 -vu 0 0 1 -vh 360 -vv 50 -x 256 -y 52 -ab 0 -pj 0 "
          "-ps 1 -dj 0 -ds 0 -o " +
          out.string() + " chrome_figures.rad",
      &log);
  ASSERT_EQ(rc, 0) << log;
  const std::vector<double> ours = luminance(image::read_picture(out.string()));
  const std::vector<double> ref =
      luminance(image::read_picture(test::data("results/chrome_figures_vtc.hdr")));
  ASSERT_EQ(ours.size(), ref.size());
  double mean = 0, sq = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    mean += ref[i] / ref.size();
    sq += (ours[i] - ref[i]) * (ours[i] - ref[i]) / ref.size();
  }
  EXPECT_LT(std::sqrt(sq) / mean, 0.01);
}
