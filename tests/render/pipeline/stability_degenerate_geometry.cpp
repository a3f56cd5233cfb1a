// Issue 8 case 3: coincident and coplanar surfaces, a polygon with a seam-connected hole,
// concave and self-touching polygons, zero-area and collinear polygons, degenerate cones,
// cylinders, rings and spheres (Radiance 5.4a: a warning and the surface is ignored, except a
// negative ring radius, which is fatal), and a 10 km ground with centimetre detail on it.
#include <array>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/loader.h"
#include "radcl/util/error.h"
#include "scene_dir.h"
#include "warnings.h"

using namespace radcl;

namespace {

constexpr double kPi = std::numbers::pi;
using V = std::array<double, 3>;

class StabilityDegenerate : public test::SceneDir {
protected:
  std::optional<scene::LoadedScene> ls;
  std::optional<geometry::SceneGeometry> geom;

  test::CapturedWarnings captured;

  std::vector<std::string>& warnings() { return captured.list(); }
  void load(const std::string& text) {
    std::ofstream("g.rad", std::ios::trunc) << text;
    geom.reset();
    ls = scene::load_scene({"g.rad"});
    geom.emplace(*ls);
  }
  std::string name_down(double x, double y, double z = 5) const {
    auto h = geom->intersect({x, y, z}, {0, 0, -1}, 0, 1e30);
    return h ? ls->main.objects[h->object].name : "";
  }
  bool warned(const std::string& w) {
    for (const auto& s : warnings())
      if (s == w) return true;
    return false;
  }
};

// Even-odd rule (a point inside crosses the outline an odd number of times going +x).
bool inside(const std::vector<std::array<double, 2>>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto &a = poly[i], &b = poly[j];
    if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) in = !in;
  }
  return in;
}

std::string polygon(const std::string& mod, const std::string& name,
                    const std::vector<std::array<double, 2>>& pts, double z = 0) {
  std::string s = mod + " polygon " + name + " 0 0 " + std::to_string(3 * pts.size());
  char buf[100];
  for (const auto& p : pts) {
    std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g", p[0], p[1], z);
    s += buf;
  }
  return s + "\n";
}

} // namespace

// Coincident copies of a polygon, coplanar overlapping polygons and coincident spheres: every
// ray takes the same one of them (Radiance keeps the first it tests at equal distance: the
// lower object number), so no ray mixes the two.
TEST_F(StabilityDegenerate, CoincidentSurfacesPickOne) {
  const std::vector<std::array<double, 2>> sq = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::vector<std::array<double, 2>> big = {{10, 0}, {16, 0}, {16, 6}, {10, 6}};
  const std::vector<std::array<double, 2>> small = {{11, 1}, {15, 1}, {15, 5}, {11, 5}};
  load("void plastic red 0 0 5 .5 0 0 0 0\nvoid plastic blue 0 0 5 0 0 .5 0 0\n" +
       polygon("red", "a", sq) + polygon("blue", "b", sq) + polygon("red", "big", big) +
       polygon("blue", "small", small) + "red sphere s1 0 0 4 -5 2 0 1\n" +
       "blue sphere s2 0 0 4 -5 2 0 1\n");
  int a = 0, b = 0, bg = 0, sm = 0, s1 = 0, s2 = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const double u = (i + 0.5) / 40, v = (j + 0.5) / 40;
      const std::string n1 = name_down(4 * u, 4 * v);
      a += n1 == "a", b += n1 == "b";
      const std::string n2 = name_down(11 + 4 * u, 1 + 4 * v);
      bg += n2 == "big", sm += n2 == "small";
      const std::string n3 = name_down(-5.7 + 1.4 * u, 1.3 + 1.4 * v);
      s1 += n3 == "s1", s2 += n3 == "s2";
    }
  EXPECT_EQ(a, 1600);
  EXPECT_EQ(b, 0);
  // Coplanar but different polygons: Embree's float distances nominate them, so which one
  // wins is not Radiance's rule, but it is the same one for every ray.
  EXPECT_TRUE(bg == 1600 || sm == 1600) << bg << " " << sm;
  EXPECT_EQ(s1 + s2, 1600);
  EXPECT_EQ(s2, 0);
}

