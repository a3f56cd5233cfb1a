// compile_sources(): the luminaires scene's eight sources against values worked out by hand
// from tests/data/scenes/luminaires.rad, and Radiance's messages for bad sources.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <vector>

#include "radcl/render/lights/light_sources.h"
#include "radcl/scene/loader.h"
#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"
#include "warnings.h"

using namespace radcl;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = std::numbers::pi;

// Kept from the first scene compiled on, as that scene's warnings are checked.
std::vector<std::string>& warnings() {
  static test::CapturedWarnings captured;
  return captured.list();
}

struct Compiled {
  scene::LoadedScene scene;
  std::unique_ptr<geometry::SceneGeometry> geom;
  render::CompiledSources out;
};

// Surface index = object number + 1000, so the mapping is visible in the records.
Compiled compile_file(const std::string& path) {
  Compiled c;
  c.scene = scene::load_scene({path});
  c.geom = std::make_unique<geometry::SceneGeometry>(c.scene);
  c.out = render::compile_sources(
      c.scene.main, *c.geom, [](std::int32_t o) { return static_cast<std::uint32_t>(o + 1000); });
  return c;
}

Compiled compile_text(const std::string& text) {
  const test::TempFolder tmp("light_sources");
  const fs::path p = tmp / "s.rad";
  std::ofstream(p) << text;
  warnings().clear();
  return compile_file(p.string());
}

std::string fatal_of(const std::string& text) {
  try {
    compile_text(text);
  } catch (const FatalError& e) {
    return e.what();
  }
  return "(no error)";
}

bool has_warning(const std::string& w) {
  for (const auto& s : warnings())
    if (s == w) return true;
  return false;
}

void expect_vec(const rc_float4& v, double x, double y, double z, double tol = 1e-5) {
  EXPECT_NEAR(v.x, x, tol);
  EXPECT_NEAR(v.y, y, tol);
  EXPECT_NEAR(v.z, z, tol);
}

} // namespace

TEST(LightSources, LuminairesScene) {
  Compiled c = compile_file(test::data("scenes/luminaires.rad"));
  const auto& s = c.out.sources;
  ASSERT_EQ(s.size(), 8u);
  // Room 8 x 6 x 2.8: everything is re-centred on (4, 3, 1.4).
  const auto ctr = c.geom->centre();
  EXPECT_NEAR(ctr[0], 4, 1e-9);
  EXPECT_NEAR(ctr[1], 3, 1e-9);
  EXPECT_NEAR(ctr[2], 1.4, 1e-9);

  // panel1..4 (objects 15..18): 0.6 x 0.6 squares at z 2.79, clockwise seen from above, so
  // Radiance's normal points down; a rectangle is sampled over its own half edges.
  const double px[] = {2.0, 6.0, 2.0, 6.0}, py[] = {1.5, 1.5, 4.5, 4.5};
  for (int i = 0; i < 4; ++i) {
    const rc_source& p = s[i];
    EXPECT_EQ(p.kind, RC_SRC_FLAT);
    EXPECT_EQ(p.flags, 0u);
    EXPECT_EQ(p.surface, 1015u + i);
    expect_vec(p.pos, px[i] - 4, py[i] - 3, 2.79 - 1.4);
    EXPECT_NEAR(p.pos.w, std::sqrt(0.18), 1e-6); // centre to corner
    expect_vec(p.axis, 0, 0, -1);
    EXPECT_NEAR(p.axis.w, 0.36, 1e-6);
    expect_vec(p.su, 0.3, 0, 0);
    expect_vec(p.sv, 0, -0.3, 0);
    EXPECT_NEAR(p.su.w, 0, 1e-6);
    EXPECT_NEAR(p.sv.w, 0, 1e-6);
    expect_vec(p.emit, 30, 29, 27);
    EXPECT_EQ(p.nverts, 4u);
    EXPECT_EQ(p.verts, 4u * i);
    EXPECT_FLOAT_EQ(p.spot.w, -2);
  }
  ASSERT_EQ(c.out.verts.size(), 20u);
  expect_vec(c.out.verts[0], 1.7 - 4, 1.8 - 3, 2.79 - 1.4);

  // spot1: disc of radius 0.06 facing down, spotlight 40 degrees, focus 1.
  const rc_source& sp = s[4];
  EXPECT_EQ(sp.kind, RC_SRC_FLAT);
  EXPECT_EQ(sp.flags, RC_SRCF_SPOT);
  EXPECT_EQ(sp.surface, 1019u);
  EXPECT_EQ(sp.nverts, 0u);
  expect_vec(sp.pos, 0, 0, 1.39);
  EXPECT_NEAR(sp.pos.w, 0.06, 1e-7);
  expect_vec(sp.axis, 0, 0, -1);
  EXPECT_NEAR(sp.axis.w, kPi * 0.0036, 1e-7);
  EXPECT_NEAR(sp.su.w, 0, 1e-9);
  EXPECT_NEAR(std::hypot(sp.su.x, sp.su.y, sp.su.z), 0.06, 1e-7);
  EXPECT_NEAR(sp.su.x * sp.sv.x + sp.su.y * sp.sv.y + sp.su.z * sp.sv.z, 0, 1e-9);
  // su x sv along the normal.
  EXPECT_LT(sp.su.x * sp.sv.y - sp.su.y * sp.sv.x, 0);
  expect_vec(sp.emit, 1500, 1400, 1200);
  expect_vec(sp.spot, 0, 0, -1);
  EXPECT_NEAR(sp.spot.w, std::cos(20 * kPi / 180), 1e-6);
  EXPECT_FLOAT_EQ(sp.spot_focus, 1);

  // pendant: glow sphere, radius of influence 1.5.
  const rc_source& pe = s[5];
  EXPECT_EQ(pe.kind, RC_SRC_SPHERE);
  EXPECT_EQ(pe.flags, RC_SRCF_GLOW);
  EXPECT_EQ(pe.surface, 1020u);
  expect_vec(pe.pos, 0, -2, 0.8);
  EXPECT_NEAR(pe.pos.w, 0.12, 1e-7);
  EXPECT_NEAR(pe.axis.w, kPi * 0.0144, 1e-6);
  EXPECT_NEAR(pe.emit.w, 1.5, 1e-7);
  expect_vec(pe.emit, 50, 45, 40);

  // bulb: light sphere.
  const rc_source& bu = s[6];
  EXPECT_EQ(bu.kind, RC_SRC_SPHERE);
  EXPECT_EQ(bu.flags, 0u);
  expect_vec(bu.pos, -3, 2.2, 0.4);
  EXPECT_NEAR(bu.pos.w, 0.03, 1e-7);
  expect_vec(bu.emit, 2000, 1800, 1500);

  // skylight_port: 1 x 1 illum facing down.
  const rc_source& sk = s[7];
  EXPECT_EQ(sk.kind, RC_SRC_FLAT);
  EXPECT_EQ(sk.flags, RC_SRCF_ILLUM);
  EXPECT_EQ(sk.surface, 1022u);
  expect_vec(sk.pos, 0, 2, 1.38);
  expect_vec(sk.axis, 0, 0, -1);
  EXPECT_NEAR(sk.axis.w, 1.0, 1e-6);
  expect_vec(sk.emit, 80, 85, 95);
  EXPECT_EQ(sk.verts, 16u);
}

