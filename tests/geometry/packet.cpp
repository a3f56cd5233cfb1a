// Queries in Embree packets (SceneGeometry::intersect_block) give each ray the answer a single
// query gives it, bit for bit: polygons, quadrics (user geometry), an instance and a mesh,
// from inside a closed room and from the surfaces the rays met, lanes that set up nothing
// mixed in, and blocks that do not fill a packet.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "scene_fixture.h"

namespace radcl::geometry {
namespace {

using test::SceneMaker;

std::shared_ptr<scene::SceneDescription> ball_octree() {
  SceneMaker m;
  const auto mat = m.material("inner");
  m.add(RC_OBJ_SPHERE, "ball", {1, 0, 0, 0.5}, mat);
  m.add(RC_OBJ_POLYGON, "tile", {2, -0.5, -1, 3, -0.5, -1, 3, 0.5, -1, 2, 0.5, -1}, mat);
  return std::make_shared<scene::SceneDescription>(m.d);
}

std::shared_ptr<scene::TriangleMesh> quad_mesh() {
  auto mesh = std::make_shared<scene::TriangleMesh>();
  mesh->positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh->triangle_material = {0, 0};
  mesh->materials = {"paint"};
  return mesh;
}

// A closed 10 x 10 x 4 room with a sphere, a cylinder, a ring, two coplanar overlapping
// tiles (exact ties), a rotated and scaled instance and a placed mesh inside.
scene::LoadedScene room() {
  SceneMaker m;
  const auto mat = m.material();
  const double x0 = -5, x1 = 5, y0 = -5, y1 = 5, z0 = 0, z1 = 4;
  m.add(RC_OBJ_POLYGON, "floor", {x0, y0, z0, x0, y1, z0, x1, y1, z0, x1, y0, z0}, mat);
  m.add(RC_OBJ_POLYGON, "ceiling", {x0, y0, z1, x1, y0, z1, x1, y1, z1, x0, y1, z1}, mat);
  m.add(RC_OBJ_POLYGON, "south", {x0, y0, z0, x1, y0, z0, x1, y0, z1, x0, y0, z1}, mat);
  m.add(RC_OBJ_POLYGON, "north", {x0, y1, z0, x0, y1, z1, x1, y1, z1, x1, y1, z0}, mat);
  m.add(RC_OBJ_POLYGON, "west", {x0, y0, z0, x0, y0, z1, x0, y1, z1, x0, y1, z0}, mat);
  m.add(RC_OBJ_POLYGON, "east", {x1, y0, z0, x1, y1, z0, x1, y1, z1, x1, y0, z1}, mat);
  m.add(RC_OBJ_SPHERE, "ball", {2, 2, 1, 0.7}, mat);
  m.add(RC_OBJ_CYLINDER, "post", {-3, 2, 0, -3, 2, 3, 0.3}, mat);
  m.add(RC_OBJ_RING, "disc", {0, -3, 2, 0, 0, 1, 0.2, 1}, mat);
  m.add(RC_OBJ_POLYGON, "tile_a", {-2, -2, 1, -1, -2, 1, -1, -1, 1, -2, -1, 1}, mat);
  m.add(RC_OBJ_POLYGON, "tile_b", {-1.5, -2, 1, -0.5, -2, 1, -0.5, -1, 1, -1.5, -1, 1}, mat);
  m.add(RC_OBJ_INSTANCE, "it", {}, scene::kVoid,
        {"box.oct", "-rz", "90", "-s", "1.5", "-t", "3", "-2", "1"});
  m.add(RC_OBJ_MESH, "quad", {}, scene::kVoid, {"quad.rtm", "-s", "2", "-t", "-4", "2", "2.5"});
  auto s = m.loaded();
  s.octrees["/here/box.oct"] = ball_octree();
  s.meshes["quad.rtm"] = quad_mesh();
  return s;
}

void expect_same(const std::optional<Hit>& a, const std::optional<Hit>& b, std::size_t i) {
  ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
  if (!a) return;
  EXPECT_EQ(a->t, b->t) << "ray " << i;
  EXPECT_EQ(a->point, b->point) << "ray " << i;
  EXPECT_EQ(a->normal, b->normal) << "ray " << i;
  EXPECT_EQ(a->front, b->front) << "ray " << i;
  EXPECT_EQ(a->object, b->object) << "ray " << i;
  EXPECT_EQ(a->instance, b->instance) << "ray " << i;
  EXPECT_EQ(a->placement, b->placement) << "ray " << i;
  EXPECT_EQ(a->prim, b->prim) << "ray " << i;
  EXPECT_EQ(a->u, b->u) << "ray " << i;
  EXPECT_EQ(a->v, b->v) << "ray " << i;
}

// Rays from points in the room in random directions (hemispheres of 16 from one point, as the
// renderer's), then from the surfaces they met, leaving them as the kernels' rays do.
std::vector<Ray> rays_in(const SceneGeometry& g) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Ray> first;
  for (int p = 0; p < 40; ++p) {
    const Vec3d org{4.5 * u(rng), 4.5 * u(rng), 2 + 1.9 * u(rng)};
    for (int k = 0; k < 16; ++k) {
      Ray r;
      r.org = org;
      r.dir = {u(rng), u(rng), u(rng)};
      r.free_origin = p % 3 == 0;
      r.tmin = p % 5 == 0 ? -1 : p % 3 == 0 ? 1e-3 : 0;
      if (p % 7 == 0 && k == 5) r.dir = {0, 0, 0}; // sets up nothing
      if (p % 4 == 0) r.tmax = 3;
      first.push_back(r);
    }
  }
  std::vector<Ray> all = first;
  for (const Ray& r : first) {
    const auto h = g.intersect(r.org, r.dir, r.tmin, r.tmax, r.free_origin);
    if (!h) continue;
    Ray s;
    s.org = h->point;
    s.dir = {u(rng), u(rng), u(rng)};
    all.push_back(s);
  }
  return all;
}

TEST(Packet, SameAnswersAsSingleQueries) {
  const scene::LoadedScene scene = room();
  int widths = 0;
  for (const char* w : {"16", "8", "4", "1"}) {
    setenv("RADCL_RAY_PACKET", w, 1);
    SceneGeometry g(scene);
    unsetenv("RADCL_RAY_PACKET");
    if (g.packet_width() != std::atoi(w)) continue; // not native on this CPU
    ++widths;
    const std::vector<Ray> rays = rays_in(g);
    ASSERT_GT(rays.size(), 1000u);
    std::vector<std::optional<Hit>> block(rays.size());
    // Blocks of 37 rays: packets left part empty at each block's end.
    for (std::size_t a = 0; a < rays.size(); a += 37)
      g.intersect_block(rays.data() + a, std::min<std::size_t>(37, rays.size() - a),
                        block.data() + a);
    std::size_t hits = 0, user = 0, placed = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Ray& r = rays[i];
      const auto one = g.intersect(r.org, r.dir, r.tmin, r.tmax, r.free_origin);
      expect_same(block[i], one, i);
      if (!one) continue;
      ++hits;
      if (one->object >= 6 && one->object <= 8 && one->placement == 0) ++user;
      if (one->placement != 0) ++placed;
    }
    // The rays met every kind of surface, and some met none (leaving the room, short tmax).
    EXPECT_GT(hits, rays.size() / 2) << "width " << w;
    EXPECT_LT(hits, rays.size()) << "width " << w;
    EXPECT_GT(user, 20u) << "width " << w;
    EXPECT_GT(placed, 5u) << "width " << w;
    // The parallel wave query agrees too.
    std::vector<std::optional<Hit>> wave(rays.size());
    g.intersect(rays, wave);
    for (std::size_t i = 0; i < rays.size(); ++i)
      expect_same(wave[i], block[i], i);
  }
  EXPECT_GE(widths, 1);
}

} // namespace
} // namespace radcl::geometry