// A square with a square hole joined by a seam, concave and self-touching outlines: a ray
// hits where the even-odd rule says the point is inside, and nowhere else.
TEST_F(StabilityDegenerate, HoleConcaveAndSelfTouchingPolygons) {
  const std::vector<std::vector<std::array<double, 2>>> shapes = {
      // outline counter-clockwise, then the hole clockwise from the seam
      {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}},
      // a comb
      {{10, 0}, {14, 0}, {14, 4}, {13, 4}, {13, 1}, {12, 4}, {11.5, 1}, {11, 4}, {10, 4}},
      // two squares touching at one corner, one outline
      {{20, 0}, {22, 0}, {22, 2}, {24, 2}, {24, 4}, {22, 4}, {22, 2}, {20, 2}},
      // a star
      {{32, 0}, {32.6, 1.4}, {34, 2}, {32.6, 2.6}, {32, 4}, {31.4, 2.6}, {30, 2}, {31.4, 1.4}}};
  std::string text = "void plastic grey 0 0 5 .5 .5 .5 0 0\n";
  for (std::size_t k = 0; k < shapes.size(); ++k)
    text += polygon("grey", "p" + std::to_string(k), shapes[k]);
  load(text);
  EXPECT_TRUE(warnings().empty()) << warnings().front();
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const double x0 = shapes[k][0][0] == 32 ? 30 : shapes[k][0][0];
    int wrong = 0;
    for (int i = 0; i < 97; ++i)
      for (int j = 0; j < 97; ++j) {
        const double x = x0 - 0.5 + 5.0 * (i + 0.37) / 97, y = -0.5 + 5.0 * (j + 0.61) / 97;
        const bool want = inside(shapes[k], x, y);
        wrong += (name_down(x, y) == "p" + std::to_string(k)) != want;
      }
    EXPECT_EQ(wrong, 0) << "shape " << k;
  }
}

// Zero-area polygons (all vertices equal, collinear vertices, a spike) get Radiance's
// "zero area" warning and are left out; a polygon with a repeated vertex is kept.
TEST_F(StabilityDegenerate, ZeroAreaAndCollinearPolygons) {
  load("void plastic grey 0 0 5 .5 .5 .5 0 0\n"
       "grey polygon point 0 0 9 1 1 0 1 1 0 1 1 0\n"
       "grey polygon line 0 0 9 0 0 0 1 1 0 2 2 0\n"
       "grey polygon line5 0 0 15 0 0 0 1 0 0 2 0 0 3 0 0 1.5 0 0\n"
       "grey polygon spike 0 0 12 5 5 0 6 5 0 7 5 0 6 5 0\n"
       "grey polygon repeat 0 0 15 10 0 0 12 0 0 12 0 0 12 2 0 10 2 0\n");
  for (const char* n : {"point", "line", "line5", "spike"})
    EXPECT_TRUE(warned(std::string("zero area for polygon \"") + n + "\"")) << n;
  EXPECT_EQ(geom->counts().skipped_degenerate, 4u);
  EXPECT_EQ(geom->counts().polygons, 1u);
  EXPECT_EQ(name_down(1, 1), "");
  EXPECT_EQ(name_down(0.5, 0.5), "");
  EXPECT_EQ(name_down(1.5, 0), "");
  EXPECT_EQ(name_down(6, 5), "");
  EXPECT_EQ(name_down(11, 1), "repeat");
  // The whole scene renders.
  render::RenderSettings st;
  st.ab = 0;
  auto res = render_rays("g.rad", {{{11, 1, 5}, {0, 0, -1}, 0}, {{1, 1, 5}, {0, 0, -1}, 0}}, st);
  EXPECT_TRUE(res[0].hit);
  EXPECT_FALSE(res[1].hit);
}

// Degenerate quadrics as Radiance 5.4a treats them: ignored with a warning.
TEST_F(StabilityDegenerate, DegenerateQuadricsWarnAndAreIgnored) {
  load("void plastic grey 0 0 5 .5 .5 .5 0 0\n"
       "grey cone pin 0 0 8 0 0 0 0 0 1 0 0\n"
       "grey cone flat 0 0 8 0 0 1 0 0 1 0.5 1\n"
       "grey cone opposite 0 0 8 0 0 0 0 0 1 1 -1\n"
       "grey cylinder wire 0 0 7 0 0 0 0 0 1 0\n"
       "grey cylinder dot 0 0 7 1 1 1 1 1 1 0.5\n"
       "grey ring annulus0 0 0 8 0 0 2 0 0 1 0.5 0.5\n"
       "grey ring nowhere 0 0 8 0 0 2 0 0 0 0 1\n"
       "grey sphere nil 0 0 4 0 0 0 0\n"
       "grey ring ok 0 0 8 0 0 0.5 0 0 1 0 2\n");
  for (const char* w :
       {"illegal radii for cone \"pin\"", "unknown orientation for cone \"flat\"",
        "illegal radii for cone \"opposite\"", "illegal radii for cylinder \"wire\"",
        "unknown orientation for cylinder \"dot\"", "illegal radii for ring \"annulus0\"",
        "unknown orientation for ring \"nowhere\"", "zero radius for sphere \"nil\""})
    EXPECT_TRUE(warned(w)) << w;
  EXPECT_EQ(geom->counts().skipped_degenerate, 8u);
  EXPECT_EQ(name_down(0.2, 0.1), "ok");
  // A negative ring radius is fatal.
  try {
    load("void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey ring neg 0 0 8 0 0 0 0 0 1 -1 0\n");
    FAIL() << "no error";
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "negative radii for ring \"neg\"");
  }
  // A light on a degenerate ring is no source (Radiance: "illegal source").
  std::ofstream("l.rad") << "void light glow1 0 0 3 1 1 1\nglow1 ring lamp 0 0 8 0 0 2 0 0 1 0 0\n";
  try {
    render::RenderSettings st;
    render_rays("l.rad", {{{0, 0, 0}, {0, 0, 1}, 0}}, st);
    FAIL() << "no error";
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "illegal source for ring \"lamp\"");
  }
}

