// Issue 8 case 2: grazing rays on polygons and quadrics, rays that start exactly on a surface
// (inside a polygon, on an edge shared by two polygons or two triangles of one, on a vertex),
// and -I sensors placed exactly on a surface facing either way. Radiance's rules: a ray along a
// plane (|cos| <= FTINY) misses it, a ray starting on a surface never hits that surface at
// distance 0 (t <= FTINY is no hit), and a sensor reads what the side it faces sees. Geometry
// checks go through SceneGeometry (primary rays); irradiance checks through the renderer with
// -ab 0 -dj 0 -ds 0 -dt 0, which are deterministic and, for sphere lights wholly in front of
// the sensor, exact: E = pi L r^2 cos(theta) / d^2.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/mesh.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;

namespace {

constexpr double kPi = std::numbers::pi;
using V = std::array<double, 3>;

V add(const V& a, const V& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
V sub(const V& a, const V& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V mul(const V& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
double dot(const V& a, const V& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V unit(const V& a) {
  return mul(a, 1 / std::sqrt(dot(a, a)));
}

struct Lamp {
  V c;
  double r, L;
};

// Irradiance at meter point p facing n from lamps wholly in front of it, each seen unless the
// plane z = 0 (the floor) lies between.
double lamp_irradiance(const V& p, const V& n, const std::vector<Lamp>& lamps, bool floor) {
  double e = 0;
  for (const Lamp& l : lamps) {
    const V d = sub(l.c, p);
    const double d2 = dot(d, d), cosv = dot(unit(d), n);
    if (cosv <= 0) continue;
    if (floor && (p[2] > 0) != (l.c[2] > 0)) continue;
    e += kPi * l.L * l.r * l.r * cosv / d2;
  }
  return e;
}

class StabilityGrazing : public test::SceneDir {
protected:
  std::optional<scene::LoadedScene> ls;
  std::optional<geometry::SceneGeometry> geom;

  void load(const std::string& text) {
    std::ofstream("g.rad", std::ios::trunc) << text;
    geom.reset();
    ls = scene::load_scene({"g.rad"});
    geom.emplace(*ls);
  }
  std::optional<geometry::Hit> hit(const V& o, const V& d) const {
    return geom->intersect(o, d, 0, 1e30);
  }
  // The object name a ray hits, "" for none.
  std::string hit_name(const V& o, const V& d) const {
    auto h = hit(o, d);
    if (!h) return "";
    EXPECT_TRUE(std::isfinite(h->t) && h->t > 0);
    return ls->main.objects[h->object].name;
  }

  static render::RenderSettings direct(bool sensors) {
    return test::direct_light_settings(sensors);
  }
  std::vector<render::PrimaryResult> render(const std::string& text,
                                            const std::vector<render::PrimaryRay>& rays,
                                            const render::RenderSettings& st) {
    std::ofstream("r.rad", std::ios::trunc) << text;
    return render_rays("r.rad", rays, st);
  }
};

// A square floor split into four polygons meeting at the origin (so the origin is a vertex of
// all four and the axes are shared edges), a ceiling at z = 1 and a basement at z = -1.
const char* kFloors = R"(
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon f1 0 0 12  0 0 0  2 0 0  2 2 0  0 2 0
grey polygon f2 0 0 12  0 0 0  0 2 0  -2 2 0  -2 0 0
grey polygon f3 0 0 12  0 0 0  -2 0 0  -2 -2 0  0 -2 0
grey polygon f4 0 0 12  0 0 0  0 -2 0  2 -2 0  2 0 0
grey polygon ceiling 0 0 12  -99 -99 1  -99 99 1  99 99 1  99 -99 1
grey polygon basement 0 0 12  -99 -99 -1  99 -99 -1  99 99 -1  -99 99 -1
)";

} // namespace

// Rays in the plane of a polygon miss it (Radiance: |cos| <= FTINY); barely dipping rays hit
// it where the exact geometry says.
TEST_F(StabilityGrazing, PolygonGrazingRays) {
  load(kFloors);
  EXPECT_EQ(hit_name({-5, 0.5, 0}, {1, 0, 0}), "");
  EXPECT_EQ(hit_name({-5, 0.5, 1e-9}, {1, 0, 0}), "");
  // cos 1e-7 counts as along the plane: from the floor rising, and falling onto it.
  EXPECT_EQ(hit_name({-1.5, 0.5, 0}, {1, 0, 1e-7}), "");
  EXPECT_EQ(hit_name({-1.5, 0.5, 1e-8}, {1, 0, -1e-7}), "");
  // Dipping at cos 1e-3 and 1e-5: the floor at x = 0.7, y = 0.5.
  for (double c : {1e-3, 1e-5}) {
    const V o{0.7 - 3 / c * std::sqrt(1 - c * c) * 1, 0.5, 3};
    const V d{std::sqrt(1 - c * c), 0, -c};
    auto h = hit(o, d);
    ASSERT_TRUE(h) << c;
    EXPECT_EQ(ls->main.objects[h->object].name, "f1") << c;
    EXPECT_NEAR(h->point[0], 0.7, 1e-6 / c) << c;
    EXPECT_NEAR(h->point[1], 0.5, 1e-9) << c;
    EXPECT_NEAR(h->point[2], 0, 1e-9) << c;
    EXPECT_NEAR(h->t, 3 / c, 1e-6 / c) << c;
  }
}

// Rays starting on the floor (inside a polygon, on a shared edge, on the common vertex, on
// the outline's edge and corner) never hit the floor: up they meet the ceiling, down the
// basement, at the exact distance.
TEST_F(StabilityGrazing, RaysStartingOnPolygon) {
  load(kFloors);
  const std::vector<V> starts = {{0.7, 0.4, 0}, {0.7, 0, 0}, {0, -1.3, 0}, {0, 0, 0},
                                 {2, 0.5, 0},   {2, 2, 0},   {1, 1, 0},    {-1, 1, 0}};
  const std::vector<V> dirs = {{0, 0, 1}, {0.3, -0.2, 1}, {1, 1, 0.05}, {-1, 0.5, 0.02}};
  for (const V& o : starts)
    for (const V& d0 : dirs)
      for (double s : {1.0, -1.0}) {
        const V d = unit({d0[0], d0[1], s * d0[2]});
        auto h = hit(o, d);
        ASSERT_TRUE(h) << o[0] << "," << o[1] << " dir z " << d[2];
        EXPECT_EQ(ls->main.objects[h->object].name, s > 0 ? "ceiling" : "basement")
            << o[0] << "," << o[1] << " dir z " << d[2];
        EXPECT_NEAR(h->t, 1 / std::abs(d[2]), 1e-9 / std::abs(d[2]));
      }
}

// Spheres: tangent and near-tangent rays, rays from the surface outwards (miss), inwards (the
// far side at the chord 2 r cos), and along the tangent plane (miss).
TEST_F(StabilityGrazing, SphereGrazingAndOnSurface) {
  const V c{0.3, -0.2, 0.5};
  const double r = 0.7;
  load("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey sphere ball 0 0 4 0.3 -0.2 0.5 0.7\n");
  for (double off : {1e-7, 1e-9}) {
    EXPECT_EQ(hit_name({c[0] - 5, c[1], c[2] + r + off * r}, {1, 0, 0}), "") << off;
    auto h = hit({c[0] - 5, c[1], c[2] + r - off * r}, {1, 0, 0});
    ASSERT_TRUE(h) << off;
    EXPECT_NEAR(h->point[0], c[0], 2e-3) << off; // sqrt(2 off) r from the tangent point
    EXPECT_NEAR(h->point[2], c[2] + r - off * r, 1e-9) << off;
    EXPECT_TRUE(std::isfinite(h->normal[0] + h->normal[1] + h->normal[2]));
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    V n;
    do
      n = {u(rng), u(rng), u(rng)};
    while (dot(n, n) > 1 || dot(n, n) < 1e-2);
    n = unit(n);
    const V p = add(c, mul(n, r));
    V w = unit({u(rng), u(rng), u(rng)});
    if (std::abs(dot(w, n)) < 1e-3) continue;
    if (dot(w, n) > 0) w = mul(w, -1);
    EXPECT_EQ(hit_name(p, mul(w, -1)), "") << i; // outwards
    auto h = hit(p, w);                          // inwards: the far side
    ASSERT_TRUE(h) << i;
    EXPECT_NEAR(h->t, -2 * r * dot(w, n), 1e-9) << i;
    EXPECT_FALSE(h->front) << i;
    const V t = unit(sub(w, mul(n, dot(w, n)))); // along the tangent plane
    auto ht = hit(p, t);
    EXPECT_FALSE(ht) << i << " t " << (ht ? ht->t : 0) << " r-|p-c| "
                     << r - std::sqrt(dot(sub(p, c), sub(p, c)));
  }
}

// Cylinders and cones: rays along a side line (the quadratic's leading term vanishes), rays
// from the surface inwards and outwards, and rays through a cone's apex.
TEST_F(StabilityGrazing, ConeAndCylinderGrazing) {
  load("void plastic grey 0 0 5 .5 .5 .5 0 0\n"
       "grey cylinder can 0 0 7 0 0 0 0 0 2 0.5\n"
       "grey cone hat 0 0 8 5 0 0 5 0 2 1 0\n");
  // Along the cylinder's side line, on it and just off it: no hit, nothing non-finite.
  for (double x : {0.5, 0.5 - 1e-9, 0.5 + 1e-9})
    EXPECT_EQ(hit_name({x, 0, -1}, {0, 0, 1}), "") << x;
  // Along the cone's side line from below the base through to the apex.
  // Along the cone's side line (through the apex): a hit, if any, lies on the cone.
  for (double off : {0.0, 1e-9, -1e-9}) {
    auto g = hit({7 + off, 0, -2}, {-1, 0, 2});
    if (g) {
      const double rho = std::hypot(g->point[0] - 5, g->point[1]);
      EXPECT_NEAR(rho, 1 - g->point[2] / 2, 1e-6) << off;
      EXPECT_GE(g->point[2], -1e-9);
      EXPECT_LE(g->point[2], 2 + 1e-9);
    }
  }
  // From points on the cylinder: inwards across the chord, outwards nothing.
  for (double a = 0.1; a < 6.2; a += 0.7) {
    const V p{0.5 * std::cos(a), 0.5 * std::sin(a), 1.0};
    const V in = unit({-std::cos(a + 0.3), -std::sin(a + 0.3), 0.2});
    auto h = hit(p, in);
    ASSERT_TRUE(h) << a;
    EXPECT_EQ(ls->main.objects[h->object].name, "can");
    const double chord = 2 * 0.5 * std::cos(0.3) * std::sqrt(1 + 0.2 * 0.2);
    EXPECT_NEAR(h->t, chord, 1e-9) << a;
    EXPECT_NE(hit_name(p, {std::cos(a), std::sin(a), 0}), "can") << a;
  }
  // From the cone's apex: along the axis inside (open base: nothing), and outwards.
  EXPECT_EQ(hit_name({5, 0, 2}, {0, 0, -1}), "");
  EXPECT_EQ(hit_name({5, 0, 2}, {0, 0, 1}), "");
  EXPECT_EQ(hit_name({5, 0, 2}, {1, 0, 0}), "");
  // From a point on the cone's side across to the other side at the same height.
  auto h = hit({5.5, 0, 1}, {-1, 0, 0});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 1.0, 1e-9);
}

// Rings: rays in the ring's plane miss; rays onto the inner and outer edges hit (Radiance's
// bounds are inclusive); rays from the ring go on to what lies behind.
TEST_F(StabilityGrazing, RingGrazingAndEdges) {
  load("void plastic grey 0 0 5 .5 .5 .5 0 0\n"
       "grey ring disc 0 0 8 0 0 1 0 0 1 0.25 1\n"
       "grey polygon below 0 0 12 -9 -9 0 9 -9 0 9 9 0 -9 9 0\n");
  EXPECT_EQ(hit_name({-5, 0.5, 1}, {1, 0, 0}), "");
  EXPECT_EQ(hit_name({-5, 0.5, 1 + 1e-9}, {1, 0, 0}), "");
  EXPECT_EQ(hit_name({0.6, 0, 3}, {0, 0, -1}), "disc");
  EXPECT_EQ(hit_name({0.1, 0, 3}, {0, 0, -1}), "below");
  EXPECT_EQ(hit_name({1.1, 0, 3}, {0, 0, -1}), "below");
  for (const V& o : std::vector<V>{{0.6, 0, 1}, {0.25, 0, 1}, {0, 1, 1}, {0.6, 0.3, 1}}) {
    auto h = hit(o, {0.1, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_EQ(ls->main.objects[h->object].name, "below");
    EXPECT_EQ(hit_name(o, {0.1, 0, 1}), "");
  }
}

// -I sensors exactly on the split floor (inside, on shared edges, on the common vertex) facing
// up, down and obliquely: each reads the lamps on the side it faces, never one across the
// floor it sits on, to the analytic value.
TEST_F(StabilityGrazing, SensorsOnSurfaceFacingBothWays) {
  const std::vector<Lamp> lamps = {{{0.2, 0.1, 0.8}, 0.05, 100},
                                   {{1.5, 0.2, -0.6}, 0.05, 40},
                                   {{-1.2, 0.3, 0.5}, 0.04, 70},
                                   {{-0.9, -1.1, -0.7}, 0.06, 20}};
  std::string text =
      std::string(kFloors).substr(0, std::string(kFloors).find("grey polygon ceiling"));
  text += "void light lamp 0 0 3 1 1 1\n";
  for (std::size_t i = 0; i < lamps.size(); ++i) {
    const Lamp& l = lamps[i];
    text += "void light lm" + std::to_string(i) + " 0 0 3 " + std::to_string(l.L) + " " +
            std::to_string(l.L) + " " + std::to_string(l.L) + "\n";
    char buf[200];
    std::snprintf(buf, sizeof buf, "lm%zu sphere s%zu 0 0 4 %.17g %.17g %.17g %.17g\n", i, i,
                  l.c[0], l.c[1], l.c[2], l.r);
    text += buf;
  }
  const std::vector<V> points = {{0.7, 0.4, 0}, {0.7, 0, 0}, {0, -0.3, 0}, {0, 0, 0}, {-0.4, 0, 0}};
  const std::vector<V> normals = {{0, 0, 1},  {0, 0, -1},  {1, 0, 1},   {1, 0, -1},
                                  {-1, 0, 1}, {0, -1, -1}, {1, 0, 0.1}, {1, 0, -0.1}};
  std::vector<render::PrimaryRay> rays;
  for (const V& p : points)
    for (const V& n : normals)
      rays.push_back({p, unit(n), 0});
  auto res = render(text, rays, direct(true));
  const std::vector<render::Vec3d> meters = meter_points("r.rad", rays);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const V meter = meters[i]; // Radiance's 1e-4 out, less in a model this small
    const double want = lamp_irradiance(meter, rays[i].dir, lamps, true);
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(std::isfinite(res[i].value[k]));
      EXPECT_NEAR(res[i].value[k], want, 1e-4 * want + 1e-9)
          << "point " << rays[i].org[0] << "," << rays[i].org[1] << " facing " << rays[i].dir[0]
          << "," << rays[i].dir[1] << "," << rays[i].dir[2];
    }
  }
}

// Sensors on a sphere, cylinder and ring facing out and in (inside, the surface itself blocks
// the light), and a lamp at 1 degree elevation over a floor (grazing light). want < 0: the
// formula, every lamp in front unoccluded.
TEST_F(StabilityGrazing, SensorsOnQuadricsAndGrazingLight) {
  const std::string text = "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "void light lm 0 0 3 100 100 100\n"
                           "lm sphere lamp 0 0 4 0 0 6 0.1\n"
                           "void light lo 0 0 3 50 50 50\n"
                           "lo sphere low 0 0 4 -8 -28 0.5 0.2\n"
                           "grey sphere ball 0 0 4 0 0 1 0.5\n"
                           "grey cylinder can 0 0 7 3 0 0 3 0 2 0.5\n"
                           "grey ring disc 0 0 8 -3 0 1 0 0 1 0 0.5\n"
                           "grey polygon floor 0 0 12 -9 -29 0 9 -29 0 9 9 0 -9 9 0\n";
  const std::vector<Lamp> lamps = {{{0, 0, 6}, 0.1, 100}, {{-8, -28, 0.5}, 0.2, 50}};
  struct Case {
    V p, n;
    double want;
  };
  const double s2 = std::sqrt(0.5);
  const std::vector<Case> cases = {
      {{0, 0, 1.5}, {0, 0, 1}, -1},                      // top of the ball, outwards
      {{0, 0, 1.5}, {0, 0, -1}, 0},                      // into the ball: its inside blocks
      {{3.5, 0, 1}, {1, 0, 0}, -1},                      // the can's side, outwards (dark)
      {{3 + 0.5 * s2, 0.5 * s2, 0.5}, {-s2, -s2, 0}, 0}, // inside the can: its wall blocks
      {{-3, 0, 1}, {0, 0, 1}, -1},                       // the ring's centre, up
      {{-3.2, 0.1, 1}, {0, 0, -1}, -1},                  // under the ring: the low lamp
      {{-3.5, 0, 1}, {0, 0, 1}, -1},                     // the ring's outer edge, up
      {{-8, 0, 0}, {0, 0, 1}, -1},                       // the floor: grazing low lamp
      {{-8, 0, 0}, {0, -1, 0.02}, -1},                   // the floor, facing the low lamp
  };
  std::vector<render::PrimaryRay> rays;
  for (const Case& c : cases)
    rays.push_back({c.p, unit(c.n), 0});
  auto res = render(text, rays, direct(true));
  const std::vector<render::Vec3d> meters = meter_points("r.rad", rays);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    double want = cases[i].want;
    if (want < 0) want = lamp_irradiance(meters[i], rays[i].dir, lamps, false);
    ASSERT_TRUE(std::isfinite(res[i].value[0])) << i;
    EXPECT_NEAR(res[i].value[0], want, 1e-4 * want + 1e-9) << "case " << i;
  }
}

// Camera rays grazing every kind of surface, and rays starting on each surface in random
// directions, with ambient bounces: every value finite and non-negative.
TEST_F(StabilityGrazing, RandomRaysFromSurfacesStayFinite) {
  const std::string text = "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "void light lm 0 0 3 100 100 100\n"
                           "lm sphere lamp 0 0 4 0 0 6 0.1\n"
                           "grey sphere ball 0 0 4 0 0 1 0.5\n"
                           "grey cylinder can 0 0 7 3 0 0 3 0 2 0.5\n"
                           "grey cone hat 0 0 8 0 3 0 0 3 1 0.5 0\n"
                           "grey ring disc 0 0 8 -3 0 1 0 0 1 0.1 0.5\n"
                           "grey polygon floor 0 0 12 -9 -9 0 9 -9 0 9 9 0 -9 9 0\n";
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1), a(0, 2 * kPi);
  std::vector<render::PrimaryRay> rays;
  for (int i = 0; i < 64; ++i) {
    const double t = a(rng);
    const V d = unit({u(rng), u(rng), u(rng)});
    rays.push_back({{0.5 * std::cos(t), 0.5 * std::sin(t), 1}, d, 0});                    // ball
    rays.push_back({{3 + 0.5 * std::cos(t), 0.5 * std::sin(t), 1 + 0.9 * u(rng)}, d, 0}); // can
    rays.push_back({{0.25 * std::cos(t), 3 + 0.25 * std::sin(t), 0.5}, d, 0});            // hat
    rays.push_back({{-3 + 0.3 * std::cos(t), 0.3 * std::sin(t), 1}, d, 0});               // disc
    rays.push_back({{4 * u(rng), 4 * u(rng), 0}, d, 0});                                  // floor
    rays.push_back({{-8, 0.3 * u(rng), 1}, {1, 0, 0}, 0});  // grazing the ball's top
    rays.push_back({{3 + 0.5, -5, 1}, {0, 1, 0}, 0});       // tangent to the can
    rays.push_back({{-8, 0, 1}, {1, 0, 1e-8 * u(rng)}, 0}); // along the ring's plane
  }
  render::RenderSettings st = direct(false);
  st.ab = 1;
  st.ad = 64;
  st.as = 16;
  auto res = render(text, rays, st);
  for (std::size_t i = 0; i < rays.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(res[i].value[k])) << i;
      EXPECT_GE(res[i].value[k], 0) << i;
    }
}

