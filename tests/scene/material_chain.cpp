// First material of a modifier chain through patterns and both alias forms; light sources.
#include <gtest/gtest.h>
#include <sstream>

#include "radcl/scene/material_chain.h"
#include "radcl/scene/rad_reader.h"

using namespace radcl::scene;

namespace {
SceneDescription read(const std::string& text) {
  SceneDescription sd;
  std::istringstream in(text);
  read_rad_stream(sd, in, "test");
  return sd;
}
} // namespace

TEST(MaterialChain, ThroughPatternsAndAliases) {
  SceneDescription sd = read(R"(
void plastic white 0 0 5 .5 .5 .5 0 0
void brightfunc pat 2 foo . 0 0
pat plastic patterned 0 0 5 .2 .2 .2 0 0
white polygon a 0 0 9 0 0 0 1 0 0 0 1 0
pat alias p2 white
p2 polygon b 0 0 9 0 0 0 1 0 0 0 1 0
inherit alias w2 white
w2 sphere c 0 0 4 0 0 0 1
void polygon d 0 0 9 0 0 0 1 0 0 0 1 0
patterned sphere e 0 0 4 0 0 0 1
)");
  auto idx = [&](const char* name) {
    for (std::size_t i = 0; i < sd.objects.size(); ++i)
      if (sd.objects[i].name == name) return static_cast<std::int32_t>(i);
    return kVoid;
  };
  EXPECT_EQ(first_material(sd, idx("a")), idx("white"));
  EXPECT_EQ(first_material(sd, idx("b")), idx("white")); // named alias stands for white
  EXPECT_EQ(first_material(sd, idx("c")), idx("white")); // pass-through alias
  EXPECT_EQ(first_material(sd, idx("d")), kVoid);
  EXPECT_EQ(first_material(sd, idx("e")), idx("patterned"));
  EXPECT_EQ(alias_target(sd, idx("p2")), idx("white"));
}

TEST(MaterialChain, LightSources) {
  SceneDescription sd = read(R"(
void light bright 0 0 3 10 10 10
void light dark 0 0 3 0 0 0
void glow near 0 0 4 1 1 1 2
void glow sky 0 0 4 1 1 1 0
void spotlight spot 0 0 7 9 9 9 30 0 0 -1
void illum port 0 0 3 1 1 1
bright sphere s1 0 0 4 0 0 0 1
dark sphere s2 0 0 4 0 0 0 1
near sphere s3 0 0 4 0 0 0 1
sky source s4 0 0 4 0 0 1 180
near source s5 0 0 4 0 0 1 10
spot ring s6 0 0 8 0 0 3 0 0 -1 0 .1
port polygon s7 0 0 9 0 0 0 1 0 0 0 1 0
bright source sun 0 0 4 0 0 1 .5
)");
  std::vector<bool> expect = {true, false, true, false, false, true, true, true};
  std::size_t k = 0;
  for (std::size_t i = 0; i < sd.objects.size(); ++i) {
    if (is_surface(sd.objects[i].type)) {
      EXPECT_EQ(is_light_source(sd, static_cast<std::int32_t>(i)), expect[k++])
          << sd.objects[i].name;
    }
  }
}
