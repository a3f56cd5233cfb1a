// Type names and roles (Radiance's otypes.h flags).
#include "radcl/scene/object_type.h"

#include <gtest/gtest.h>

using namespace radcl::scene;

TEST(ObjectType, NamesRoundTrip) {
  for (int i = 0; i < RC_OBJ_COUNT; ++i) {
    auto t = static_cast<ObjectType>(i);
    auto back = type_from_name(type_name(t));
    ASSERT_TRUE(back.has_value()) << type_name(t);
    EXPECT_EQ(*back, t);
  }
  EXPECT_EQ(type_from_name("BSDF"), RC_OBJ_BSDF);
  EXPECT_EQ(type_from_name("aBSDF"), RC_OBJ_ABSDF);
  EXPECT_EQ(type_from_name("BRTDfunc"), RC_OBJ_BRTDFUNC);
  EXPECT_FALSE(type_from_name("Plastic")); // case-sensitive
  EXPECT_FALSE(type_from_name("brtdfunc"));
  EXPECT_FALSE(type_from_name("void"));
  EXPECT_FALSE(type_from_name("inherit"));
  EXPECT_FALSE(type_from_name(""));
}

TEST(ObjectType, Roles) {
  for (auto t :
       {RC_OBJ_POLYGON, RC_OBJ_CONE, RC_OBJ_SPHERE, RC_OBJ_RING, RC_OBJ_CYLINDER, RC_OBJ_CUP,
        RC_OBJ_BUBBLE, RC_OBJ_TUBE, RC_OBJ_SOURCE, RC_OBJ_INSTANCE, RC_OBJ_MESH}) {
    EXPECT_TRUE(is_surface(t)) << type_name(t);
    EXPECT_FALSE(is_modifier(t)) << type_name(t);
    EXPECT_FALSE(is_material(t)) << type_name(t);
  }
  for (auto t : {RC_OBJ_LIGHT, RC_OBJ_ILLUM, RC_OBJ_GLOW, RC_OBJ_SPOTLIGHT}) {
    EXPECT_TRUE(is_light(t)) << type_name(t);
    EXPECT_TRUE(is_material(t)) << type_name(t);
    EXPECT_TRUE(is_modifier(t)) << type_name(t);
  }
  for (auto t : {RC_OBJ_PLASTIC, RC_OBJ_METAL, RC_OBJ_GLASS, RC_OBJ_MIRROR, RC_OBJ_ANTIMATTER,
                 RC_OBJ_MIST, RC_OBJ_BSDF, RC_OBJ_PRISM1, RC_OBJ_ASHIK2, RC_OBJ_BRTDFUNC}) {
    EXPECT_TRUE(is_material(t)) << type_name(t);
    EXPECT_FALSE(is_light(t)) << type_name(t);
  }
  for (auto t : {RC_OBJ_BRIGHTFUNC, RC_OBJ_COLORFUNC, RC_OBJ_BRIGHTDATA, RC_OBJ_COLORDATA,
                 RC_OBJ_COLORPICT, RC_OBJ_BRIGHTTEXT, RC_OBJ_COLORTEXT}) {
    EXPECT_TRUE(is_pattern(t)) << type_name(t);
    EXPECT_FALSE(is_material(t)) << type_name(t);
  }
  EXPECT_TRUE(is_texture(RC_OBJ_TEXFUNC));
  EXPECT_TRUE(is_texture(RC_OBJ_TEXDATA));
  for (auto t : {RC_OBJ_MIXFUNC, RC_OBJ_MIXDATA, RC_OBJ_MIXTEXT, RC_OBJ_MIXPICT})
    EXPECT_TRUE(is_mixture(t)) << type_name(t);
  EXPECT_TRUE(is_modifier(RC_OBJ_ALIAS));
  EXPECT_FALSE(is_material(RC_OBJ_ALIAS));
  // Every type has exactly one role.
  for (int i = 0; i < RC_OBJ_COUNT; ++i) {
    auto t = static_cast<ObjectType>(i);
    int roles = is_surface(t) + is_material(t) + is_pattern(t) + is_texture(t) + is_mixture(t) +
                (t == RC_OBJ_ALIAS);
    EXPECT_EQ(roles, 1) << type_name(t);
    EXPECT_NE(is_surface(t), is_modifier(t)) << type_name(t);
  }
}
