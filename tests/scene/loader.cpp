// load_scene(): octree vs .rad inputs, instance octrees and meshes loaded once each.
#include "radcl/scene/loader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "radcl/util/error.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::scene {
namespace {

namespace fs = std::filesystem;

fs::path scenes_dir() {
  if (std::getenv("RADCL_TEST_DATA")) return fs::path(test::data_dir()) / "scenes";
  return fs::path(__FILE__).parent_path().parent_path() / "data" / "scenes";
}

class InDir {
public:
  explicit InDir(const fs::path& dir) : old_(fs::current_path()) { fs::current_path(dir); }
  ~InDir() { fs::current_path(old_); }

private:
  fs::path old_;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

TEST(Loader, FurnishedResolvesInstancesAndMesh) {
  InDir here(scenes_dir());
  const LoadedScene s = load_scene({"furnished.oct"});
  EXPECT_EQ(s.main.objects.size(), 52u);
  EXPECT_FALSE(s.main.frozen);

  // Three instances of chair.oct share one loaded octree.
  int instances = 0;
  for (const auto& o : s.main.objects)
    instances += o.type == RC_OBJ_INSTANCE;
  EXPECT_EQ(instances, 3);
  ASSERT_EQ(s.octrees.size(), 1u);
  const auto& [chair_path, chair] = *s.octrees.begin();
  EXPECT_TRUE(ends_with(chair_path, "chair.oct")) << chair_path;
  EXPECT_EQ(chair->objects.size(), 37u);
  EXPECT_TRUE(chair->frozen);

  ASSERT_EQ(s.meshes.size(), 1u);
  const auto& [mesh_path, mesh] = *s.meshes.begin();
  EXPECT_TRUE(ends_with(mesh_path, "octa.rtm")) << mesh_path;
  EXPECT_EQ(mesh->triangles.size(), 8u);
  EXPECT_EQ(mesh->positions.size(), 6u);
}

TEST(Loader, RadInputsGiveTheSameSceneAsTheOctree) {
  InDir here(scenes_dir());
  const LoadedScene oct = load_scene({"office_clear.oct"});
  const LoadedScene rad =
      load_scene({"office_mat.rad", "office_geom.rad", "office_desk.rad", "office_sky_clear.rad"});
  ASSERT_EQ(oct.main.objects.size(), rad.main.objects.size());
  for (std::size_t i = 0; i < oct.main.objects.size(); ++i) {
    EXPECT_EQ(oct.main.objects[i].name, rad.main.objects[i].name);
    EXPECT_EQ(oct.main.objects[i].type, rad.main.objects[i].type);
    EXPECT_EQ(oct.main.objects[i].fargs, rad.main.objects[i].fargs);
  }
  EXPECT_FALSE(oct.main.header.empty());
  EXPECT_TRUE(rad.main.header.empty());
  EXPECT_TRUE(rad.octrees.empty());
  EXPECT_TRUE(rad.meshes.empty());
}

TEST(Loader, FurnishedFromRadFiles) {
  InDir here(scenes_dir());
  const LoadedScene s = load_scene({"office_mat.rad", "office_geom.rad", "office_desk.rad",
                                    "office_sky_clear.rad", "furnished.rad"});
  EXPECT_EQ(s.main.objects.size(), 52u);
  EXPECT_EQ(s.octrees.size(), 1u);
  EXPECT_EQ(s.meshes.size(), 1u);
}

TEST(Loader, OctreeDetectedByHeaderWithoutSuffix) {
  InDir here(scenes_dir());
  const test::TempFolder tmp("loader");
  const fs::path copy = tmp / "sphere_octree";
  fs::copy_file("sphere.oct", copy, fs::copy_options::overwrite_existing);
  const LoadedScene s = load_scene({copy.string()});
  EXPECT_EQ(s.main.objects.size(), 4u);
  EXPECT_FALSE(s.main.header.empty());
}

TEST(Loader, InputErrors) {
  InDir here(scenes_dir());
  EXPECT_THROW(load_scene({}), FatalError);
  EXPECT_THROW(load_scene({"sphere.oct", "sphere.rad"}), FatalError);
  EXPECT_THROW(load_scene({"no_such_file.rad"}), FatalError);
  try {
    load_scene({"no_such_file.oct"});
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "cannot open octree file \"no_such_file.oct\"");
  }
}

TEST(Loader, MissingInstanceOctree) {
  const test::TempFolder tmp("loader");
  const fs::path rad = tmp / "missing.rad";
  std::ofstream(rad) << "void instance x 1 /nonexistent/none.oct 0 0\n";
  try {
    load_scene({rad.string()});
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_STREQ(e.what(), "cannot find octree file \"/nonexistent/none.oct\"");
  }
}

} // namespace
} // namespace radcl::scene
