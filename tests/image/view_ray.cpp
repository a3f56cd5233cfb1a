// View rays (viewray) for every view type: against vwrays' output for materials.vf and against
// the projection formulas at chosen image positions.
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

#include "radcl/image/view_ray.h"
#include "radcl/options/view.h"
#include "reference_data.h"
#include "test_env.h"

using namespace radcl;
using options::View;

namespace {

constexpr double kPi = std::numbers::pi;

View make(char type, double vh, double vv, double vo = 0, double va = 0, double vs = 0,
          double vl = 0, options::Vec3 vd = {0, 1, 0}, options::Vec3 vp = {1, 2, 3}) {
  View v;
  v.type = type;
  v.point = vp;
  v.direction = vd;
  v.horiz = vh;
  v.vert = vv;
  v.fore = vo;
  v.aft = va;
  v.shift = vs;
  v.lift = vl;
  EXPECT_EQ(options::setup_view(v), "");
  return v;
}

double angle(const image::Vec3& a, const image::Vec3& b) {
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::acos(std::clamp(d, -1.0, 1.0)) * 180 / kPi;
}

} // namespace

// vwrays -vf materials.vf -x 16 -y 12: 16 x 10 after aspect normalisation, top row first.
TEST(ViewRay, MatchesVwraysForMaterialsView) {
  View v;
  ASSERT_GT(options::read_view_file(test::data("scenes/materials.vf"), v, "rpict"), 0);
  ASSERT_EQ(options::setup_view(v), "");
  int x = 16, y = 12;
  image::normalize_aspect(image::view_aspect(v), x, y, 1.0);
  ASSERT_EQ(x, 16);
  ASSERT_EQ(y, 10);
  auto ref = test::read_rays(test::data("scenes/materials_rays.txt"));
  ASSERT_EQ(ref.size(), 160u);
  std::size_t k = 0;
  for (int j = y - 1; j >= 0; --j)
    for (int i = 0; i < x; ++i, ++k) {
      auto r = image::view_ray(v, (i + 0.5) / x, (j + 0.5) / y);
      ASSERT_TRUE(r);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(r->org[c], ref[k][c], 1e-5) << "ray " << k;
        EXPECT_NEAR(r->dir[c], ref[k][3 + c], 1e-5) << "ray " << k;
      }
    }
}

TEST(ViewRay, CentreRayLooksAlongTheViewDirection) {
  for (char t : {'v', 'l', 'c', 'h', 'a', 's'}) {
    View v = make(t, t == 'l' ? 4 : 90, t == 'l' ? 3 : 60, 0, 0, 0, 0, {1, 1, 0});
    auto r = image::view_ray(v, 0.5, 0.5);
    ASSERT_TRUE(r) << t;
    EXPECT_NEAR(angle(r->dir, {std::sqrt(0.5), std::sqrt(0.5), 0}), 0, 1e-5) << t;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(r->org[c], v.point[c], 1e-12) << t;
  }
}

// The image edge lies at half the view angle from the axis (how each type defines -vh/-vv).
TEST(ViewRay, EdgesAtHalfTheViewAngle) {
  struct Case {
    char type;
    double vh, vv;
  } cases[] = {{'v', 60, 40},  {'v', 120, 30},  {'v', 10, 170},  {'h', 180, 180},
               {'h', 120, 90}, {'a', 180, 180}, {'a', 360, 360}, {'a', 90, 200},
               {'c', 360, 60}, {'c', 180, 90},  {'s', 180, 180}, {'s', 300, 120}};
  for (const Case& c : cases) {
    View v = make(c.type, c.vh, c.vv);
    auto right = image::view_ray(v, 1.0, 0.5);
    auto top = image::view_ray(v, 0.5, 1.0);
    if (c.type == 'a' && c.vh >= 360) {
      EXPECT_TRUE(right) << c.type << c.vh; // the rim of a full angular fisheye looks back
    }
    ASSERT_TRUE(right) << c.type << " " << c.vh;
    ASSERT_TRUE(top) << c.type << " " << c.vv;
    EXPECT_NEAR(angle(right->dir, v.direction), std::min(c.vh / 2, 180.0), 1e-6)
        << c.type << " -vh " << c.vh;
    if (c.type != 'c') // a cylindrical view's vertical extent is perspective, measured at x=0.5
      EXPECT_NEAR(angle(top->dir, v.direction), c.vv / 2, 1e-6) << c.type << " -vv " << c.vv;
    else
      EXPECT_NEAR(angle(top->dir, v.direction), c.vv / 2, 1e-6);
  }
}

