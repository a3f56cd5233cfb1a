// antimatter (scene-format.md §3.16): holes cut through a wall, a notch cut into a block whose
// cut faces are shaded with mod1, shadow rays through both, and the scene compiler's checks.
// Expected values are worked out by hand (plastic under a sun, -ab 0).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "radcl/device/context.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/compile/compiled_scene.h"
#include "radcl/render/pipeline/irradiance_meter.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "warnings.h"

using namespace radcl;

namespace {

constexpr double kL = 1000;         // radiance of the lights
constexpr double kSunAngle = 0.533; // degrees

double sun_solid_angle() {
  return 2 * M_PI * (1 - std::cos(kSunAngle * M_PI / 360));
}

// An axis-aligned box of polygons with outward normals (as genbox makes it).
std::string box(const std::string& mod, const std::string& name, double x0, double y0, double z0,
                double x1, double y1, double z1) {
  std::ostringstream s;
  auto face = [&](const char* side, std::initializer_list<std::array<double, 3>> v) {
    s << mod << " polygon " << name << "." << side << " 0 0 12";
    for (const auto& p : v)
      s << "  " << p[0] << " " << p[1] << " " << p[2];
    s << "\n";
  };
  face("bottom", {{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}});
  face("top", {{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}});
  face("west", {{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}});
  face("east", {{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}});
  face("south", {{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}});
  face("north", {{x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}});
  return s.str();
}

struct Scene {
  explicit Scene(const std::string& body) { std::ofstream(path) << body; }
  // Radiance (green) of each ray, or irradiance at -I sensors.
  std::vector<double> values(std::vector<render::PrimaryRay> rays, bool sensors = false) {
    scene::LoadedScene ls = scene::load_scene({path});
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    st.ds = 0.01;
    st.dt = 0;
    st.dc = 1;
    st.lw = 1e-9; // deterministic: no Russian roulette
    st.lr = 60;
    st.irradiance_I = sensors;
    render::Renderer r(ls, st, device::default_context());
    std::vector<render::PrimaryResult> res(rays.size());
    r.render(rays, res);
    std::vector<double> out;
    for (const auto& x : res)
      out.push_back(x.value[1]);
    return out;
  }
  // Where an -I sensor along r measures in this scene.
  render::Vec3d meter(const render::PrimaryRay& r) {
    geometry::SceneGeometry geom(scene::load_scene({path}));
    return render::meter_point(geom, r.org, r.dir);
  }
  // Compiles only (no device program): for the argument checks.
  render::CompiledScene compile() {
    scene::LoadedScene ls = scene::load_scene({path});
    geometry::SceneGeometry geom(ls);
    return render::compile_scene(ls, geom);
  }
  test::TempFolder dir{"antimatter"};
  std::string path = (dir / "s.rad").string();
};

// A lamp facing down at z = 5 (half-width w), an opaque plastic wall at z = 1 facing down, and
// an antimatter box (void mod1) around a 1 x 1 hole in the wall.
std::string wall_with_hole(double lamp_half_width) {
  double w = lamp_half_width;
  std::ostringstream s;
  s << "void light lamp 0 0 3 " << kL << " " << kL << " " << kL << "\n"
    << "lamp polygon ceiling 0 0 12 " << -w << " " << -w << " 5  " << -w << " " << w << " 5  " << w
    << " " << w << " 5  " << w << " " << -w << " 5\n"
    << "void plastic wallmat 0 0 5 0.5 0.5 0.5 0 0\n"
    << "wallmat polygon wall 0 0 12 -50 -50 1  -50 50 1  50 50 1  50 -50 1\n"
    << "void antimatter hole 2 void wallmat 0 0\n"
    << box("hole", "cutter", -0.5, -0.5, 0.5, 0.5, 0.5, 1.5);
  return s.str();
}

} // namespace

