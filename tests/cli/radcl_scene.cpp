// radcl scene on the reference scenes: counts checked against the scene files by hand.
#include <gtest/gtest.h>
#include <string>

#include "test_env.h"

using radcl::test::run_command;

namespace {
// Runs radcl in the reference-scene folder (unfrozen octrees name their files relative to it).
int radcl_scene(const std::string& args, std::string* out) {
  return run_command("cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                         "/radcl scene " + args,
                     out);
}
} // namespace

TEST(RadclScene, LuminairesCounts) {
  std::string out;
  ASSERT_EQ(radcl_scene("luminaires.oct", &out), 0) << out;
  // luminaires.rad: 9 materials, 11 polygons, 1 ring, 2 spheres; sources: 4 light panels, the
  // spotlight ring, the glow sphere (radius 1.5), the light sphere and the illum port.
  EXPECT_NE(out.find("objects         23\n"), std::string::npos) << out;
  EXPECT_NE(out.find("surfaces        polygon 11, ring 1, sphere 2\n"), std::string::npos) << out;
  EXPECT_NE(out.find("materials       glass 1, glow 1, illum 1, light 2, plastic 3, spotlight 1\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("light sources   8 local, 0 distant\n"), std::string::npos) << out;
  EXPECT_NE(out.find("bounding box    0 0 0 .. 8 6 2.8"), std::string::npos) << out;
}

TEST(RadclScene, FurnishedResolvesInstancesAndMesh) {
  std::string out;
  ASSERT_EQ(radcl_scene("furnished.oct", &out), 0) << out;
  EXPECT_NE(out.find("chair.oct (37 objects)"), std::string::npos) << out;
  EXPECT_NE(out.find("octa.rtm (8 triangles)"), std::string::npos) << out;
}

TEST(RadclScene, FrozenAndUnfrozenListsAgree) {
  std::string a, b;
  ASSERT_EQ(radcl_scene("--list office_clear.oct", &a), 0) << a;
  ASSERT_EQ(radcl_scene("--list office_clear_frozen.oct", &b), 0) << b;
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.rfind("0\t", 0), 0u) << a;
}

TEST(RadclScene, RadFilesWhereOctreeExpected) {
  std::string a, b;
  ASSERT_EQ(radcl_scene("luminaires.rad", &a), 0) << a;
  ASSERT_EQ(radcl_scene("luminaires.oct", &b), 0) << b;
  EXPECT_EQ(a, b);
}

TEST(RadclScene, MissingFileIsFatal) {
  std::string out;
  EXPECT_EQ(radcl_scene("no_such_file.rad", &out), 1) << out;
  EXPECT_EQ(out.rfind("radcl: fatal - ", 0), 0u) << out;
}