TEST(LightSources, DistantSources) {
  Compiled c = compile_text("void light solar 0 0 3 1e6 1e6 1e6\n"
                            "solar source sun 0 0 4 0 3 4 0.533\n"
                            "void glow skyglow 0 0 4 1 1 1 0\n"
                            "skyglow source sky 0 0 4 0 0 1 180\n"
                            "void plastic m 0 0 5 .5 .5 .5 0 0\n"
                            "m sphere s 0 0 4 0 0 0 1\n");
  ASSERT_EQ(c.out.sources.size(), 1u); // glow on a source is never a direct source
  const rc_source& d = c.out.sources[0];
  EXPECT_EQ(d.kind, RC_SRC_DISTANT);
  EXPECT_EQ(d.surface, RC_NONE);
  expect_vec(d.pos, 0, 0.6, 0.8);
  const double omega = 2 * kPi * (1 - std::cos(0.533 / 2 * kPi / 180));
  EXPECT_NEAR(d.axis.w, omega, omega * 1e-6);
}

TEST(LightSources, PolygonSamplingRectangleCoversIt) {
  // A triangle: not a parallelogram, so the smallest covering rectangle (one side along an
  // edge) is used, centred off the centroid.
  Compiled c = compile_text("void light l 0 0 3 1 1 1\n"
                            "l polygon t 0 0 9  0 0 0  4 0 0  0 3 0\n");
  ASSERT_EQ(c.out.sources.size(), 1u);
  const rc_source& s = c.out.sources[0];
  const auto ctr = c.geom->centre();
  expect_vec(s.pos, 4.0 / 3 - ctr[0], 1 - ctr[1], 0 - ctr[2]);
  expect_vec(s.axis, 0, 0, 1);
  EXPECT_NEAR(s.axis.w, 6, 1e-6);
  EXPECT_NEAR(s.pos.w, std::hypot(4 - 4.0 / 3, 1), 1e-5);
  const double su[] = {s.su.x, s.su.y, s.su.z}, sv[] = {s.sv.x, s.sv.y, s.sv.z};
  const double rect = 4 * std::hypot(su[1] * sv[2] - su[2] * sv[1], su[2] * sv[0] - su[0] * sv[2],
                                     su[0] * sv[1] - su[1] * sv[0]);
  EXPECT_NEAR(rect, 12, 1e-4); // a right triangle's best box is its legs' 4 x 3
  // Every vertex lies in the rectangle (parameters within [-1, 1]).
  const double rc[] = {s.pos.x + s.su.w * su[0] + s.sv.w * sv[0],
                       s.pos.y + s.su.w * su[1] + s.sv.w * sv[1],
                       s.pos.z + s.su.w * su[2] + s.sv.w * sv[2]};
  for (std::uint32_t i = 0; i < s.nverts; ++i) {
    const rc_float4& v = c.out.verts[s.verts + i];
    const double d[] = {v.x - rc[0], v.y - rc[1], v.z - rc[2]};
    const double a = (d[0] * su[0] + d[1] * su[1] + d[2] * su[2]) /
                     (su[0] * su[0] + su[1] * su[1] + su[2] * su[2]);
    const double b = (d[0] * sv[0] + d[1] * sv[1] + d[2] * sv[2]) /
                     (sv[0] * sv[0] + sv[1] * sv[1] + sv[2] * sv[2]);
    EXPECT_LE(std::abs(a), 1 + 1e-5) << i;
    EXPECT_LE(std::abs(b), 1 + 1e-5) << i;
  }
}

