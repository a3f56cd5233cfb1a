// Smoothed meshes (issue 54): where all three vertices of a mesh triangle carry normals,
// Radiance's o_mesh interpolates them at the hit and shades with the result (r->pert = smoothed
// - flat), so a chrome figure from an OBJ with `vn` reflects about its smoothed normal. The
// geometry's hit carries that perturbation and the kernels start from it.
#include <array>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "radcl/device/context.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/loader.h"
#include "radcl/scene/mesh.h"
#include "radcl/scene/mesh_writer.h"
#include "scene_dir.h"

using namespace radcl;

namespace {

using Vec3d = std::array<double, 3>;
constexpr double kPi = 3.14159265358979323846;
const double kS10 = std::sin(10 * kPi / 180), kC10 = std::cos(10 * kPi / 180);

// The quad z = 0, |x|, |y| <= 1, as two triangles wound towards +z; vertex normals `n` (each
// vertex's, or none where `n` is empty), flagged on the vertices in `with`.
scene::TriangleMesh quad(const std::vector<std::array<float, 3>>& n = {},
                         const std::vector<int>& with = {0, 1, 2, 3}) {
  scene::TriangleMesh m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.vertex_flags.assign(4, 0);
  if (!n.empty()) {
    m.normals = n;
    for (int v : with)
      m.vertex_flags[v] |= scene::TriangleMesh::kHasNormal;
  }
  return m;
}

std::vector<std::array<float, 3>> tilted() {
  const std::array<float, 3> t = {static_cast<float>(kS10), 0, static_cast<float>(kC10)};
  return {t, t, t, t};
}

Vec3d unit(const Vec3d& v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}

void expect_vec(const Vec3d& got, const Vec3d& want, double tol, const std::string& what) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(got[k], want[k], tol) << what << ", component " << k;
}

// Chrome (metal, colour 1, specularity 1, roughness 0) on mesh `file`, placed with `xform`,
// and a 0.2 x 0.2 light (radiance 100) at z = 3 over x in [0.992, 1.192], facing down: a ray
// straight down at the origin reflects into it only about a normal tilted 10 degrees about y.
// `defs` are defined after the chrome and `mod` modifies the mesh.
std::string chrome_scene(const std::string& file, const std::string& xform = "",
                         const std::string& defs = "", const std::string& mod = "chrome") {
  std::istringstream words(xform);
  int n = 1;
  for (std::string w; words >> w;)
    ++n;
  return "void metal chrome 0 0 5 1 1 1 1 0\n" + defs + mod + " mesh quad " + std::to_string(n) +
         " " + file + " " + xform +
         " 0 0\n"
         "void light lamp 0 0 3 100 100 100\n"
         "lamp polygon fixture 0 0 12 0.992 -0.1 3 0.992 0.1 3 1.192 0.1 3 1.192 -0.1 3\n";
}

class MeshNormals : public test::SceneDir {
protected:
  // The scene of chrome_scene(file) with mesh `mesh` written to `file` by the repo's writer.
  scene::LoadedScene load(const scene::TriangleMesh& mesh, const std::string& file,
                          const std::string& xform = "") {
    scene::write_mesh(mesh, (dir / file).string());
    std::ofstream((dir / "scene.rad").string()) << chrome_scene(file, xform);
    return scene::load_scene({"scene.rad"});
  }
  // The same scene, the mesh read from the file replaced by `exact` (normals not quantised).
  scene::LoadedScene load_exact(const scene::TriangleMesh& exact, const std::string& xform = "") {
    scene::LoadedScene ls = load(exact, "exact.rtm", xform);
    EXPECT_EQ(ls.meshes.size(), 1u);
    for (auto& [key, m] : ls.meshes)
      m = std::make_shared<scene::TriangleMesh>(exact);
    return ls;
  }
  static render::PrimaryResult result(const scene::LoadedScene& ls, const Vec3d& org,
                                      const Vec3d& dir) {
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    render::Renderer r(ls, st, device::default_context());
    std::vector<render::PrimaryRay> pr = {{org, dir, 0}};
    std::vector<render::PrimaryResult> res(1);
    r.render(pr, res);
    EXPECT_TRUE(res[0].hit);
    return res[0];
  }
  static Vec3d value(const scene::LoadedScene& ls, const Vec3d& org, const Vec3d& dir) {
    return result(ls, org, dir).value;
  }
  // Scene text `rad` (in scene.rad) with mesh `mesh` written to `file` by the repo's writer.
  scene::LoadedScene load_text(const std::string& rad, const scene::TriangleMesh& mesh,
                               const std::string& file) {
    scene::write_mesh(mesh, (dir / file).string());
    std::ofstream((dir / "scene.rad").string()) << rad;
    return scene::load_scene({"scene.rad"});
  }
};

