// Triangulation: triangles must cover exactly the polygon (even-odd, as Radiance's inside
// test), with no overlaps — checked by area and by sampling points.
#include "radcl/geometry/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace radcl::geometry {
namespace {

double shoelace(const std::vector<Point2>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& q = p[i];
    const auto& r = p[(i + 1) % p.size()];
    a += q[0] * r[1] - q[1] * r[0];
  }
  return 0.5 * a;
}

double tri_area(const Point2& a, const Point2& b, const Point2& c) {
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

bool inside_even_odd(const std::vector<Point2>& p, const Point2& x) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if ((p[i][1] > x[1]) != (p[j][1] > x[1]) &&
        x[0] < (p[j][0] - p[i][0]) * (x[1] - p[i][1]) / (p[j][1] - p[i][1]) + p[i][0])
      in = !in;
  return in;
}

// Every triangle positive, total area equal, and random points inside the polygon lie in
// exactly one triangle (outside: in none).
void check_cover(const std::vector<Point2>& poly, const std::vector<Tri>& tris, double tol) {
  double sum = 0;
  for (const auto& t : tris) {
    const double a = tri_area(poly[t[0]], poly[t[1]], poly[t[2]]);
    EXPECT_GT(a, 0);
    sum += a;
  }
  const double area = shoelace(poly);
  EXPECT_NEAR(sum, area, tol * std::abs(area));
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& q : poly)
    for (int k = 0; k < 2; ++k)
      lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(lo[0], hi[0]), uy(lo[1], hi[1]);
  int mismatches = 0;
  for (int s = 0; s < 2000; ++s) {
    const Point2 x{ux(rng), uy(rng)};
    int count = 0;
    for (const auto& t : tris) {
      const double a = tri_area(poly[t[0]], poly[t[1]], x), b = tri_area(poly[t[1]], poly[t[2]], x),
                   c = tri_area(poly[t[2]], poly[t[0]], x);
      count += (a > 0 && b > 0 && c > 0);
    }
    const int expect = inside_even_odd(poly, x) ? 1 : 0;
    mismatches += count != expect;
  }
  EXPECT_EQ(mismatches, 0);
}

std::vector<Point2> star(std::mt19937& rng, int n, double rmin, double rmax, double phase = 0) {
  std::uniform_real_distribution<double> ur(rmin, rmax);
  std::vector<Point2> p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * std::numbers::pi * i / n;
    const double r = ur(rng);
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

TEST(Triangulate, ConvexFan) {
  std::vector<Point2> sq{{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  auto t = triangulate_2d(sq);
  EXPECT_EQ(t.size(), 2u);
  check_cover(sq, t, 1e-12);
}

TEST(Triangulate, RandomStarShaped) {
  std::mt19937 rng(42);
  for (int iter = 0; iter < 200; ++iter) {
    const int n = 3 + iter % 40;
    auto p = star(rng, n, 0.2, 1.0);
    check_cover(p, triangulate_2d(p), 1e-9);
  }
}

TEST(Triangulate, CombConcave) {
  // A comb: teeth pointing up, deep notches.
  std::vector<Point2> p{{0, 0}, {10, 0}, {10, 5}};
  for (int i = 9; i >= 0; --i) {
    p.push_back({i + 0.8, 5});
    p.push_back({i + 0.5, 1});
    p.push_back({i + 0.2, 5});
  }
  p.push_back({0, 5});
  check_cover(p, triangulate_2d(p), 1e-9);
}

TEST(Triangulate, CollinearAndRepeatedVertices) {
  std::vector<Point2> p{{0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}};
  check_cover(p, triangulate_2d(p), 1e-12);
}

// Outline counter-clockwise, hole clockwise, joined by a seam walked in both directions —
// how Radiance models holes (e.g. genbox/xform output, mkillum windows).
std::vector<Point2> with_hole(const std::vector<Point2>& outer, std::size_t oi,
                              const std::vector<Point2>& hole_ccw, std::size_t hi) {
  std::vector<Point2> p(outer.begin(), outer.begin() + oi + 1);
  const std::size_t m = hole_ccw.size();
  for (std::size_t k = 0; k <= m; ++k)
    p.push_back(hole_ccw[(hi + m - k % m) % m]);
  p.push_back(outer[oi]);
  p.insert(p.end(), outer.begin() + oi + 1, outer.end());
  return p;
}

TEST(Triangulate, SquareWithSeamHole) {
  std::vector<Point2> outer{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  std::vector<Point2> hole{{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  for (std::size_t oi = 0; oi < 4; ++oi)
    for (std::size_t hi = 0; hi < 4; ++hi) {
      if (hi == (oi + 2) % 4) continue; // that seam would cross the hole
      auto p = with_hole(outer, oi, hole, hi);
      EXPECT_NEAR(shoelace(p), 12, 1e-12);
      check_cover(p, triangulate_2d(p), 1e-12);
    }
}

TEST(Triangulate, RandomStarWithStarHole) {
  std::mt19937 rng(3);
  for (int iter = 0; iter < 100; ++iter) {
    const int n = 4 + iter % 17, m = 3 + iter % 11;
    auto outer = star(rng, n, 0.6, 1.0);
    // Hole vertices at the outline's angles too, so a radial seam exists between them.
    auto hole = star(rng, n * m, 0.1, 0.4); // inside every outline chord (n >= 4)
    std::vector<Point2> h2;
    for (int k = 0; k < n * m; k += m)
      h2.push_back(hole[k]);
    for (int k = 0; k < n * m; ++k)
      if (k % m != 0) h2.push_back(hole[k]);
    std::sort(h2.begin(), h2.end(), [](const Point2& a, const Point2& b) {
      return std::atan2(a[1], a[0]) < std::atan2(b[1], b[0]);
    });
    // Seam from outline vertex 0 (angle 0) to the hole vertex at angle 0.
    std::size_t hi = 0;
    for (std::size_t k = 0; k < h2.size(); ++k)
      if (std::abs(std::atan2(h2[k][1], h2[k][0])) < 1e-12) hi = k;
    auto p = with_hole(outer, 0, h2, hi);
    const double expect = shoelace(outer) - shoelace(h2);
    EXPECT_NEAR(shoelace(p), expect, 1e-12);
    check_cover(p, triangulate_2d(p), 1e-9);
  }
}

TEST(Triangulate, TwoHolesSameOutlineVertex) {
  std::vector<Point2> outer{{0, 0}, {6, 0}, {6, 3}, {0, 3}};
  std::vector<Point2> h1{{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  std::vector<Point2> h2{{4, 1}, {5, 1}, {5, 2}, {4, 2}};
  // Around the shared vertex the seams must leave in angular order (h1 at 45 degrees
  // first, then h2) or the outline would cross itself.
  auto p = with_hole(with_hole(outer, 0, h2, 0), 0, h1, 0);
  EXPECT_NEAR(shoelace(p), 16, 1e-12);
  check_cover(p, triangulate_2d(p), 1e-12);
}

TEST(Triangulate, PolygonPlaneMatchesRadiance) {
  std::vector<std::array<double, 3>> v{{0, 0, 1}, {2, 0, 1}, {2, 3, 1}, {0, 3, 1}};
  auto pl = polygon_plane(v);
  EXPECT_DOUBLE_EQ(pl.area, 6);
  EXPECT_DOUBLE_EQ(pl.normal[2], 1);
  EXPECT_DOUBLE_EQ(pl.offset, 1);
  auto t = triangulate_polygon(v, pl.normal);
  EXPECT_EQ(t.size(), 2u);
}

} // namespace
} // namespace radcl::geometry