// A 10 km ground with a 1 cm cube and a 4 mm ball on it under a sun at 30 degrees: camera
// rays find the small surfaces; the cube's top and the ground in the open read the sun's
// exact irradiance, the ground 1 mm from the cube's shaded side and under the ball reads 0,
// and a sensor on the ground facing down reads nothing of the sun.
TEST_F(StabilityDegenerate, HugeGroundWithSmallDetail) {
  const double L = 1e6, ang = 0.5; // sun radiance and diameter (degrees)
  const double omega = 2 * kPi * (1 - std::cos(ang / 2 * kPi / 180));
  const double el = 30 * kPi / 180;
  char sun[200];
  std::snprintf(sun, sizeof sun,
                "void light sunl 0 0 3 %g %g %g\nsunl source sun 0 0 4 %.17g 0 %.17g %g\n", L, L, L,
                std::cos(el), std::sin(el), ang);
  // The cube spans [0, 0.01]^3 with its shaded side (away from the sun, at +x... the sun is
  // towards +x) at x = 0.
  const std::string text = std::string(sun) +
                           "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                           "grey polygon ground 0 0 12 -5000 -5000 0 5000 -5000 0 5000 5000 0 "
                           "-5000 5000 0\n"
                           "grey polygon c_bot 0 0 12 0 0 0 0 .01 0 .01 .01 0 .01 0 0\n"
                           "grey polygon c_top 0 0 12 0 0 .01 .01 0 .01 .01 .01 .01 0 .01 .01\n"
                           "grey polygon c_xlo 0 0 12 0 0 0 0 0 .01 0 .01 .01 0 .01 0\n"
                           "grey polygon c_xhi 0 0 12 .01 0 0 .01 .01 0 .01 .01 .01 .01 0 .01\n"
                           "grey polygon c_ylo 0 0 12 0 0 0 .01 0 0 .01 0 .01 0 0 .01\n"
                           "grey polygon c_yhi 0 0 12 0 .01 0 0 .01 .01 .01 .01 .01 .01 .01 0\n"
                           "grey sphere ball 0 0 4 0.05 0.05 0.002 0.002\n"
                           "grey polygon fin 0 0 12 0.1 0 0 0.1 0 .01 0.1 .01 .01 0.1 .01 0\n";
  load(text);
  auto name = [&](const V& o, const V& d) {
    auto h = geom->intersect(o, d, 0, 1e30);
    return h ? ls->main.objects[h->object].name : std::string();
  };
  EXPECT_EQ(name({0.005, 0.005, 1}, {0, 0, -1}), "c_top");
  EXPECT_EQ(name({-1, 0.005, 0.005}, {1, 0, 0}), "c_xlo");
  EXPECT_EQ(name({0.05, 0.005, 0.005}, {-1, 0, 0}), "c_xhi");
  EXPECT_EQ(name({-0.0001, 0.005, 1}, {0, 0, -1}), "ground");
  EXPECT_EQ(name({0.05, 0.05, 1}, {0, 0, -1}), "ball");
  EXPECT_EQ(name({0.05, 0.0525, 1}, {0, 0, -1}), "ground");
  // From inside the cube down: the cube's bottom and the ground lie in one plane, and the
  // ground, the lower object number, wins as in Radiance.
  EXPECT_EQ(name({0.005, 0.005, 0.005}, {0.3, 0.2, -1}), "ground");
  EXPECT_EQ(name({0.005, 0.005, 0.005}, {0.3, 0.2, 1}), "c_top");

  const double full = L * omega * std::sin(el);
  struct Case {
    V p, n;
    double want;
  };
  const std::vector<Case> cases = {
      {{0.005, 0.005, 0.01}, {0, 0, 1}, full}, // the cube's top
      {{0.5, 0.3, 0}, {0, 0, 1}, full},        // open ground
      {{3000, -2000, 0}, {0, 0, 1}, full},     // far out on the ground
      {{-0.001, 0.005, 0}, {0, 0, 1}, 0},      // 1 mm from the shaded side
      {{-0.003, 0.005, 0}, {0, 0, 1}, 0},      // 3 mm from it
      {{0.05 - 0.003, 0.05, 0}, {0, 0, 1}, 0}, // in the ball's shadow
      {{0.099, 0.005, 0}, {0, 0, 1}, 0},       // 1 mm from a thin fin's shade side
      {{0.0995, 0.005, 0.005}, {1, 0, 0}, 0},  // 0.5 mm from the fin, facing it
      {{0.5, 0.3, 0}, {0, 0, -1}, 0},          // under the ground
      {{0.5, 0.3, 0}, {1, 0, -0.2}, 0},        // under the ground, towards the sun
      {{0.01, 0.005, 0.005}, {1, 0, 0}, L * omega * std::cos(el)}, // the cube's lit side
  };
  std::vector<render::PrimaryRay> rays;
  for (const Case& c : cases) {
    V n = c.n;
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    rays.push_back({c.p, {n[0] / l, n[1] / l, n[2] / l}, 0});
  }
  render::RenderSettings st = test::direct_light_settings(true);
  auto res = render_rays("g.rad", rays, st);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    ASSERT_TRUE(std::isfinite(res[i].value[0])) << i;
    EXPECT_NEAR(res[i].value[0], cases[i].want, 1e-4 * cases[i].want + 1e-9) << "case " << i;
  }
}