// The square z = 1, |x|, |y| <= 2 (two triangles wound towards +z), as Radiance's obj2mesh
// makes it from an OBJ with every vertex's normal (sin deg, 0, cos deg), or with none (flat).
scene::TriangleMesh pane(double deg, bool smooth) {
  scene::TriangleMesh m;
  m.positions = {{-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.vertex_flags.assign(4, 0);
  if (smooth) {
    const float s = static_cast<float>(std::sin(deg * kPi / 180)),
                c = static_cast<float>(std::cos(deg * kPi / 180));
    m.normals.assign(4, {s, 0, c});
    m.vertex_flags.assign(4, scene::TriangleMesh::kHasNormal);
  }
  return m;
}

// A white floor at z = 0 and a 0.2 x 0.2 light (radiance 100) at z = 3 facing down.
std::string room() {
  return "void plastic white 0 0 5 .5 .5 .5 0 0\n"
         "white polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n"
         "void light lamp 0 0 3 100 100 100\n"
         "lamp polygon fixture 0 0 12 -0.1 -0.1 3 -0.1 0.1 3 0.1 0.1 3 0.1 -0.1 3\n";
}

// room() with material `mat` defined and the mesh `pane.rtm` shaded by modifier `mod`.
std::string pane_scene(const std::string& mat, const std::string& mod) {
  return room() + mat + "\n" + mod + " mesh g 1 pane.rtm 0 0\n";
}

void expect_rel(double got, double want, double rel, const std::string& what) {
  EXPECT_NEAR(got, want, rel * std::fabs(want)) << what;
}

} // namespace

// The hit's smoothed normal (normal + pert) is the interpolation of the vertex normals, made
// unit; the geometric normal stays the flat one (Radiance's -oN).
TEST_F(MeshNormals, HitCarriesTheInterpolatedNormal) {
  scene::LoadedScene ls = load_exact(quad(tilted()));
  geometry::SceneGeometry g(ls);
  for (const Vec3d& at : {Vec3d{0, 0, 1}, Vec3d{0.5, -0.5, 1}, Vec3d{-0.7, 0.6, 1}}) {
    auto h = g.intersect(at, {0, 0, -1});
    ASSERT_TRUE(h);
    expect_vec(h->normal, {0, 0, 1}, 1e-12, "flat normal");
    const Vec3d s = {h->normal[0] + h->pert[0], h->normal[1] + h->pert[1],
                     h->normal[2] + h->pert[2]};
    expect_vec(s, {0.173648, 0, 0.984808}, 1e-5, "smoothed normal");
    expect_vec(s, {kS10, 0, kC10}, 1e-7, "smoothed normal");
  }
}

// Barycentric weights in the vertex order the triangles were given (v0 v1 v2 of triangle 0 are
// quad vertices 0 1 2): at (0.5, -0.5), in triangle 0, the weights are 1/4, 1/2, 1/4.
TEST_F(MeshNormals, WeightsFollowTheVertexOrder) {
  const std::vector<std::array<float, 3>> n = {
      {0, 0, 1}, {0.5f, 0, 0.8660254f}, {0, 0.6f, 0.8f}, {-0.6f, 0, 0.8f}};
  Vec3d want = {0, 0, 0};
  const double w[3] = {0.25, 0.5, 0.25};
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c)
      want[c] += w[k] * n[k][c];
  want = unit(want);
  {
    scene::LoadedScene ls = load_exact(quad(n));
    geometry::SceneGeometry g(ls);
    auto h = g.intersect({0.5, -0.5, 1}, {0, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_EQ(h->prim, 0u);
    expect_vec({h->normal[0] + h->pert[0], h->normal[1] + h->pert[1], h->normal[2] + h->pert[2]},
               want, 1e-7, "interpolated");
  }
  // Placed turned 90 degrees about z and scaled: the normal turns with the mesh, as the flat
  // one does (mesh point (x, y) is world (-2y, 2x)).
  {
    scene::LoadedScene ls = load_exact(quad(n), "-rz 90 -s 2");
    geometry::SceneGeometry g(ls);
    auto h = g.intersect({1, 1, 1}, {0, 0, -1});
    ASSERT_TRUE(h);
    expect_vec(h->normal, {0, 0, 1}, 1e-12, "flat normal");
    expect_vec({h->normal[0] + h->pert[0], h->normal[1] + h->pert[1], h->normal[2] + h->pert[2]},
               {-want[1], want[0], want[2]}, 1e-7, "interpolated, turned");
  }
}

// Radiance smooths a triangle only where all three of its vertices have normals; a mesh
// without them keeps the flat normal.
TEST_F(MeshNormals, FlatWithoutNormalsOnEveryVertex) {
  for (const scene::TriangleMesh& m : {quad(), quad(tilted(), {0, 2, 3})}) {
    scene::LoadedScene ls = load_exact(m);
    geometry::SceneGeometry g(ls);
    auto h = g.intersect({0.5, -0.5, 1}, {0, 0, -1}); // triangle 0: vertex 1 lacks a normal
    ASSERT_TRUE(h);
    expect_vec(h->normal, {0, 0, 1}, 1e-12, "flat normal");
    expect_vec(h->pert, {0, 0, 0}, 0, "no perturbation");
  }
  // Triangle 1 (vertices 0 2 3) of the partly smoothed quad is smooth.
  scene::LoadedScene ls = load_exact(quad(tilted(), {0, 2, 3}));
  geometry::SceneGeometry g(ls);
  auto h = g.intersect({-0.5, 0.5, 1}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_EQ(h->prim, 1u);
  expect_vec(h->pert, {kS10, 0, kC10 - 1}, 1e-7, "perturbation");
}

// The rendered value: the ray `0 0 1 0 0 -1` reflects about the tilted normal to (sin 20, 0,
// cos 20) and meets the light. Radiance 5.4a (rtrace -h -ab 0 -ovnN, the same scene with the
// mesh made by its obj2mesh from an OBJ with `vn sin10 0 cos10`) gives 100 100 100, perturbed
// normal 0.1736803 0 0.9848021 (the .rtm's 32-bit direction code), unperturbed 0 0 1; without
// `vn`, 0 0 0 and the flat normal.
TEST_F(MeshNormals, ChromeReflectsAboutTheSmoothedNormal) {
  scene::LoadedScene ls = load(quad(tilted()), "quad.rtm");
  const Vec3d v = value(ls, {0, 0, 1}, {0, 0, -1});
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(v[c], 100.0, 100.0 * 1e-3) << "channel " << c;
  geometry::SceneGeometry g(ls);
  auto h = g.intersect({0, 0, 1}, {0, 0, -1});
  ASSERT_TRUE(h);
  expect_vec(h->normal, {0, 0, 1}, 1e-12, "flat normal");
  expect_vec({h->normal[0] + h->pert[0], h->normal[1] + h->pert[1], h->normal[2] + h->pert[2]},
             {0.1736803, 0, 0.9848021}, 1e-6, "Radiance's -on");

  scene::LoadedScene flat = load(quad(), "flat.rtm");
  const Vec3d f = value(flat, {0, 0, 1}, {0, 0, -1});
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(f[c], 0.0) << "channel " << c;
  geometry::SceneGeometry gf(flat);
  auto hf = gf.intersect({0, 0, 1}, {0, 0, -1});
  ASSERT_TRUE(hf);
  expect_vec(hf->normal, {0, 0, 1}, 1e-12, "flat normal");
  expect_vec(hf->pert, {0, 0, 0}, 0, "no perturbation");
}

// A mixture's sides each start from the hit's smoothed normal (Radiance's raymixture copies
// the ray, r->pert included). Radiance 5.4a, `rtrace -h -ab 0 -ovnN` on the chrome scene with
// `void plastic black 0 0 5 0 0 0 0 0`, `void mixfunc half 4 chrome black .5 . 0 0` and
// `half mesh quad 1 quad.rtm 0 0` (the mesh by obj2mesh as above): 50 50 50, -on 0.1736803 0
// 0.9848021; the chrome side reflected about the flat normal would miss the light (0).
TEST_F(MeshNormals, MixtureSidesStartFromTheSmoothedNormal) {
  scene::LoadedScene ls = load_text(chrome_scene("quad.rtm", "",
                                                 "void plastic black 0 0 5 0 0 0 0 0\n"
                                                 "void mixfunc half 4 chrome black .5 . 0 0\n",
                                                 "half"),
                                    quad(tilted()), "quad.rtm");
  const render::PrimaryResult r = result(ls, {0, 0, 1}, {0, 0, -1});
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(r.value[c], 50.0, 50.0 * 1e-3) << "channel " << c;
  expect_vec(r.normal, {0, 0, 1}, 1e-12, "flat normal");
  expect_vec({r.normal[0] + r.pert[0], r.normal[1] + r.pert[1], r.normal[2] + r.pert[2]},
             {0.1736803, 0, 0.9848021}, 1e-6, "the perturbed normal -on shows");
}

// Shadow rays meet the smoothed normal too: glass and trans transmit by the cosine to the
// tilted normal (m_glass, m_normal's Fresnel term), also as a mixture's side. Radiance 5.4a,
// `rtrace -h -ab 0 -ov` on pane_scene with the pane made by obj2mesh from an OBJ of the square
// with `vn sin60 0 cos60` on every vertex (and without `vn` for the flat values):
//   glass (`void glass pane 0 0 3 .96 .96 .96`), floor at 0 0 0.5 looking down: 0.05669514
//     (flat 0.06235052); from 0 0 2 looking down at the pane: 0.02571537
//   trans (`void trans tr 0 0 7 .8 .8 .8 .05 0 .9 1`), floor from 0 0 0.5 / 0.5 0.3 0.5:
//     0.04592565 / 0.03922579 (flat 0.04838310 / 0.04491000)
//   `void mixfunc gm 4 pane void .5 . 0 0` (glass as above) from 0 0 0.5 / 0.5 0.3 0.5:
//     0.06371533 / 0.05558912
TEST_F(MeshNormals, ShadowRaysSeeTheSmoothedNormal) {
  const std::string glass = "void glass pane 0 0 3 .96 .96 .96";
  const std::string trans = "void trans tr 0 0 7 .8 .8 .8 .05 0 .9 1";
  struct Case {
    std::string mat, mod;
    bool smooth;
    Vec3d org;
    double want;
  };
  const std::vector<Case> cases = {
      {glass, "pane", true, {0, 0, 0.5}, 0.05669514},
      {glass, "pane", false, {0, 0, 0.5}, 0.06235052},
      {glass, "pane", true, {0, 0, 2}, 0.02571537},
      {trans, "tr", true, {0, 0, 0.5}, 0.04592565},
      {trans, "tr", true, {0.5, 0.3, 0.5}, 0.03922579},
      {trans, "tr", false, {0, 0, 0.5}, 0.04838310},
      {trans, "tr", false, {0.5, 0.3, 0.5}, 0.04491000},
      {glass + "\nvoid mixfunc gm 4 pane void .5 . 0 0", "gm", true, {0, 0, 0.5}, 0.06371533},
      {glass + "\nvoid mixfunc gm 4 pane void .5 . 0 0", "gm", true, {0.5, 0.3, 0.5}, 0.05558912},
  };
  for (const Case& c : cases) {
    scene::LoadedScene ls = load_text(pane_scene(c.mat, c.mod), pane(60, c.smooth), "pane.rtm");
    const Vec3d v = value(ls, c.org, {0, 0, -1});
    const std::string what = c.mod + (c.smooth ? " smooth" : " flat") + " from " +
                             std::to_string(c.org[0]) + " " + std::to_string(c.org[1]) + " " +
                             std::to_string(c.org[2]);
    for (int k = 0; k < 3; ++k)
      expect_rel(v[k], c.want, 1e-4, what);
  }
}

// The textures' part of the perturbation reaches the result (rtrace's -on) from the device:
// Radiance 5.4a, `rtrace -h -ab 0 -onN` with `void texfunc wave 4 .3*sin(2*Px) .2*cos(3*Py) 0 .
// 0 0`, `wave plastic wavy 0 0 5 .6 .6 .6 .05 0` on the floor z = 0 and a light sphere, ray
// 0.3 0.2 2 0 0 -1: 0.1648447 0.1606352 0.9731508, unperturbed 0 0 1. On the chrome mesh with
// that texture between the mesh and its material, the two tilts add.
TEST_F(MeshNormals, ResultCarriesTheTexturesPerturbation) {
  std::ofstream((dir / "tex.rad").string())
      << "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 0 0 6 0.5\n"
         "void texfunc wave 4 .3*sin(2*Px) .2*cos(3*Py) 0 . 0 0\n"
         "wave plastic wavy 0 0 5 .6 .6 .6 .05 0\n"
         "wavy polygon floor 0 0 12 -5 -5 0 5 -5 0 5 5 0 -5 5 0\n";
  scene::LoadedScene ls = scene::load_scene({"tex.rad"});
  const render::PrimaryResult r = result(ls, {0.3, 0.2, 2}, {0, 0, -1});
  expect_vec(r.normal, {0, 0, 1}, 1e-12, "flat normal");
  expect_vec(unit({r.normal[0] + r.pert[0], r.normal[1] + r.pert[1], r.normal[2] + r.pert[2]}),
             {0.1648447, 0.1606352, 0.9731508}, 1e-6, "perturbed normal");
  expect_vec(r.pert, {0.3 * std::sin(0.6), 0.2 * std::cos(0.6), 0}, 1e-6, "texture's tilt");

  scene::LoadedScene both =
      load_text(chrome_scene("quad.rtm", "", "chrome texfunc lean 4 0 .1 0 . 0 0\n", "lean"),
                quad(tilted()), "quad.rtm");
  const render::PrimaryResult b = result(both, {0, 0, 1}, {0, 0, -1});
  expect_vec(b.pert, {0.1736803, 0.1, 0.9848021 - 1}, 1e-6, "mesh and texture");
}

// The same rule for a texture's tilt: a trans pane under `void texfunc tt 4 1.2 0 0 . 0 0`
// passes shadow rays by the tilted normal's Fresnel term. Radiance 5.4a, `rtrace -h -ab 0 -ov`
// on room()'s floor and light with `tt trans ttr 0 0 7 .8 .8 .8 .05 0 .9 1` on the polygon
// z = 1, |x|, |y| <= 2: from 0 0 0.5 / 0.5 0.3 0.5 looking down 0.04737896 / 0.04268151
// (untilted, as the flat trans mesh above: 0.04838310 / 0.04491000).
TEST_F(MeshNormals, ShadowRaysSeeATexturesTilt) {
  std::ofstream((dir / "tex.rad").string()) << room() << "void texfunc tt 4 1.2 0 0 . 0 0\n"
                                            << "tt trans ttr 0 0 7 .8 .8 .8 .05 0 .9 1\n"
                                            << "ttr polygon p 0 0 12 -2 -2 1 2 -2 1 2 2 1 -2 2 1\n";
  scene::LoadedScene ls = scene::load_scene({"tex.rad"});
  const Vec3d a = value(ls, {0, 0, 0.5}, {0, 0, -1}), b = value(ls, {0.5, 0.3, 0.5}, {0, 0, -1});
  for (int k = 0; k < 3; ++k) {
    expect_rel(a[k], 0.04737896, 1e-4, "from 0 0 0.5");
    expect_rel(b[k], 0.04268151, 1e-4, "from 0.5 0.3 0.5");
  }
}