TEST(ViewRay, FisheyeCircleAndClipping) {
  View h = make('h', 180, 180);
  EXPECT_FALSE(image::view_ray(h, 0.95, 0.95)); // outside the circle
  EXPECT_TRUE(image::view_ray(h, 0.85, 0.5));
  // An angular fisheye's circle reaches 180 degrees from the axis: a 180-degree view still has
  // (backward-looking) rays in its corners; a 360-degree one does not.
  EXPECT_TRUE(image::view_ray(make('a', 180, 180), 0.99, 0.99));
  EXPECT_FALSE(image::view_ray(make('a', 360, 360), 0.99, 0.99));
  // Fore clipping starts rays on a sphere (fisheyes) or plane; aft limits their length.
  View v = make('v', 60, 60, 2, 5);
  auto r = image::view_ray(v, 1.0, 1.0);
  ASSERT_TRUE(r);
  double t = std::tan(30 * kPi / 180);
  double len = std::sqrt(1 + 2 * t * t);
  EXPECT_NEAR(r->org[1] - v.point[1], 2.0, 1e-9); // on the plane 2 ahead
  EXPECT_NEAR(r->maxlen, 3 * len, 1e-9);
  View hv = make('h', 180, 180, 1.5, 4);
  auto rh = image::view_ray(hv, 0.7, 0.4);
  ASSERT_TRUE(rh);
  double d = std::hypot(rh->org[0] - 1, rh->org[1] - 2, rh->org[2] - 3);
  EXPECT_NEAR(d, 1.5, 1e-9);
  EXPECT_NEAR(rh->maxlen, 2.5, 1e-9);
}

TEST(ViewRay, ShiftLiftAndParallelViews) {
  // -vs 1 moves the image one width right: its left edge is the unshifted right edge.
  View v = make('v', 60, 40, 0, 0, 1, 0);
  View v0 = make('v', 60, 40);
  auto a = image::view_ray(v, 0.0, 0.3), b = image::view_ray(v0, 1.0, 0.3);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(angle(a->dir, b->dir), 0, 1e-5); // acos near 1 resolves ~1e-6 degrees
  View l = make('l', 0.5, 0.25, 0, 0, 0.5, -0.5);
  View l0 = make('l', 0.5, 0.25);
  auto c = image::view_ray(l, 0.25, 0.75), d = image::view_ray(l0, 0.75, 0.25);
  ASSERT_TRUE(c && d);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(c->org[k], d->org[k], 1e-12);
  EXPECT_NEAR(angle(c->dir, l.direction), 0, 1e-5);
  // Parallel view: origins span -vh x -vv world units.
  auto e = image::view_ray(l0, 1.0, 0.5), f = image::view_ray(l0, 0.0, 0.5);
  EXPECT_NEAR(std::hypot(e->org[0] - f->org[0], e->org[1] - f->org[1], e->org[2] - f->org[2]), 0.5,
              1e-12);
}

TEST(ViewRay, AspectNormalisation) {
  // cli-rtrace-rpict.md §4.3's example and the other branches.
  View v = make('v', 45, 45);
  int x = 64, y = 48;
  EXPECT_DOUBLE_EQ(image::normalize_aspect(image::view_aspect(v), x, y, 1.0), 1.0);
  EXPECT_EQ(x, 48);
  EXPECT_EQ(y, 48);
  View w = make('v', 90, 40);
  x = 512, y = 512;
  image::normalize_aspect(image::view_aspect(w), x, y, 1.0);
  EXPECT_EQ(x, 512);
  EXPECT_EQ(y, static_cast<int>(512 * std::tan(20 * kPi / 180) / std::tan(45 * kPi / 180) + 0.5));
  x = 300, y = 100;
  double pa = image::normalize_aspect(image::view_aspect(w), x, y, 0);
  EXPECT_EQ(x, 300);
  EXPECT_EQ(y, 100);
  EXPECT_NEAR(pa, image::view_aspect(w) * 3, 1e-12);
  x = 100, y = 100;
  image::normalize_aspect(1.0, x, y, 2.0); // tall pixels: fewer scanlines
  EXPECT_EQ(x, 100);
  EXPECT_EQ(y, 50);
}
