// The same scene far from the origin must give the same answers relative to it: Embree works
// in float, so this depends on re-centring and on exact double refinement of every hit.
#include <gtest/gtest.h>

#include <random>

#include "scene_fixture.h"

namespace radcl::geometry {
namespace {

using test::SceneMaker;

// A room-sized mix of every surface kind, shifted by `d`.
scene::LoadedScene mixed(const Vec3d& d) {
  SceneMaker m;
  const auto mat = m.material();
  auto poly = [&](std::vector<double> f) {
    for (std::size_t i = 0; i < f.size(); ++i)
      f[i] += d[i % 3];
    return f;
  };
  m.add(RC_OBJ_POLYGON, "floor", poly({0, 0, 0, 1, 1, 0, 1, 3, 0, 3, 3, 0, 3, 1, 0,
                                       1, 1, 0, 0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0}),
        mat);
  m.add(RC_OBJ_POLYGON, "wall", poly({0, 4, 0, 4, 4, 0, 4, 4, 3, 0, 4, 3}), mat);
  m.add(RC_OBJ_POLYGON, "ceiling", poly({0, 0, 3, 0, 4, 3, 4, 4, 3, 4, 0, 3}), mat);
  m.add(RC_OBJ_SPHERE, "ball", {2 + d[0], 2 + d[1], 1 + d[2], 0.5}, mat);
  m.add(RC_OBJ_CYLINDER, "post",
        {3.5 + d[0], 0.5 + d[1], d[2], 3.5 + d[0], 0.5 + d[1], 2 + d[2], 0.1}, mat);
  m.add(RC_OBJ_CONE, "shade",
        {0.5 + d[0], 0.5 + d[1], 2 + d[2], 0.5 + d[0], 0.5 + d[1], 2.3 + d[2], 0.3, 0.1}, mat);
  m.add(RC_OBJ_RING, "lamp", {2 + d[0], 2 + d[1], 2.9 + d[2], 0, 0, -1, 0, 0.3}, mat);
  m.add(RC_OBJ_INSTANCE, "chair", {}, scene::kVoid,
        {"chair.oct", "-rz", "30", "-s", "0.5", "-t", std::to_string(1 + d[0]),
         std::to_string(3 + d[1]), std::to_string(d[2])});
  auto s = m.loaded();
  SceneMaker c;
  const auto cm = c.material();
  c.add(RC_OBJ_POLYGON, "seat", {-0.5, -0.5, 1, 0.5, -0.5, 1, 0.5, 0.5, 1, -0.5, 0.5, 1}, cm);
  c.add(RC_OBJ_SPHERE, "knob", {0, 0, 2, 0.2}, cm);
  s.octrees["chair.oct"] = std::make_shared<scene::SceneDescription>(c.d);
  return s;
}

TEST(Recentre, FarFromOriginSameAnswers) {
  const Vec3d far{1e6, -2e6, 1e6};
  const auto near_scene = mixed({0, 0, 0});
  const auto far_scene = mixed(far);
  SceneGeometry a(near_scene), b(far_scene);
  EXPECT_NEAR(b.centre()[0] - a.centre()[0], far[0], 1e-6);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.05, 3.95), h(0.05, 2.9), s(-1, 1);
  int hits = 0, bounces = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3d o{u(rng), u(rng), h(rng)};
    const Vec3d dir{s(rng), s(rng), s(rng)};
    auto ha = a.intersect(o, dir);
    auto hb = b.intersect(test::translate(o, far), dir);
    ASSERT_EQ(ha.has_value(), hb.has_value()) << i;
    if (!ha) continue;
    ++hits;
    EXPECT_EQ(ha->object, hb->object) << i;
    EXPECT_EQ(ha->instance, hb->instance) << i;
    EXPECT_EQ(ha->front, hb->front) << i;
    EXPECT_NEAR(hb->t, ha->t, 1e-6 * ha->t) << i;
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(hb->normal[k], ha->normal[k], 1e-6) << i;
      EXPECT_NEAR(hb->point[k] - far[k], ha->point[k], 1e-6) << i;
    }
    // Continue from the hit point in both scenes: no self-hits, same next surface.
    const Vec3d d2{-dir[1], dir[0], -dir[2]};
    auto na = a.intersect(ha->point, d2);
    auto nb = b.intersect(hb->point, d2);
    ASSERT_EQ(na.has_value(), nb.has_value()) << i;
    if (!na) continue;
    ++bounces;
    EXPECT_GT(na->t, 1e-6);
    EXPECT_EQ(na->object, nb->object) << i;
    // Points near 1e6 carry ~1e-10 of rounding, magnified at grazing angles.
    EXPECT_NEAR(nb->t, na->t, 1e-6 * na->t + 1e-7) << i;
  }
  EXPECT_GT(hits, 1500);
  EXPECT_GT(bounces, 500);
}

} // namespace
} // namespace radcl::geometry
