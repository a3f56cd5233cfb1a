// rtrace's ray input (-fa/-ff/-fd), direction normalization and the -x/-y count/flush rules.
#include "radcl/options/ray_io.h"

#include "test_env.h"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace radcl::options;

namespace {

std::vector<std::pair<Vec3, Vec3>> read_all(std::istream& in, char fmt) {
  RayReader reader(in, fmt);
  std::vector<std::pair<Vec3, Vec3>> rays;
  Vec3 o, d;
  while (reader.read(o, d))
    rays.emplace_back(o, d);
  return rays;
}

std::vector<std::pair<Vec3, Vec3>> read_file(const std::string& name, char fmt) {
  std::ifstream in(radcl::test::data(name), std::ios::binary);
  EXPECT_TRUE(in) << name;
  return read_all(in, fmt);
}

} // namespace

TEST(RayInput, ReadsAllThreeFormats) {
  auto a = read_file("scenes/materials_rays.txt", 'a');
  auto f = read_file("scenes/materials_rays.f32", 'f');
  auto d = read_file("scenes/materials_rays.f64", 'd');
  ASSERT_EQ(a.size(), 160u);
  ASSERT_EQ(f.size(), 160u);
  ASSERT_EQ(d.size(), 160u);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a[i].first[k], d[i].first[k], 1e-5);
      EXPECT_NEAR(a[i].second[k], d[i].second[k], 1e-5);
      EXPECT_NEAR(f[i].second[k], d[i].second[k], 1e-6);
    }
}

// Radiance prints the normalized direction: reading the text rays, normalizing and writing
// "od" reproduces the first six columns of its -oodv output exactly.
TEST(RayInput, NormalizedDirectionsMatchRadiance) {
  auto rays = read_file("scenes/materials_rays.txt", 'a');
  std::ifstream ref(radcl::test::data("results/materials_plain_rays_odv.txt"));
  std::string line;
  for (auto& [o, d] : rays) {
    ASSERT_TRUE(std::getline(ref, line));
    double len = normalize_direction(d);
    EXPECT_GT(len, 0);
    std::string out;
    append_record(out, "od", RayOutput::empty(o, d), 'a');
    out.pop_back(); // newline
    EXPECT_EQ(out, line.substr(0, out.size()));
  }
}

TEST(RayInput, NormalizeDirection) {
  Vec3 v{3, 0, 4};
  EXPECT_DOUBLE_EQ(normalize_direction(v), 5);
  EXPECT_DOUBLE_EQ(v[0], 0.6);
  EXPECT_EQ(v[1], 0.0);
  EXPECT_DOUBLE_EQ(v[2], 0.8);
  Vec3 z{0, 0, 0};
  EXPECT_EQ(normalize_direction(z), 0.0); // a flush request
  Vec3 near{1.0000001, 0, 0};             // within 1e-6 of unit: Radiance's shortcut
  double d2 = near[0] * near[0];
  EXPECT_EQ(normalize_direction(near), 0.5 + 0.5 * d2);
  EXPECT_EQ(near[0], 1.0000001 * (2.0 - (0.5 + 0.5 * d2)));
}

TEST(RayInput, AsciiWords) {
  // Any whitespace separates; quotes are honoured; a non-number ends the input.
  std::istringstream in("0 0 0\n0 0 1  \t1 2 3 '4' \"5\" 6\n\n7 8 9 1 1 x 9 9 9 9 9 9");
  auto rays = read_all(in, 'a');
  ASSERT_EQ(rays.size(), 2u);
  EXPECT_EQ(rays[1].first, (Vec3{1, 2, 3}));
  EXPECT_EQ(rays[1].second, (Vec3{4, 5, 6}));
  // Words longer than 31 characters are split: the rest becomes the next word.
  std::istringstream longw("1 2 3 0 0 " + std::string(31, '1') + "2 4 5 6 7 8");
  rays = read_all(longw, 'a');
  ASSERT_EQ(rays.size(), 2u);
  EXPECT_EQ(rays[0].second[2], std::atof(std::string(31, '1').c_str()));
  EXPECT_EQ(rays[1].first, (Vec3{2, 4, 5}));
  // A partial ray at the end is dropped.
  std::istringstream partial("1 2 3 4 5 6 7 8");
  EXPECT_EQ(read_all(partial, 'a').size(), 1u);
  std::istringstream exp("1e1 -2E-1 +.5 1. 0 0");
  rays = read_all(exp, 'a');
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_EQ(rays[0].first, (Vec3{10, -0.2, 0.5}));
}

TEST(RayInput, BinaryPartialRay) {
  float f[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  std::istringstream in(std::string(reinterpret_cast<char*>(f), sizeof f));
  EXPECT_EQ(read_all(in, 'f').size(), 1u);
  double d[6] = {1, 2, 3, 0, 0, 0};
  std::istringstream in2(std::string(reinterpret_cast<char*>(d), sizeof d - 1));
  EXPECT_EQ(read_all(in2, 'd').size(), 0u);
}

TEST(RayFlow, Unlimited) {
  RayFlow flow(0, 0);
  EXPECT_EQ(flow.flush_interval(), 0);
  EXPECT_FALSE(flow.flush_request()); // nothing computed yet: no flush
  for (int i = 0; i < 100; ++i) {
    EXPECT_FALSE(flow.ray_done());
    EXPECT_FALSE(flow.record_done());
  }
  EXPECT_TRUE(flow.flush_request());
  EXPECT_FALSE(flow.flush_request());
  EXPECT_FALSE(flow.incomplete());
}

TEST(RayFlow, FlushIntervalWithoutY) {
  RayFlow flow(3, 0);
  EXPECT_EQ(flow.flush_interval(), 3);
  std::vector<bool> flushes;
  for (int i = 0; i < 7; ++i)
    flushes.push_back(flow.ray_done());
  EXPECT_EQ(flushes, (std::vector<bool>{false, false, true, false, false, true, false}));
  EXPECT_TRUE(flow.flush_request()); // restarts the interval
  EXPECT_FALSE(flow.ray_done());
  EXPECT_FALSE(flow.ray_done());
  EXPECT_TRUE(flow.ray_done());
}

TEST(RayFlow, XOneFlushesEveryRayAndCountsY) {
  RayFlow flow(1, 3);
  EXPECT_EQ(flow.flush_interval(), 1);
  EXPECT_TRUE(flow.ray_done());
  EXPECT_FALSE(flow.record_done());
  EXPECT_TRUE(flow.ray_done());
  EXPECT_FALSE(flow.record_done());
  EXPECT_TRUE(flow.ray_done());
  EXPECT_TRUE(flow.record_done());
  EXPECT_FALSE(flow.incomplete());
}

TEST(RayFlow, PictureCountsXTimesYWithoutPeriodicFlush) {
  RayFlow flow(4, 2);
  EXPECT_EQ(flow.flush_interval(), 0);
  int stops = 0;
  for (int i = 0; i < 8; ++i) {
    EXPECT_FALSE(flow.ray_done());
    stops += flow.record_done();
  }
  EXPECT_EQ(stops, 1);
  RayFlow short_input(4, 2);
  short_input.ray_done();
  short_input.record_done();
  EXPECT_TRUE(short_input.incomplete()); // "unexpected EOF on input"
  // Flush requests count as records.
  RayFlow only_y(0, 2);
  EXPECT_FALSE(only_y.flush_request());
  EXPECT_FALSE(only_y.record_done());
  EXPECT_TRUE(only_y.record_done());
}