TEST(Antimatter, HoleThroughWallShowsTheLightBehind) {
  Scene s(wall_with_hole(100));
  auto v = s.values(
      {{{0.07, 0.11, 0}, {0, 0, 1}, 0},   // through the hole: the lamp (off the triangles' seams)
       {{0.3, -0.2, 0}, {0, 0, 1}, 0},    // elsewhere in the hole
       {{2, 0, 0}, {0, 0, 1}, 0},         // beside it: the unlit front of the wall
       {{0.2, 0, 0}, {-0.6, 0, 1}, 0},    // slanted, out through a side of the box above the wall
       {{0.8, 0, 0.5}, {0.2, 0, 1}, 0}}); // starts beside the box: meets the wall
  EXPECT_NEAR(v[0], kL, 1e-6 * kL);
  EXPECT_NEAR(v[1], kL, 1e-6 * kL);
  EXPECT_EQ(v[2], 0.0);
  EXPECT_NEAR(v[3], kL, 1e-6 * kL);
  EXPECT_EQ(v[4], 0.0);
}

TEST(Antimatter, ShadowRaysReachThePointBehindTheWallOnlyThroughTheHole) {
  // A 2 x 2 lamp seen whole through the hole from (0, 0, 0.2); from (2, 0, 0.2) the wall hides
  // it. The first sensor must get what it gets with no wall at all.
  std::string lamp = wall_with_hole(1).substr(0, wall_with_hole(1).find("void plastic"));
  Scene open(lamp);
  Scene holed(wall_with_hole(1));
  std::vector<render::PrimaryRay> sensors = {{{0, 0, 0.2}, {0, 0, 1}, 0},
                                             {{2, 0, 0.2}, {0, 0, 1}, 0}};
  auto e = holed.values(sensors, true);
  // The meters must measure at the same points: their offset grows with a small scene's size.
  std::vector<render::PrimaryRay> open_sensors = sensors;
  for (std::size_t i = 0; i < sensors.size(); ++i)
    open_sensors[i].org[2] += holed.meter(sensors[i])[2] - open.meter(sensors[i])[2];
  auto e_open = open.values(open_sensors, true);
  // Irradiance from a 2 x 2 square of radiance L, 4.8 above and centred: four corner
  // rectangles 1 x 1 (Radiance's source sampling is within a percent of it).
  double X = 1 / 4.8, a = X / std::sqrt(1 + X * X);
  double expect = kL * 2 * (2 * a * std::atan(a));
  EXPECT_NEAR(e_open[0], expect, 0.01 * expect);
  EXPECT_NEAR(e[0], e_open[0], 1e-5 * e_open[0]);
  EXPECT_GT(e_open[1], 0.5 * expect);
  EXPECT_EQ(e[1], 0.0);
}

namespace {
// A plastic block (top at z = 0) with a notch cut by antimatter `cut`, which shades its cut faces
// with the block's own material; a sun at 45 degrees from +x.
std::string notched_block() {
  std::ostringstream s;
  s << "void light solar 0 0 3 " << kL << " " << kL << " " << kL << "\n"
    << "solar source sun 0 0 4 1 0 1 " << kSunAngle << "\n"
    << "void plastic solid 0 0 5 0.5 0.5 0.5 0 0\n"
    << box("solid", "block", -2, -2, -1, 2, 2, 0) << "void antimatter cut 1 solid 0 0\n"
    << box("cut", "notch", -0.5, -0.5, -0.5, 0.5, 0.5, 1);
  return s.str();
}
} // namespace

