// Polygons: Radiance's normal and plane, concave outlines, seam-connected holes, grazing rays
// and rays leaving the surface.
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

std::vector<double> flat(const std::vector<std::array<double, 2>>& xy, double z) {
  std::vector<double> f;
  for (const auto& p : xy)
    f.insert(f.end(), {p[0], p[1], z});
  return f;
}

SceneGeometry polygon(const std::vector<double>& f) {
  SceneMaker m;
  m.add(RC_OBJ_POLYGON, "p", f, m.material());
  return SceneGeometry(m.loaded());
}

TEST(Polygon, SquareFrontAndBack) {
  auto g = polygon(flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 2));
  auto h = g.intersect({0.25, 0.75, 5}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 3, kTol);
  expect_vec(h->point, {0.25, 0.75, 2});
  expect_vec(h->normal, {0, 0, 1});
  EXPECT_TRUE(h->front);
  EXPECT_EQ(h->object, 1);
  auto b = g.intersect({0.25, 0.75, -1}, {0, 0, 1});
  ASSERT_TRUE(b);
  EXPECT_FALSE(b->front);
  expect_vec(b->normal, {0, 0, 1});
  EXPECT_FALSE(g.intersect({1.25, 0.5, 5}, {0, 0, -1}));
  EXPECT_EQ(g.counts().polygons, 1u);
  EXPECT_EQ(g.counts().triangles, 2u);
}

