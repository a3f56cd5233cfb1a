// Lookups in Radiance's own irradiance cache: rtrace -af on a copy of the .amb file Radiance
// 5.4a wrote for office_clear_default, with the same options, must give Radiance's sensor
// values (the records were made at those sensors, so nearly every value is a lookup).
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

#include "radcl/ambient/ambient_file.h"
#include "reference_data.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::run_command;

TEST(GoldenAmbientCache, OfficeClearDefaultFromRadiancesCache) {
  fs::path amb = fs::temp_directory_path() / ("radcl-oc-" + std::to_string(::getpid()) + ".amb");
  fs::path out = fs::temp_directory_path() / ("radcl-oc-" + std::to_string(::getpid()) + ".txt");
  fs::copy_file(radcl::test::data("results/office_clear_default.amb"), amb,
                fs::copy_options::overwrite_existing);
  std::string log;
  int rc = run_command("cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                           "/rtrace -h -I -ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3 -af " +
                           amb.string() + " office_clear.oct < office_grid.pts > " + out.string(),
                       &log);
  ASSERT_EQ(rc, 0) << log;
  auto ours = radcl::test::read_rgb(out.string());
  auto ref = radcl::test::read_rgb(radcl::test::data("results/office_clear_default.txt"));
  ASSERT_EQ(ours.size(), ref.size());
  ASSERT_EQ(ref.size(), 77u);
  double mean = 0, worst = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    double a = radcl::test::lux(ours[i]), b = radcl::test::lux(ref[i]);
    ASSERT_GT(b, 0);
    double e = std::fabs(a - b) / b;
    EXPECT_LE(e, 0.02) << "sensor " << i << ": " << a << " vs " << b;
    mean += e / ref.size();
    worst = std::max(worst, e);
  }
  RecordProperty("mean_rel", std::to_string(mean));
  RecordProperty("max_rel", std::to_string(worst));
  // The copy still loads whole (nothing torn was appended).
  radcl::ambient::AmbientFile f;
  EXPECT_GE(f.open(amb.string(), {}).size(), 2253u);
  f.close();
  fs::remove(amb);
  fs::remove(out);
}