TEST(Antimatter, CutFacesAreShadedWithMod1FacingTheRay) {
  Scene s(notched_block());
  double c45 = std::sqrt(0.5);
  double lit = 0.5 / M_PI * kL * sun_solid_angle() * c45; // plastic 0.5, cos 45 degrees
  auto v = s.values(
      {{{-0.2, 0, 3}, {0, 0, -1}, 0},  // the notch's floor, its shadow ray out through the notch
       {{0.3, 0, 3}, {0, 0, -1}, 0},   // the floor in the shadow of the block beyond the notch
       {{1.75, 0, 2}, {-1, 0, -1}, 0}, // the notch's west wall (cut face facing +x)
       {{1.5, 0, 3}, {0, 0, -1}, 0}}); // the block's top beside the notch
  EXPECT_NEAR(v[0], lit, 1e-4 * lit);
  EXPECT_EQ(v[1], 0.0);
  EXPECT_NEAR(v[2], lit, 1e-4 * lit);
  EXPECT_NEAR(v[3], lit, 1e-4 * lit);
}

TEST(Antimatter, ArgumentErrorsAndWarnings) {
  std::string wall = "void plastic wallmat 0 0 5 0.5 0.5 0.5 0 0\n"
                     "wallmat polygon wall 0 0 12 -5 -5 1  -5 5 1  5 5 1  5 -5 1\n";
  {
    Scene s(wall + "void antimatter bad 0 0 0\n" + box("bad", "b", 0, 0, 0, 1, 1, 1));
    try {
      s.compile();
      ADD_FAILURE() << "no error";
    } catch (const FatalError& e) {
      // The reader refuses it, naming the file and line.
      EXPECT_NE(std::string(e.what()).find("line 3): bad # arguments for antimatter \"bad\""),
                std::string::npos)
          << e.what();
    }
  }
  {
    test::CapturedWarnings warnings;
    Scene s(wall + "void antimatter cut 4 void nothere wallmat wallmat 0 0\n" +
            box("cut", "b", 0, 0, 0, 1, 1, 1));
    render::CompiledScene cs = s.compile();
    ASSERT_EQ(warnings.list().size(), 2u);
    EXPECT_EQ(warnings.list()[0], "unknown modifier \"nothere\" for antimatter \"cut\"");
    EXPECT_EQ(warnings.list()[1], "duplicate modifier for antimatter \"cut\"");
    // The wall is clipped (its bit set), the box's faces are not; void mod1 uses no counter.
    EXPECT_EQ(cs.surfaces[1].clip, 1u);
    EXPECT_EQ(cs.surfaces[1].slots, 0u);
    EXPECT_EQ(cs.surfaces[3].clip, 0u);
    EXPECT_TRUE(cs.features.has(RC_OBJ_ANTIMATTER));
  }
  {
    // Radcl's limits: 32 clipped modifiers, 4 antimatters whose mod1 shades.
    std::string many;
    for (int i = 0; i < 33; ++i)
      many += "void plastic m" + std::to_string(i) + " 0 0 5 0.5 0.5 0.5 0 0\n";
    std::string list;
    for (int i = 0; i < 33; ++i)
      list += " m" + std::to_string(i);
    Scene s(many + "void antimatter cut 34 void" + list + " 0 0\n" +
            box("cut", "b", 0, 0, 0, 1, 1, 1));
    EXPECT_THROW(s.compile(), FatalError);
    std::string five;
    for (int i = 0; i < 5; ++i)
      five += "void antimatter a" + std::to_string(i) + " 1 m0 0 0\n" +
              box("a" + std::to_string(i), "b" + std::to_string(i), 2 * i, 0, 0, 2 * i + 1, 1, 1);
    Scene t(many + five);
    EXPECT_THROW(t.compile(), FatalError);
  }
}

TEST(Antimatter, SceneWithoutAntimatterCompilesNoAntimatterCode) {
  Scene s("void plastic wallmat 0 0 5 0.5 0.5 0.5 0 0\n"
          "wallmat polygon wall 0 0 12 -5 -5 1  -5 5 1  5 5 1  5 -5 1\n");
  render::CompiledScene cs = s.compile();
  EXPECT_FALSE(cs.features.has(RC_OBJ_ANTIMATTER));
  EXPECT_EQ(cs.features.options().find("ANTIMATTER"), std::string::npos);
}