TEST(Polygon, ClockwiseFacesDown) {
  auto g = polygon(flat({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 0));
  auto h = g.intersect({0.5, 0.5, 1}, {0, 0, -1});
  ASSERT_TRUE(h);
  expect_vec(h->normal, {0, 0, -1});
  EXPECT_FALSE(h->front);
}

TEST(Polygon, SlantedExactDistance) {
  // Plane x + y + z = 1 through the triangle's corners.
  auto g = polygon({1, 0, 0, 0, 1, 0, 0, 0, 1});
  const double k = 1 / std::sqrt(3.0);
  auto h = g.intersect({0, 0, 0}, {1, 1, 1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, k, kTol);
  expect_vec(h->normal, {k, k, k});
  expect_vec(h->point, {1.0 / 3, 1.0 / 3, 1.0 / 3});
}

TEST(Polygon, NormalIsPolygonsNotTriangles) {
  // Slightly non-planar quad: every hit reports the one Radiance normal (fan sum).
  std::vector<double> f{0, 0, 0, 2, 0, 0.001, 2, 2, 0, 0, 2, 0.001};
  SceneMaker m;
  m.add(RC_OBJ_POLYGON, "p", f, m.material());
  SceneGeometry g(m.loaded());
  Vec3d sum{0, 0, 0};
  std::vector<Vec3d> v{{0, 0, 0}, {2, 0, 0.001}, {2, 2, 0}, {0, 2, 0.001}};
  for (int i = 2; i < 4; ++i) { // fan from v[0] = origin
    const Vec3d a = v[i - 1], b = v[i];
    sum[0] += a[1] * b[2] - a[2] * b[1];
    sum[1] += a[2] * b[0] - a[0] * b[2];
    sum[2] += a[0] * b[1] - a[1] * b[0];
  }
  const double l = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  for (const Vec3d& o : {Vec3d{0.3, 1.5, 3}, Vec3d{1.5, 0.3, 3}}) {
    auto h = g.intersect(o, {0, 0, -1});
    ASSERT_TRUE(h);
    expect_vec(h->normal, {sum[0] / l, sum[1] / l, sum[2] / l});
  }
}

TEST(Polygon, ConcaveL) {
  auto g = polygon(flat({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0));
  EXPECT_TRUE(g.intersect({0.5, 1.5, 1}, {0, 0, -1}));
  EXPECT_TRUE(g.intersect({1.5, 0.5, 1}, {0, 0, -1}));
  EXPECT_FALSE(g.intersect({1.5, 1.5, 1}, {0, 0, -1})); // the notch
}

TEST(Polygon, SeamHole) {
  // 4x4 square with a 2x2 hole, joined by a seam from (0,0) to (1,1), as Radiance writes it.
  auto g = polygon(
      flat({{0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}, {0, 0}, {4, 0}, {4, 4}, {0, 4}}, 0));
  for (double x = 0.05; x < 4; x += 0.1)
    for (double y = 0.05; y < 4; y += 0.1) {
      const bool in_hole = x > 1 && x < 3 && y > 1 && y < 3;
      auto h = g.intersect({x, y, 1}, {0, 0, -1});
      EXPECT_EQ(h.has_value(), !in_hole) << x << " " << y;
      if (h) {
        EXPECT_EQ(h->object, 1);
      }
    }
  // Exactly along the seam: solid on both sides, so a hit.
  EXPECT_TRUE(g.intersect({0.5, 0.5, 1}, {0, 0, -1}));
}

TEST(Polygon, GrazingAlongPlaneMisses) {
  auto g = polygon(flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0));
  EXPECT_FALSE(g.intersect({-1, 0.5, 0}, {1, 0, 0}));
  EXPECT_FALSE(g.occluded({-1, 0.5, 0}, {1, 0, 0}));
}

TEST(Polygon, StartingOnSurface) {
  SceneMaker m;
  const auto mat = m.material();
  m.add(RC_OBJ_POLYGON, "floor", flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0), mat);
  m.add(RC_OBJ_POLYGON, "ceiling", flat({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 1), mat);
  SceneGeometry g(m.loaded());
  // Rays leaving the floor in many directions reach the ceiling, never the floor again.
  for (int i = 0; i < 200; ++i) {
    const double a = 0.1 + 0.01 * i, x = 0.3 + 0.002 * i, y = 0.7 - 0.003 * i;
    const Vec3d dir{0.1 * std::cos(a), 0.1 * std::sin(a), 1};
    auto h = g.intersect({x, y, 0}, dir);
    ASSERT_TRUE(h) << i;
    EXPECT_EQ(h->object, 2) << i;
    auto back = g.intersect(h->point, {-dir[0], -dir[1], -dir[2]});
    ASSERT_TRUE(back) << i;
    EXPECT_EQ(back->object, 1) << i;
    EXPECT_NEAR(back->t, h->t, 1e-12);
    EXPECT_FALSE(g.occluded({x, y, 0}, {dir[0], dir[1], -1}));
  }
}

TEST(Polygon, ZeroAreaWarnedAndSkipped) {
  std::string got;
  static std::string* sink = &got;
  set_warning_sink([](const std::string& m) { *sink += m; });
  auto g = polygon({0, 0, 0, 1, 0, 0, 2, 0, 0});
  set_warning_sink(nullptr);
  EXPECT_EQ(got, "zero area for polygon \"p\"");
  EXPECT_EQ(g.counts().polygons, 0u);
  EXPECT_EQ(g.counts().skipped_degenerate, 1u);
  EXPECT_FALSE(g.intersect({0.5, 0, 1}, {0, 0, -1}));
}

TEST(Polygon, BadArgumentCount) {
  try {
    polygon({0, 0, 0, 1, 0, 0, 1, 1});
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "bad # arguments for polygon \"p\"");
  }
}

TEST(Polygon, VoidAndPatternOnlySurfacesAreInvisible) {
  SceneMaker m;
  const auto pat = m.add(RC_OBJ_BRIGHTFUNC, "pat", {}, scene::kVoid, {"x", "."});
  m.add(RC_OBJ_POLYGON, "a", flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0), scene::kVoid);
  m.add(RC_OBJ_POLYGON, "b", flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1), pat);
  const auto mat = m.add(RC_OBJ_PLASTIC, "m", {0.5, 0.5, 0.5, 0, 0}, pat);
  m.add(RC_OBJ_POLYGON, "c", flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, -1), mat);
  m.add(RC_OBJ_SOURCE, "sun", {0, 0, 2, 0.5}, mat);
  m.add(RC_OBJ_SOURCE, "nothing", {0, 0, 1, 0.5}, scene::kVoid);
  SceneGeometry g(m.loaded());
  auto h = g.intersect({0.5, 0.5, 5}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_EQ(h->object, 4);
  EXPECT_EQ(g.counts().skipped_void, 3u);
  ASSERT_EQ(g.distant_sources().size(), 1u);
  const auto& s = g.distant_sources()[0];
  EXPECT_EQ(s.object, 5);
  expect_vec(s.direction, {0, 0, 1});
  EXPECT_NEAR(s.solid_angle, 2 * M_PI * (1 - std::cos(0.25 * M_PI / 180)), 1e-15);
}

} // namespace
} // namespace radcl::geometry
