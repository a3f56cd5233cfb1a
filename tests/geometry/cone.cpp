// Cones, cups, cylinders, tubes and rings against analytic answers, with Radiance's
// conversions and errors.
#include <gtest/gtest.h>

#include "radcl/util/error.h"
#include "scene_fixture.h"

namespace radcl::geometry {
namespace {

using test::SceneMaker;

constexpr double kTol = 1e-12;

void expect_vec(const Vec3d& a, const Vec3d& b, double tol = kTol) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

SceneGeometry one(scene::ObjectType type, std::vector<double> args) {
  SceneMaker m;
  m.add(type, "s", std::move(args), m.material());
  return SceneGeometry(m.loaded());
}

std::string fatal_message(scene::ObjectType type, std::vector<double> args) {
  try {
    one(type, std::move(args));
  } catch (const FatalError& e) {
    return e.what();
  }
  return "";
}

TEST(Cylinder, OutsideInsideAndEnds) {
  auto g = one(RC_OBJ_CYLINDER, {0, 0, 0, 0, 0, 2, 1});
  auto h = g.intersect({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 4, kTol);
  expect_vec(h->normal, {-1, 0, 0});
  EXPECT_TRUE(h->front);
  auto in = g.intersect({0, 0, 1}, {0, 1, 0});
  ASSERT_TRUE(in);
  EXPECT_NEAR(in->t, 1, kTol);
  expect_vec(in->normal, {0, 1, 0});
  EXPECT_FALSE(in->front);
  // Open ends: along the axis nothing; above the top nothing.
  EXPECT_FALSE(g.intersect({0, 0, -5}, {0, 0, 1}));
  EXPECT_FALSE(g.intersect({-5, 0, 2.001}, {1, 0, 0}));
  // Through the open end from above, hitting the inside of the wall.
  auto through = g.intersect({0, 0, 3}, {1, 0, -1});
  ASSERT_TRUE(through);
  EXPECT_NEAR(through->t, std::sqrt(2.0), kTol);
  expect_vec(through->point, {1, 0, 2});
  EXPECT_FALSE(through->front);
  EXPECT_EQ(g.counts().cylinders, 1u);
}

TEST(Cylinder, GrazingAndOnSurface) {
  auto g = one(RC_OBJ_CYLINDER, {0, 0, 0, 0, 0, 2, 1});
  auto h = g.intersect({-5, 1, 0.5}, {1, 0, 0}); // tangent
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 5, 1e-9);
  expect_vec(h->normal, {0, 1, 0}, 1e-9);
  EXPECT_FALSE(g.intersect({-5, 1 + 1e-9, 0.5}, {1, 0, 0}));
  // From the wall: outwards nothing, inwards the opposite wall.
  EXPECT_FALSE(g.intersect({1, 0, 1}, {1, 0, 0}));
  auto across = g.intersect({1, 0, 1}, {-1, 0, 0});
  ASSERT_TRUE(across);
  EXPECT_NEAR(across->t, 2, kTol);
}

TEST(Cylinder, TubeAndNegativeRadius) {
  auto tube = one(RC_OBJ_TUBE, {0, 0, 0, 0, 0, 2, 1});
  auto h = tube.intersect({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(h);
  expect_vec(h->normal, {1, 0, 0});
  EXPECT_FALSE(h->front);
  auto neg = one(RC_OBJ_CYLINDER, {0, 0, 0, 0, 0, 2, -1});
  EXPECT_EQ(neg.counts().tubes, 1u);
  // Radiance 5.4a ignores a zero radius with a warning (common/cone.c).
  EXPECT_EQ(fatal_message(RC_OBJ_CYLINDER, {0, 0, 0, 0, 0, 2, 0}), "");
  EXPECT_EQ(one(RC_OBJ_CYLINDER, {0, 0, 0, 0, 0, 2, 0}).counts().skipped_degenerate, 1u);
  EXPECT_EQ(fatal_message(RC_OBJ_CYLINDER, {0, 0, 0, 0, 0, 2}),
            "bad # arguments for cylinder \"s\"");
}

TEST(Cone, PointedCone) {
  // Apex at z=2, base radius 1 at z=0: side at 45 degrees.
  auto g = one(RC_OBJ_CONE, {0, 0, 0, 0, 0, 2, 2, 0});
  auto h = g.intersect({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 4, kTol);
  const double s = std::sqrt(0.5);
  expect_vec(h->normal, {-s, 0, s});
  EXPECT_TRUE(h->front);
  // Beyond the apex the other nappe is not part of the surface.
  EXPECT_FALSE(g.intersect({-5, 0, 3}, {1, 0, 0}));
  EXPECT_EQ(g.counts().cones, 1u);
}

TEST(Cone, RadiiOrderAndCup) {
  // Same frustum given both ways round: same hits.
  auto a = one(RC_OBJ_CONE, {0, 0, 0, 0, 0, 1, 1, 2});
  auto b = one(RC_OBJ_CONE, {0, 0, 1, 0, 0, 0, 2, 1});
  for (auto* g : {&a, &b}) {
    auto h = g->intersect({-5, 0, 0.5}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.5, kTol);
    const double s = std::sqrt(0.5);
    expect_vec(h->normal, {-s, 0, -s});
  }
  auto cup = one(RC_OBJ_CUP, {0, 0, 0, 0, 0, 1, 1, 2});
  auto h = cup.intersect({-5, 0, 0.5}, {1, 0, 0});
  ASSERT_TRUE(h);
  const double s = std::sqrt(0.5);
  expect_vec(h->normal, {s, 0, s});
  EXPECT_FALSE(h->front);
  auto neg = one(RC_OBJ_CONE, {0, 0, 0, 0, 0, 1, -1, -2});
  EXPECT_EQ(neg.counts().cups, 1u);
}

TEST(Cone, EqualRadiiIsCylinder) {
  auto g = one(RC_OBJ_CONE, {0, 0, 0, 0, 0, 2, 1, 1});
  EXPECT_EQ(g.counts().cylinders, 1u);
  auto h = g.intersect({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 4, kTol);
  auto cup = one(RC_OBJ_CUP, {0, 0, 0, 0, 0, 2, 1, 1});
  EXPECT_EQ(cup.counts().tubes, 1u);
}

// Radiance 5.4a (common/cone.c): illegal radii are a warning and the surface is ignored;
// a negative ring radius is fatal.
TEST(Cone, IllegalRadii) {
  for (const auto& [type, args] : std::vector<std::pair<scene::ObjectType, std::vector<double>>>{
           {RC_OBJ_CONE, {0, 0, 0, 0, 0, 1, 0, 0}},
           {RC_OBJ_CONE, {0, 0, 0, 0, 0, 1, 1, -1}},
           {RC_OBJ_RING, {0, 0, 0, 0, 0, 1, 1, 1}},
           {RC_OBJ_RING, {0, 0, 0, 0, 0, 1, -1, 2}}}) {
    EXPECT_EQ(fatal_message(type, args), "");
    EXPECT_EQ(one(type, args).counts().skipped_degenerate, 1u);
  }
  EXPECT_EQ(fatal_message(RC_OBJ_RING, {0, 0, 0, 0, 0, 1, -1, 0}), "negative radii for ring \"s\"");
}

TEST(Ring, DiscAndAnnulus) {
  auto disc = one(RC_OBJ_RING, {0, 0, 1, 0, 0, 2, 0, 1});
  auto h = disc.intersect({0.5, 0, 5}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 4, kTol);
  expect_vec(h->normal, {0, 0, 1});
  EXPECT_TRUE(h->front);
  auto back = disc.intersect({0.5, 0, -5}, {0, 0, 1});
  ASSERT_TRUE(back);
  EXPECT_FALSE(back->front);
  EXPECT_FALSE(disc.intersect({1.5, 0, 5}, {0, 0, -1}));
  // Along its plane: parallel, no hit (Radiance's test).
  EXPECT_FALSE(disc.intersect({-5, 0, 1}, {1, 0, 0}));
  // From its own surface: no self-hit.
  EXPECT_FALSE(disc.intersect({0.5, 0, 1}, {0, 1, 1}));

  auto ann = one(RC_OBJ_RING, {0, 0, 0, 0, 0, 1, 2, 1}); // radii in any order
  EXPECT_FALSE(ann.intersect({0.5, 0, 5}, {0, 0, -1}));
  EXPECT_TRUE(ann.intersect({1.5, 0, 5}, {0, 0, -1}));
  EXPECT_FALSE(ann.intersect({2.5, 0, 5}, {0, 0, -1}));
  EXPECT_EQ(ann.counts().rings, 1u);
}

TEST(Cone, TiltedAxis) {
  // Cylinder along (1,1,1): a ray perpendicular to the axis through its middle.
  auto g = one(RC_OBJ_CYLINDER, {0, 0, 0, 3, 3, 3, 0.5});
  const Vec3d mid{1.5, 1.5, 1.5};
  // A unit vector perpendicular to (1,1,1).
  const Vec3d u{1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0};
  const Vec3d org{mid[0] + 5 * u[0], mid[1] + 5 * u[1], mid[2]};
  auto h = g.intersect(org, {-u[0], -u[1], -u[2]});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 4.5, 1e-12);
  expect_vec(h->normal, u, 1e-12);
}

} // namespace
} // namespace radcl::geometry