// A triangle mesh (the reference set's octahedron): rays starting on a vertex, an edge or a
// face, pointing out, never hit the mesh; pointing in through the centre, they hit the far
// side, never their own starting point.
TEST_F(StabilityGrazing, RaysStartingOnMeshVerticesAndEdges) {
  std::filesystem::copy_file(radcl::test::data("scenes/octa.rtm"), "octa.rtm");
  load("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey mesh orn 1 octa.rtm 0 0\n");
  ASSERT_EQ(ls->meshes.size(), 1u);
  const scene::TriangleMesh& m = *ls->meshes.begin()->second;
  ASSERT_GE(m.triangles.size(), 8u);
  V c{0, 0, 0};
  for (const auto& p : m.positions)
    c = add(c, mul(p, 1.0 / m.positions.size()));
  double size = 0;
  for (const auto& p : m.positions)
    size = std::max(size, std::sqrt(dot(sub(p, c), sub(p, c))));
  std::vector<V> starts;
  for (const auto& t : m.triangles) {
    const V &a = m.positions[t[0]], &b = m.positions[t[1]], &d = m.positions[t[2]];
    starts.push_back(a);                               // vertex
    starts.push_back(mul(add(a, b), 0.5));             // edge
    starts.push_back(add(mul(a, 0.3), mul(b, 0.7)));   // edge, off centre
    starts.push_back(mul(add(add(a, b), d), 1.0 / 3)); // face
  }
  int n = 0;
  for (const V& p : starts) {
    const V out = unit(sub(p, c));
    auto h = hit(p, out);
    EXPECT_FALSE(h) << "out of " << p[0] << "," << p[1] << "," << p[2] << " t " << (h ? h->t : 0);
    for (const V& tilt : std::vector<V>{{0, 0, 0}, {0.1, -0.05, 0.07}}) {
      const V in = unit(add(mul(out, -1), tilt));
      auto g = hit(p, in);
      ASSERT_TRUE(g) << p[0] << "," << p[1] << "," << p[2];
      EXPECT_GT(g->t, 0.5 * size) << p[0] << "," << p[1] << "," << p[2];
      EXPECT_FALSE(g->front);
      ++n;
    }
  }
  EXPECT_EQ(n, 2 * static_cast<int>(starts.size()));
}

