// Instances (octrees) and meshes placed with Radiance transforms.
#include <gtest/gtest.h>

#include "radcl/util/error.h"
#include "scene_fixture.h"

namespace radcl::geometry {
namespace {

using test::SceneMaker;

constexpr double kTol = 1e-9;

void expect_vec(const Vec3d& a, const Vec3d& b, double tol = kTol) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

// Octree contents: sphere at (1,0,0) r 0.5, an upward square at z=-1, and a square without
// material at z=-3.
std::shared_ptr<scene::SceneDescription> box_octree() {
  SceneMaker m;
  const auto mat = m.material("inner");
  m.add(RC_OBJ_SPHERE, "ball", {1, 0, 0, 0.5}, mat);
  m.add(RC_OBJ_POLYGON, "tile", {2, -0.5, -1, 3, -0.5, -1, 3, 0.5, -1, 2, 0.5, -1}, mat);
  m.add(RC_OBJ_POLYGON, "ghost", {2, -0.5, -3, 3, -0.5, -3, 3, 0.5, -3, 2, 0.5, -3}, scene::kVoid);
  return std::make_shared<scene::SceneDescription>(m.d);
}

scene::LoadedScene placed(std::int32_t* inst_index, bool with_modifier = false) {
  SceneMaker m;
  const auto mat = m.material("outer");
  *inst_index = m.add(RC_OBJ_INSTANCE, "it", {}, with_modifier ? mat : scene::kVoid,
                      {"box.oct", "-rz", "90", "-s", "2", "-t", "10", "0", "0"});
  auto s = m.loaded();
  s.octrees["/some/dir/box.oct"] = box_octree();
  return s;
}

TEST(Instance, RotatedAndScaled) {
  std::int32_t idx;
  const auto scene = placed(&idx);
  SceneGeometry g(scene);
  // Sphere: (1,0,0) -rz 90 -> (0,1,0), -s 2 -> (0,2,0) r 1, -t -> (10,2,0).
  auto h = g.intersect({10, 2, 10}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 9, kTol);
  expect_vec(h->point, {10, 2, 1});
  expect_vec(h->normal, {0, 0, 1});
  EXPECT_TRUE(h->front);
  EXPECT_EQ(h->object, 1);
  EXPECT_EQ(h->instance, idx);
  ASSERT_GT(h->placement, 0);
  const Placement& pl = g.placements()[h->placement];
  EXPECT_EQ(pl.instance_object, idx);
  EXPECT_EQ(pl.shade_object, -1);
  EXPECT_DOUBLE_EQ(pl.scale, 2);
  EXPECT_EQ(pl.scene->objects[h->object].name, "ball");
  // Sideways through the sphere's centre: t scaled with the instance.
  auto side = g.intersect({20, 2, 0}, {-1, 0, 0});
  ASSERT_TRUE(side);
  EXPECT_NEAR(side->t, 9, kTol);
  expect_vec(side->normal, {1, 0, 0});
  // From its surface inwards: the far side, 2 radii away.
  auto far = g.intersect(side->point, {-1, 0, 0});
  ASSERT_TRUE(far);
  EXPECT_NEAR(far->t, 2, kTol);
  EXPECT_FALSE(far->front);

  // Tile: x in [9,11], y in [4,6], z = -2, facing up.
  auto t = g.intersect({10, 5, 10}, {0, 0, -1});
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->t, 12, kTol);
  expect_vec(t->normal, {0, 0, 1});
  EXPECT_EQ(t->object, 2);
  auto again = g.intersect(t->point, {0.1, 0.2, 1});
  EXPECT_FALSE(again); // leaving the tile upwards: nothing
  EXPECT_FALSE(g.intersect({12, 5, 10}, {0, 0, -1}));
  EXPECT_TRUE(g.occluded({10, 5, 10}, {0, 0, -1}, 0, 12.5));
  EXPECT_FALSE(g.occluded({10, 5, 10}, {0, 0, -1}, 0, 11.5));
  EXPECT_EQ(g.counts().instances, 1u);
}

TEST(Instance, ModifierOverrideShowsVoidSurfaces) {
  std::int32_t idx;
  SceneGeometry plain(placed(&idx));
  EXPECT_FALSE(plain.intersect({10, 5, -3}, {0, 0, -1})); // ghost (z=-6) stays invisible
  const auto scene = placed(&idx, true);
  SceneGeometry g(scene);
  auto h = g.intersect({10, 5, -3}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 3, kTol);
  const Placement& pl = g.placements()[h->placement];
  EXPECT_EQ(pl.shade_object, idx);
  EXPECT_EQ(pl.shade_scene, &scene.main);
  EXPECT_EQ(pl.scene->objects[h->object].name, "ghost");
}

TEST(Instance, NestedAndShared) {
  // Octree "pair" places box.oct twice; the main scene places "pair" shifted and mirrored.
  SceneMaker pair;
  pair.add(RC_OBJ_INSTANCE, "a", {}, scene::kVoid, {"box.oct"});
  pair.add(RC_OBJ_INSTANCE, "b", {}, scene::kVoid, {"box.oct", "-t", "0", "0", "10"});
  SceneMaker m;
  const auto top =
      m.add(RC_OBJ_INSTANCE, "p", {}, scene::kVoid, {"pair.oct", "-mx", "-t", "0", "100", "0"});
  auto s = m.loaded();
  s.octrees["box.oct"] = box_octree();
  s.octrees["pair.oct"] = std::make_shared<scene::SceneDescription>(pair.d);
  SceneGeometry g(s);
  EXPECT_EQ(g.placements().size(), 3u); // main, box twice (pair itself has no surfaces)
  // Ball of "b": (1,0,0)+(0,0,10) mirrored in x -> (-1,0,10), then +(0,100,0).
  auto h = g.intersect({-1, 100, 20}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 9.5, kTol);
  EXPECT_EQ(h->instance, top);
  expect_vec(h->normal, {0, 0, 1});
  auto h2 = g.intersect({-1, 100, -20}, {0, 0, 1});
  ASSERT_TRUE(h2);
  EXPECT_NEAR(h2->t, 19.5, kTol);
  expect_vec(h2->normal, {0, 0, -1});
}

TEST(Instance, MissingOctreeIsFatal) {
  SceneMaker m;
  m.add(RC_OBJ_INSTANCE, "x", {}, scene::kVoid, {"nowhere.oct"});
  EXPECT_THROW(SceneGeometry(m.loaded()), FatalError);
}

std::shared_ptr<scene::TriangleMesh> quad_mesh() {
  auto mesh = std::make_shared<scene::TriangleMesh>();
  mesh->positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh->triangle_material = {0, -1};
  mesh->materials = {"paint"};
  return mesh;
}

TEST(Mesh, OwnMaterialsAndTransform) {
  SceneMaker m;
  const auto idx =
      m.add(RC_OBJ_MESH, "quad", {}, scene::kVoid, {"quad.rtm", "-s", "3", "-t", "0", "0", "5"});
  auto s = m.loaded();
  s.meshes["quad.rtm"] = quad_mesh();
  SceneGeometry g(s);
  // Triangle 0 (x > y) has a material; triangle 1 is void and skipped.
  auto h = g.intersect({2, 1, 10}, {0, 0, -1});
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 5, kTol);
  expect_vec(h->normal, {0, 0, 1});
  EXPECT_EQ(h->object, idx);
  EXPECT_EQ(h->instance, idx);
  EXPECT_EQ(h->prim, 0u);
  // Local point (2/3, 1/3) in triangle (0,0) (1,0) (1,1): p = (u + v, v).
  EXPECT_NEAR(h->u, 1.0 / 3, 1e-6);
  EXPECT_NEAR(h->v, 1.0 / 3, 1e-6);
  EXPECT_EQ(g.placements()[h->placement].mesh, s.meshes["quad.rtm"].get());
  EXPECT_FALSE(g.intersect({1, 2, 10}, {0, 0, -1}));
  EXPECT_FALSE(g.intersect(h->point, {0, 0, 1}));
  EXPECT_EQ(g.counts().mesh_triangles, 1u);

  // With a modifier of its own every face shows.
  SceneMaker m2;
  m2.add(RC_OBJ_MESH, "quad", {}, m2.material(), {"quad.rtm"});
  auto s2 = m2.loaded();
  s2.meshes["quad.rtm"] = quad_mesh();
  SceneGeometry g2(s2);
  auto h2 = g2.intersect({0.25, 0.75, 1}, {0, 0, -1});
  ASSERT_TRUE(h2);
  EXPECT_EQ(h2->prim, 1u);
}

} // namespace
} // namespace radcl::geometry