TEST(LightSources, CylinderAndDimSources) {
  Compiled c = compile_text("void light l 0 0 3 5 5 5\n"
                            "void light dim 0 0 3 0 0 0\n"
                            "void glow g0 0 0 4 1 1 1 0\n"
                            "l cylinder tube 0 0 7  0 0 0  0 0 2  0.1\n"
                            "dim sphere off 0 0 4 0 0 0 1\n"
                            "g0 sphere sky 0 0 4 0 0 0 1\n");
  ASSERT_EQ(c.out.sources.size(), 1u);
  const rc_source& s = c.out.sources[0];
  EXPECT_EQ(s.kind, RC_SRC_CYLINDER);
  expect_vec(s.axis, 0, 0, 1);
  EXPECT_NEAR(s.axis.w, 2, 1e-6);
  EXPECT_NEAR(s.pos.w, 0.1, 1e-7);
  EXPECT_TRUE(warnings().empty());
}

TEST(LightSources, RadianceMessages) {
  // Vertex average (2, 2.25) falls in the notch of this U.
  EXPECT_EQ(
      fatal_of("void light l 0 0 3 1 1 1\n"
               "l polygon u 0 0 24  0 0 0  4 0 0  4 4 0  3 4 0  3 1 0  1 1 0  1 4 0  0 4 0\n"),
      "cannot hit source center for polygon \"u\"");
  EXPECT_EQ(fatal_of("void light l 0 0 3 1 1 1\nl cone c 0 0 8 0 0 0 0 0 1 1 0.5\n"),
            "illegal material for cone \"c\"");
  EXPECT_EQ(fatal_of("void light l 0 0 3 1 1 1\nl bubble b 0 0 4 0 0 0 1\n"),
            "illegal material for bubble \"b\"");
  EXPECT_EQ(fatal_of("void light l 0 0 3 1 1 1\nl ring r 0 0 8 0 0 0 0 0 1 0.2 1\n"),
            "cannot hit source center for ring \"r\"");
  EXPECT_EQ(fatal_of("void spotlight s 0 0 7 1 1 1 0 0 0 -1\ns ring r 0 0 8 0 0 0 0 0 -1 0 1\n"),
            "zero angle for spotlight \"s\"");
  EXPECT_EQ(fatal_of("void spotlight s 0 0 7 1 1 1 30 0 0 0\ns ring r 0 0 8 0 0 0 0 0 -1 0 1\n"),
            "zero focus vector for spotlight \"s\"");

  compile_text("void light l 0 0 3 1 1 1\nl cylinder fat 0 0 7 0 0 0 0 0 1 0.3\n");
  EXPECT_TRUE(has_warning("source aspect too small for cylinder \"fat\""));

  Compiled c = compile_text("void spotlight s 0 0 7 1 1 1 30 0 0 -1\n"
                            "s source sun 0 0 4 0 0 1 1\n");
  EXPECT_TRUE(has_warning("distant source is a spotlight for source \"sun\""));
  ASSERT_EQ(c.out.sources.size(), 1u);
  EXPECT_EQ(c.out.sources[0].flags, RC_SRCF_SPOT);

  // A spotlight aimed just behind its disc's plane: Radiance's checkspot() rejects it (it
  // only compares the cone with the angle to the normal's axis, so straight back passes).
  c = compile_text("void spotlight s 0 0 7 1 1 1 40 1 0 0.1\n"
                   "s ring r 0 0 8 0 0 0 0 0 -1 0 1\n");
  EXPECT_TRUE(has_warning("invalid spotlight direction for ring \"r\""));
  EXPECT_TRUE(c.out.sources.empty());
}