// Glossy, metallic, transmitting and mirror surfaces seen at grazing angles (|cos| from 1e-2
// down to 1e-7) with a lamp glinting in them: finite, non-negative, and no brighter than
// the lamp (100) itself.
TEST_F(StabilityGrazing, GrazingShadingOfGlossyMaterials) {
  const std::string text = "void light lm 0 0 3 100 100 100\n"
                           "lm sphere lamp 0 0 4 20 0 0.5 0.3\n"
                           "void plastic shiny 0 0 5 .5 .5 .5 .05 .01\n"
                           "void metal steel 0 0 5 .8 .8 .8 .9 .02\n"
                           "void trans frost 0 0 7 .6 .6 .6 .04 .05 .5 .5\n"
                           "void glass clear 0 0 3 .9 .9 .9\n"
                           "void mirror mir 0 0 3 .9 .9 .9\n"
                           "shiny polygon f_shiny 0 0 12 -9 -9 0 9 -9 0 9 -3 0 -9 -3 0\n"
                           "steel polygon f_steel 0 0 12 -9 -3 0 9 -3 0 9 3 0 -9 3 0\n"
                           "frost polygon f_frost 0 0 12 -9 3 0 9 3 0 9 9 0 -9 9 0\n"
                           "clear sphere ball 0 0 4 0 -6 1 1\n"
                           "mir sphere bead 0 0 4 0 6 1 1\n"
                           "steel cylinder pipe 0 0 7 -5 0 0 -5 0 3 0.5\n";
  std::vector<render::PrimaryRay> rays;
  for (double c : {1e-2, 1e-3, 1e-4, 1e-5, 1e-7})
    for (double y : {-6.0, -0.2, 0.0, 6.0}) {
      const double s = std::sqrt(1 - c * c);
      rays.push_back({{-8, y, 8 * c / s}, {s, 0, -c}, 0});       // onto the floor, towards the lamp
      rays.push_back({{-8, y + 1e-3, 2 - c}, {1, 0, 0}, 0});     // over the spheres' tops
      rays.push_back({{-5.5 + c * 0.5, -8, 1.5}, {0, 1, 0}, 0}); // along the pipe's side
    }
  render::RenderSettings st = direct(false);
  st.ab = 1;
  st.ad = 64;
  st.as = 0;
  auto res = render(text, rays, st);
  for (std::size_t i = 0; i < rays.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(res[i].value[k])) << i;
      EXPECT_GE(res[i].value[k], 0) << i;
      EXPECT_LE(res[i].value[k], 100) << i;
    }
}

