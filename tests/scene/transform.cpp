// parse_transform / Transform against xform's definition (scene-format.md §1.3).
#include "radcl/scene/transform.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "radcl/util/error.h"

using radcl::FatalError;
using radcl::scene::parse_transform;
using radcl::scene::Transform;
using radcl::scene::transform_prefix;
using V = std::array<double, 3>;

namespace {

std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> w;
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t j = s.find(' ', i);
    if (j == std::string::npos) j = s.size();
    if (j > i) w.push_back(s.substr(i, j - i));
    i = j + 1;
  }
  return w;
}

Transform xf(const std::string& s) {
  return parse_transform(words(s));
}

void expect_near(const V& a, const V& b) {
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(a[i], b[i], 1e-12) << "component " << i;
}

} // namespace

TEST(Transform, EmptyIsIdentity) {
  Transform t = parse_transform({});
  EXPECT_TRUE(t.is_identity());
  EXPECT_EQ(t.scale, 1.0);
  EXPECT_TRUE(parse_transform({"x.oct"}, 1).is_identity());
}

TEST(Transform, Translate) {
  Transform t = xf("-t 1 2 3");
  expect_near(t.point({1, 1, 1}), {2, 3, 4});
  expect_near(t.vector({1, 1, 1}), {1, 1, 1}); // vectors ignore translation
  EXPECT_EQ(t.m[3][0], 1);                     // row-vector convention: translation in the 4th row
  EXPECT_EQ(t.m[3][2], 3);
}

TEST(Transform, RotationsAreCounterClockwiseFromPositiveAxis) {
  expect_near(xf("-rx 90").point({0, 1, 0}), {0, 0, 1}); // y -> z
  expect_near(xf("-ry 90").point({0, 0, 1}), {1, 0, 0}); // z -> x
  expect_near(xf("-rz 90").point({1, 0, 0}), {0, 1, 0}); // x -> y
  Transform t = xf("-rx 30");
  double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  expect_near(t.point({0, 2, 3}), {0, 2 * c - 3 * s, 2 * s + 3 * c});
}

TEST(Transform, OptionsApplyInOrder) {
  expect_near(xf("-t 1 0 0 -rz 90").point({0, 0, 0}), {0, 1, 0});
  expect_near(xf("-rz 90 -t 1 0 0").point({0, 0, 0}), {1, 0, 0});
  expect_near(xf("-s 2 -t 1 0 0").point({1, 1, 1}), {3, 2, 2});
  expect_near(xf("-t 1 0 0 -s 2").point({1, 1, 1}), {4, 2, 2});
}

TEST(Transform, ScaleAndMirrors) {
  Transform t = xf("-s 2 -s 1.5");
  EXPECT_DOUBLE_EQ(t.scale, 3);
  expect_near(t.point({1, 0, 0}), {3, 0, 0});
  expect_near(xf("-mx").point({1, 2, 3}), {-1, 2, 3});
  expect_near(xf("-my").point({1, 2, 3}), {1, -2, 3});
  expect_near(xf("-mz").point({1, 2, 3}), {1, 2, -3});
  EXPECT_DOUBLE_EQ(xf("-mx -s 2").scale, 2);  // the scale is the absolute value
  EXPECT_DOUBLE_EQ(xf("-s -0.5").scale, 0.5); // negative factor: a point reflection
  expect_near(xf("-s -0.5").point({2, 4, 6}), {-1, -2, -3});
}

TEST(Transform, IterationRepeatsTheFollowingGroup) {
  // Before the first -i: once; each group after -i N: N times.
  expect_near(xf("-t 1 0 0 -i 3 -t 0 1 0").point({0, 0, 0}), {1, 3, 0});
  expect_near(xf("-i 4 -rz 90 -t 1 0 0").point({0, 0, 0}), {0, 0, 0}); // a square walk
  expect_near(xf("-i 2 -t 1 0 0 -i 3 -t 0 0 1").point({0, 0, 0}), {2, 0, 3});
  expect_near(xf("-t 5 0 0 -i 0 -t 1 0 0").point({0, 0, 0}), {5, 0, 0});
  EXPECT_DOUBLE_EQ(xf("-i 3 -s 2").scale, 8);
  expect_near(xf("-i 3 -rz 30").point({1, 0, 0}), {0, 1, 0});
  // Huge counts (done by squaring) give the same result as repeating.
  expect_near(xf("-i 1000000 -t 1 0 0.5").point({0, 0, 0}), {1e6, 0, 5e5});
  EXPECT_NEAR(xf("-i 5000 -s 1.0001").scale, std::pow(1.0001, 5000), 1e-11);
}

TEST(Transform, BadTransforms) {
  for (const char* bad : {"-t 1 2", "-t 1 2 x", "-rx", "-rw 3", "-tx 1 2 3", "-q", "foo", "-s 0",
                          "-t 1 2 3 -s 0", "-i", "-i 1.5 -t 1 1 1", "-rz nan", "-s inf",
                          "-t 0x1 0 0", "-mx 1", "-mq", "-t 1 2 3 extra"}) {
    EXPECT_THROW(xf(bad), FatalError) << bad;
    try {
      xf(bad);
    } catch (const FatalError& e) {
      EXPECT_STREQ(e.what(), "bad transform");
    }
  }
}

TEST(Transform, PrefixStopsWhereXformStops) {
  Transform t;
  auto w = words("name -t 1 2 3 -s 0 -t 4 5 6");
  EXPECT_EQ(transform_prefix(w, 1, t), 5u); // "-s 0" ends it and is not consumed
  expect_near(t.point({0, 0, 0}), {1, 2, 3});
  w = words("-rz 90 plain");
  EXPECT_EQ(transform_prefix(w, 0, t), 2u);
  w = words("-t 1 2 3 -mz");
  EXPECT_EQ(transform_prefix(w, 0, t), w.size());
  // Numbers accept Radiance's real forms.
  w = words("-t +1. .5 -2e-1");
  EXPECT_EQ(transform_prefix(w, 0, t), w.size());
  expect_near(t.point({0, 0, 0}), {1, 0.5, -0.2});
}

TEST(Transform, InverseUndoesTheTransform) {
  Transform t = xf("-rx 17 -t 1 -2 3 -s 2.5 -ry -40 -mz -i 2 -rz 13 -t 0.1 0.2 0.3");
  Transform inv = t.inverse();
  V p{0.3, -1.7, 2.9};
  expect_near(inv.point(t.point(p)), p);
  expect_near(t.point(inv.point(p)), p);
  expect_near(inv.vector(t.vector(p)), p);
  EXPECT_DOUBLE_EQ(t.scale, 2.5);
  EXPECT_DOUBLE_EQ(inv.scale, 1 / 2.5);
  // The inverse of a translation is the opposite translation.
  expect_near(xf("-t 1 2 3").inverse().point({0, 0, 0}), {-1, -2, -3});
  EXPECT_FALSE(t.is_identity());
}