// The same kind of detail 4 km from the scene's centre, where float positions are 0.24 mm
// apart and rays leave surfaces 8e-7 x 4000 = 3.2 mm along (hit_output.cl's rc_leave): a fin 1 cm
// tall shades the ground 5 mm and more from it; the open ground reads the sun.
std::vector<double> far_fin_irradiance(const std::vector<double>& gaps, double& full) {
  const double L = 1e6, ang = 0.5, el = 30 * kPi / 180;
  full = L * 2 * kPi * (1 - std::cos(ang / 2 * kPi / 180)) * std::sin(el);
  char sun[200];
  std::snprintf(sun, sizeof sun,
                "void light sunl 0 0 3 %g %g %g\nsunl source sun 0 0 4 %.17g 0 %.17g %g\n", L, L, L,
                std::cos(el), std::sin(el), ang);
  std::ofstream("far.rad") << sun
                           << "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
                              "grey polygon ground 0 0 12 -5000 -5000 0 5000 -5000 0 5000 5000 0 "
                              "-5000 5000 0\n"
                              "grey polygon fin 0 0 12 4000 -3000 0 4000 -3000 .01 4000 -2999.99 "
                              ".01 4000 -2999.99 0\n";
  std::vector<render::PrimaryRay> rays;
  for (double g : gaps)
    rays.push_back({{4000 - g, -2999.995, 0}, {0, 0, 1}, 0});
  render::RenderSettings st = test::direct_light_settings(true);
  std::vector<double> out;
  scene::LoadedScene scene = scene::load_scene({"far.rad"});
  render::Renderer renderer(scene, st, device::default_context());
  std::vector<render::PrimaryResult> res(rays.size());
  renderer.render(rays, res);
  for (const auto& r : res)
    out.push_back(r.value[0]);
  return out;
}

TEST_F(StabilityDegenerate, FarDetailOnHugeGround) {
  double full = 0;
  auto e = far_fin_irradiance({0.005, 0.01, -0.005}, full);
  EXPECT_EQ(e[0], 0);
  EXPECT_EQ(e[1], 0);
  EXPECT_NEAR(e[2], full, 1e-5 * full); // the sunny side
}

// Closer than the float rounding of the meter's point (1.6 mm here) the fin was taken for the
// surface the meter's rays leave and the ground read the full sun at 0.5, 1 and 2 mm. A meter
// lies on no surface (geometry::Ray::free_origin), so Radiance's shadows hold, as in double.
TEST_F(StabilityDegenerate, FarDetailWithinFloatResolution) {
  double full = 0;
  auto e = far_fin_irradiance({0.0005, 0.001, 0.002}, full);
  for (double v : e)
    EXPECT_EQ(v, 0);
}