// Convex surfaces, one at a time, inside a uniform glowing bubble (radiance 1, no direct
// source): every ambient sample leaving a sphere, cylinder, cone or polygon (level, tilted) sees
// the bubble unless it hits the surface it leaves, so a diffuse reflectance of 0.5 reads exactly
// 0.5 — near the scene's centre and 3 km from it.
TEST_F(StabilityGrazing, AmbientRaysNeverHitTheirOwnConvexSurface) {
  for (double off : {0.0, 3000.0}) {
    const std::string o = std::to_string(off);
    const std::vector<std::string> shapes = {
        "grey sphere ball 0 0 4 " + o + " 0 1 0.5\n",
        "grey cylinder can 0 0 7 " + o + " 0 0 " + o + " 0 2 0.5\n",
        "grey cone hat 0 0 8 " + o + " 0 0 " + o + " 0 1 0.5 0\n",
        "grey polygon tile 0 0 12 " + std::to_string(off - 1) + " -1 0.5 " +
            std::to_string(off + 1) + " -1 0.5 " + std::to_string(off + 1) + " 1 0.5 " +
            std::to_string(off - 1) + " 1 0.5\n",
        "grey polygon tilt 0 0 12 " + std::to_string(off - 1) + " -1 0.5 " +
            std::to_string(off + 1) + " -1 0.9 " + std::to_string(off + 1) + " 1 1.3 " +
            std::to_string(off - 1) + " 1 0.9\n"};
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      const std::string text = "void glow sky 0 0 4 1 1 1 0\n"
                               "sky bubble dome 0 0 4 0 0 0 6000\n"
                               "void plastic grey 0 0 5 .5 .5 .5 0 0\n" +
                               shapes[k];
      std::vector<render::PrimaryRay> rays;
      for (int i = 0; i < 24; ++i) {
        const double a = 2 * kPi * i / 24, c = std::cos(a), s = std::sin(a);
        if (k >= 3)
          rays.push_back({{off + 0.5 * c, 0.5 * s, 3}, {0.1 * c, 0.1 * s, -1}, 0});
        else
          rays.push_back({{off + 3 * c, 3 * s,
                           k == 0   ? 1 + 0.45 * std::sin(3 * a)
                           : k == 1 ? 1.3
                                    : 0.4},
                          {-c, -s, k == 1 ? -0.1 : 0},
                          0});
      }
      render::RenderSettings st = direct(false);
      st.ab = 1;
      st.ad = 1024;
      st.as = 0;
      auto res = render(text, rays, st);
      for (std::size_t i = 0; i < rays.size(); ++i) {
        ASSERT_TRUE(res[i].hit) << i;
        EXPECT_NEAR(res[i].value[0], 0.5, 1e-5)
            << "offset " << off << " shape " << k << " ray " << i;
      }
    }
  }
}
