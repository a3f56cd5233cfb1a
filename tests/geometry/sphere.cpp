// Spheres and bubbles against analytic answers.
#include <gtest/gtest.h>

#include "radcl/util/error.h"
#include "scene_fixture.h"

namespace radcl::geometry {
namespace {

using test::SceneMaker;

constexpr double kTol = 1e-12;

SceneGeometry unit_sphere(scene::ObjectType type = RC_OBJ_SPHERE, double r = 1) {
  SceneMaker m;
  const auto mat = m.material();
  m.add(type, "ball", {0, 0, 0, r}, mat);
  return SceneGeometry(m.loaded());
}

void expect_vec(const Vec3d& a, const Vec3d& b, double tol = kTol) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

TEST(Sphere, FromOutside) {
  auto g = unit_sphere();
  auto h = g.intersect({-5, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 4, kTol);
  expect_vec(h->point, {-1, 0, 0});
  expect_vec(h->normal, {-1, 0, 0});
  EXPECT_TRUE(h->front);
  EXPECT_EQ(h->object, 1);
  EXPECT_EQ(h->instance, -1);
  EXPECT_EQ(g.counts().spheres, 1u);
}

TEST(Sphere, UnnormalisedDirectionGivesDistance) {
  auto g = unit_sphere();
  auto h = g.intersect({-5, 0, 0}, {3, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 4, kTol);
}

TEST(Sphere, FromInsideHitsBack) {
  auto g = unit_sphere();
  auto h = g.intersect({0.5, 0, 0}, {0, 1, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, std::sqrt(0.75), kTol);
  expect_vec(h->normal, {0.5, std::sqrt(0.75), 0});
  EXPECT_FALSE(h->front);
}

TEST(Sphere, BubbleNormalInward) {
  auto g = unit_sphere(RC_OBJ_BUBBLE);
  auto h = g.intersect({-5, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(h);
  expect_vec(h->normal, {1, 0, 0});
  EXPECT_FALSE(h->front);
  auto in = g.intersect({0, 0, 0}, {0, 0, 1});
  ASSERT_TRUE(in);
  EXPECT_NEAR(in->t, 1, kTol);
  EXPECT_TRUE(in->front);
  EXPECT_EQ(g.counts().bubbles, 1u);
}

TEST(Sphere, NegativeRadiusBecomesBubble) {
  std::string got;
  static std::string* sink = &got;
  set_warning_sink([](const std::string& m) { *sink += m; });
  auto g = unit_sphere(RC_OBJ_SPHERE, -2);
  set_warning_sink(nullptr);
  EXPECT_EQ(got, "negative radius for sphere \"ball\"");
  EXPECT_EQ(g.counts().bubbles, 1u);
  auto h = g.intersect({-5, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 3, kTol);
  expect_vec(h->normal, {1, 0, 0});
}

// oconv (Radiance 5.4a ot/sphere.c) warns "zero radius" and leaves the sphere out.
TEST(Sphere, ZeroRadiusIsSkipped) {
  SceneMaker m;
  m.add(RC_OBJ_SPHERE, "s", {0, 0, 0, 0}, m.material());
  SceneGeometry g(m.loaded());
  EXPECT_EQ(g.counts().skipped_degenerate, 1u);
  EXPECT_EQ(g.counts().spheres, 0u);
  EXPECT_FALSE(g.intersect({-5, 0, 0}, {1, 0, 0}));
  SceneMaker bad;
  bad.add(RC_OBJ_SPHERE, "s", {0, 0, 0}, bad.material());
  EXPECT_THROW(SceneGeometry(bad.loaded()), FatalError);
}

TEST(Sphere, Grazing) {
  auto g = unit_sphere();
  // Exactly tangent: the discriminant is exactly 0, Radiance counts a double root as a hit.
  auto h = g.intersect({-5, 1, 0}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 5, 1e-9);
  expect_vec(h->normal, {0, 1, 0}, 1e-9);
  EXPECT_FALSE(g.intersect({-5, 1 + 1e-9, 0}, {1, 0, 0}));
  auto just = g.intersect({-5, 1 - 1e-6, 0}, {1, 0, 0});
  ASSERT_TRUE(just);
  EXPECT_NEAR(just->t, 5 - std::sqrt(1 - (1 - 1e-6) * (1 - 1e-6)), 1e-9);
}

TEST(Sphere, StartingOnSurface) {
  auto g = unit_sphere();
  const double s = std::sqrt(1.0 / 3);
  const Vec3d p{s, s, s};
  // Leaving outwards: nothing. Going inwards: the far side, not the start point.
  EXPECT_FALSE(g.intersect(p, {1, 1, 1}));
  EXPECT_FALSE(g.occluded(p, {1, 1, 1}));
  auto h = g.intersect(p, {-1, -1, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 2, kTol);
  expect_vec(h->point, {-s, -s, -s});
  EXPECT_FALSE(h->front);
  // A hit point handed back by intersect() works as the next origin.
  auto h0 = g.intersect({-5, 0.3, 0.2}, {1, 0, 0});
  ASSERT_TRUE(h0);
  auto h1 = g.intersect(h0->point, {1, 0, 0});
  ASSERT_TRUE(h1);
  EXPECT_NEAR(h1->t, 2 * std::sqrt(1 - 0.13), 1e-12);
  EXPECT_FALSE(g.intersect(h1->point, {1, 0, 0}));
}

TEST(Sphere, IntervalAndOcclusion) {
  auto g = unit_sphere();
  EXPECT_FALSE(g.intersect({-5, 0, 0}, {1, 0, 0}, 0, 3.9));
  EXPECT_TRUE(g.intersect({-5, 0, 0}, {1, 0, 0}, 0, 4.1));
  auto far = g.intersect({-5, 0, 0}, {1, 0, 0}, 4.5);
  ASSERT_TRUE(far);
  EXPECT_NEAR(far->t, 6, kTol);
  EXPECT_TRUE(g.occluded({-5, 0, 0}, {1, 0, 0}, 0, 4.1));
  EXPECT_FALSE(g.occluded({-5, 0, 0}, {1, 0, 0}, 0, 3.9));
  EXPECT_FALSE(g.occluded({-5, 0, 0}, {-1, 0, 0}));
}

TEST(Sphere, NearestOfSeveral) {
  SceneMaker m;
  const auto mat = m.material();
  m.add(RC_OBJ_SPHERE, "a", {0, 0, 0, 1}, mat);
  m.add(RC_OBJ_SPHERE, "b", {3, 0, 0, 0.5}, mat);
  m.add(RC_OBJ_SPHERE, "hidden", {6, 0, 0, 0.5}, scene::kVoid);
  SceneGeometry g(m.loaded());
  EXPECT_EQ(g.counts().skipped_void, 1u);
  auto h = g.intersect({10, 0, 0}, {-1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_EQ(h->object, 2);
  EXPECT_NEAR(h->t, 6.5, kTol);
  auto h2 = g.intersect(h->point, {-1, 0, 0});
  ASSERT_TRUE(h2);
  EXPECT_EQ(h2->object, 2);
  EXPECT_NEAR(h2->t, 1, kTol);
}

TEST(Sphere, Batch) {
  auto g = unit_sphere();
  std::vector<Ray> rays;
  for (int i = 0; i < 1000; ++i) {
    const double y = -1.5 + 3.0 * i / 999;
    rays.push_back({{-5, y, 0}, {1, 0, 0}, 0, 1e300});
  }
  std::vector<std::optional<Hit>> hits(rays.size());
  std::vector<std::uint8_t> blocked(rays.size());
  g.intersect(rays, hits);
  g.occluded(rays, blocked);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const double y = rays[i].org[1];
    EXPECT_EQ(hits[i].has_value(), std::abs(y) <= 1) << y;
    EXPECT_EQ(blocked[i] != 0, std::abs(y) <= 1) << y;
    if (hits[i]) {
      EXPECT_NEAR(hits[i]->t, 5 - std::sqrt(1 - y * y), 1e-9);
    }
  }
}

} // namespace
} // namespace radcl::geometry
