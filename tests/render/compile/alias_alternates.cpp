// Aliases (scene-format.md §1.2; Radiance's m_alias) and the alternate materials of mirrors
// (§3.7; m_mirror). A named alias is a copy of its target whose modifier is the alias's own;
// `inherit` (or the target's own modifier) passes straight through to the target; `void` drops
// the modifier. A mirror with an alternate looks like that material to every ray except those
// its virtual sources account for (ambient and specular rays meeting its front, shadow rays
// aimed at its images); `void` makes it invisible to them.
//
// Expected values are worked out from those rules: a brightfunc of constant k scales the
// plastic it modifies by exactly k at -ab 0, so each aliased surface is compared with an
// unaliased one lit identically (mirror-symmetric points under one lamp). The two
// Radiance 2fcca99ac outputs are checked too.
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "scene_dir.h"

using namespace radcl;

namespace {

// A lamp over the origin; plastic red (.6 .1 .1) and its patterns; polygon `left` (x < 0) and
// `right` (x > 0) on z = 0, facing up. Rays look straight down at x = -1 and x = +1.
const char* kLit = "void plastic red 0 0 5 .6 .1 .1 0 0\n"
                   "void brightfunc dim 2 0.1 . 0 0\n"
                   "void brightfunc half 2 0.5 . 0 0\n"
                   "void light lamp 0 0 3 100 100 100\n"
                   "lamp sphere bulb 0 0 4 0 0 5 0.5\n";

std::string two_floors(const std::string& left_mod, const std::string& right_mod) {
  return left_mod + " polygon left 0 0 12  -2 -1 0  0 -1 0  0 1 0  -2 1 0\n" + right_mod +
         " polygon right 0 0 12  0 -1 0  2 -1 0  2 1 0  0 1 0\n";
}

class AliasAlternates : public test::SceneDir {
protected:
  // Red, green and blue seen by rays (org, dir) at -ab `ab`.
  std::vector<render::Vec3d> trace(const std::string& scene,
                                   const std::vector<std::pair<render::Vec3d, render::Vec3d>>& rays,
                                   int ab = 0) {
    std::ofstream("scene.rad") << scene;
    render::RenderSettings st = test::direct_light_settings(false);
    st.ab = ab;
    st.ad = 256;
    st.aa = 0;
    st.lw = 1e-4;
    std::vector<render::PrimaryRay> pr;
    for (const auto& [o, d] : rays)
      pr.push_back({o, d, 0});
    std::vector<render::Vec3d> out;
    for (const render::PrimaryResult& r : render_rays("scene.rad", pr, st))
      out.push_back({r.value[0], r.value[1], r.value[2]});
    return out;
  }
  // The right floor's red over the left floor's.
  double ratio(const std::string& scene) {
    auto v = trace(scene, {{{-1, 0, 1}, {0, 0, -1}}, {{1, 0, 1}, {0, 0, -1}}});
    EXPECT_GT(v[0][0], 0.0);
    return v[1][0] / v[0][0];
  }
};

} // namespace

// The scene: `dim alias red_dim red` is red with dim as its modifier.
TEST_F(AliasAlternates, AliasWithModifier) {
  const std::string s =
      std::string(kLit) + "dim alias red_dim red\n" + two_floors("red", "red_dim");
  auto v = trace(s, {{{-1, 0, 1}, {0, 0, -1}}, {{1, 0, 1}, {0, 0, -1}}});
  EXPECT_NEAR(v[1][0] / v[0][0], 0.1, 1e-4);
  // Radiance 2fcca99ac: 0.5657 0.0943 0.0943, then 0.05657 0.00943 0.00943.
  EXPECT_NEAR(v[0][0], 0.5657, 0.01 * 0.5657);
  EXPECT_NEAR(v[0][1], 0.0943, 0.01 * 0.0943);
  EXPECT_NEAR(v[1][0], 0.05657, 0.01 * 0.05657);
  EXPECT_NEAR(v[1][2], 0.00943, 0.01 * 0.00943);
}

TEST_F(AliasAlternates, InheritAndVoid) {
  const std::string pat = std::string(kLit) + "dim plastic red_pat 0 0 5 .6 .1 .1 0 0\n";
  // inherit: keeps the reference's modifier (dim).
  EXPECT_NEAR(ratio(pat + "inherit alias kept red_pat\n" + two_floors("red", "kept")), 0.1, 1e-4);
  // The reference's own modifier named explicitly: the same pass-through.
  EXPECT_NEAR(ratio(pat + "dim alias same red_pat\n" + two_floors("red", "same")), 0.1, 1e-4);
  // void: the copy has no modifier.
  EXPECT_NEAR(ratio(pat + "void alias plain red_pat\n" + two_floors("red", "plain")), 1.0, 1e-4);
  // Another modifier replaces dim (it does not add to it).
  EXPECT_NEAR(ratio(pat + "half alias halved red_pat\n" + two_floors("red", "halved")), 0.5, 1e-4);
}

TEST_F(AliasAlternates, AliasesOfAliases) {
  const std::string base = std::string(kLit) + "dim alias red_dim red\n";
  // A named alias of an alias: its target's target, with the newest alias's modifier.
  EXPECT_NEAR(ratio(base + "half alias red_half red_dim\n" + two_floors("red", "red_half")), 0.5,
              1e-4);
  // inherit: passes through to red_dim, whose dim applies once.
  EXPECT_NEAR(ratio(base + "inherit alias red_dim2 red_dim\n" + two_floors("red", "red_dim2")), 0.1,
              1e-4);
  // A pass-through alias of a pattern applies the pattern once, not twice.
  EXPECT_NEAR(ratio(std::string(kLit) + "inherit alias dim2 dim\n" +
                    "dim2 plastic red2 0 0 5 .6 .1 .1 0 0\n" + two_floors("red", "red2")),
              0.1, 1e-4);
  // A named alias of a pattern, with its own modifier after it: both apply.
  EXPECT_NEAR(ratio(std::string(kLit) + "half alias dim_half dim\n" +
                    "dim_half plastic red3 0 0 5 .6 .1 .1 0 0\n" + two_floors("red", "red3")),
              0.05, 1e-4);
}

TEST_F(AliasAlternates, ReferenceIsTheDefinitionBeforeTheAlias) {
  // red is redefined (green) after the alias: the alias keeps the first red; surfaces naming
  // red after the redefinition get the green one.
  const std::string s = std::string(kLit) + "half alias old_red red\n" +
                        "void plastic red 0 0 5 .1 .6 .1 0 0\n" + two_floors("red", "old_red");
  auto v = trace(s, {{{-1, 0, 1}, {0, 0, -1}}, {{1, 0, 1}, {0, 0, -1}}});
  EXPECT_NEAR(v[0][1] / v[0][0], 6.0, 1e-3); // left: the green red
  EXPECT_NEAR(v[1][0] / v[0][1], 0.5, 1e-4); // right: half of the first red's .6
  EXPECT_NEAR(v[1][0] / v[1][1], 6.0, 1e-3); // which was red
}

TEST_F(AliasAlternates, MixtureAsTheNewModifier) {
  // A mixture of two patterns, half and half: the copy's colour is scaled by 0.5 x 0.1 + 0.5 x
  // 0.5 = 0.3.
  const std::string s = std::string(kLit) + "void mixfunc blend 4 dim half 0.5 . 0 0\n" +
                        "blend alias red_blend red\n" + two_floors("red", "red_blend");
  EXPECT_NEAR(ratio(s), 0.3, 1e-4);
}

namespace {

// The mirror: a mirror on z = 0 with pink plastic as its alternate, a lamp above it,
// a grey ceiling at z = 3 facing down.
std::string mirror_scene(const std::string& mirror) {
  return "void plastic pink 0 0 5 .9 .5 .6 0 0\n" + mirror +
         "void light lamp 0 0 3 100 100 100\n"
         "lamp sphere bulb 0 0 4 1 0 2 0.2\n"
         "mir polygon p1 0 0 12  -2 -1 0  2 -1 0  2 1 0  -2 1 0\n"
         "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
         "grey polygon w 0 0 12 -2 -1 3  -2 1 3  2 1 3  2 -1 3\n";
}

const std::pair<render::Vec3d, render::Vec3d> kView{{0, -3, 1}, {0, 1, -0.3}};

} // namespace

TEST_F(AliasAlternates, MirrorShowsItsAlternate) {
  auto alt = trace(mirror_scene("void mirror mir 1 pink 0 3 .8 .8 .8\n"), {kView});
  // Radiance 2fcca99ac: 0.6231 0.3462 0.4154 (the pink plastic lit by the lamp).
  EXPECT_NEAR(alt[0][0], 0.6231, 0.01 * 0.6231);
  EXPECT_NEAR(alt[0][1], 0.3462, 0.01 * 0.3462);
  EXPECT_NEAR(alt[0][2], 0.4154, 0.01 * 0.4154);
  // Exactly what the pink plastic itself shows there.
  auto pink = trace(mirror_scene("void alias mir pink\n"), {kView});
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(alt[0][c], pink[0][c], 1e-5) << c;
}

TEST_F(AliasAlternates, MirrorVirtualSourcesStay) {
  // The ceiling above the mirror is lit by the lamp and by its image in the mirror; the
  // alternate changes neither.
  const std::pair<render::Vec3d, render::Vec3d> up{{0, 0, 2.5}, {0, 0, 1}};
  auto plain = trace(mirror_scene("void mirror mir 0 0 3 .8 .8 .8\n"), {up});
  auto alt = trace(mirror_scene("void mirror mir 1 pink 0 3 .8 .8 .8\n"), {up});
  auto none = trace(mirror_scene("void plastic mir 0 0 5 0 0 0 0 0\n"), {up});
  // The image adds 0.8 x (cos 0.98 / 26 m²) against the lamp's (cos 0.71 / 2 m²): 8.5%.
  EXPECT_NEAR(plain[0][0] / none[0][0], 1.085, 0.01);
  EXPECT_NEAR(alt[0][0], plain[0][0], 1e-5 * plain[0][0]);
}

TEST_F(AliasAlternates, MirrorAmbientRaysSeeTheMirror) {
  // A meter-like view of the ceiling at -ab 1: ambient rays from the ceiling meet the mirror's
  // front, which they see as a mirror (the alternate would count its light twice).
  const std::pair<render::Vec3d, render::Vec3d> up{{0.3, 0.2, 2.5}, {0, 0, 1}};
  auto plain = trace(mirror_scene("void mirror mir 0 0 3 .8 .8 .8\n"), {up}, 1);
  auto alt = trace(mirror_scene("void mirror mir 1 pink 0 3 .8 .8 .8\n"), {up}, 1);
  EXPECT_NEAR(alt[0][0], plain[0][0], 1e-4 * plain[0][0]);
  EXPECT_NEAR(alt[0][1], plain[0][1], 1e-4 * plain[0][1]);
}

TEST_F(AliasAlternates, MirrorWithVoidAlternateIsInvisible) {
  // A black floor below the mirror; with a void alternate, view rays see the floor lit
  // straight through the mirror, exactly as with no mirror at all.
  const std::string floor = "void plastic below 0 0 5 .5 .5 .5 0 0\n"
                            "below polygon f 0 0 12  -5 -5 -1  5 -5 -1  5 5 -1  -5 5 -1\n";
  const std::pair<render::Vec3d, render::Vec3d> down{{0.5, 0.3, 1}, {0, 0, -1}};
  auto gone = trace(floor + mirror_scene("void mirror mir 1 void 0 3 .8 .8 .8\n"), {down});
  // Without a mirror: the same scene with the mirror's polygon removed.
  std::string bare = floor + mirror_scene("void mirror mir 0 0 3 .8 .8 .8\n");
  bare.erase(bare.find("mir polygon"),
             bare.find('\n', bare.find("mir polygon")) - bare.find("mir polygon") + 1);
  auto none = trace(bare, {down});
  ASSERT_GT(none[0][0], 0.0);
  EXPECT_NEAR(gone[0][0], none[0][0], 1e-5 * none[0][0]);
}

TEST_F(AliasAlternates, MirrorBackShowsItsAlternate) {
  // From below, a mirror is black; with an alternate, that material, as the plastic itself
  // shows its back lit by a lamp below.
  const std::pair<render::Vec3d, render::Vec3d> from_below{{0.5, 0.3, -1}, {0, 0, 1}};
  const std::string lamp_below = "void light low 0 0 3 50 50 50\nlow sphere lb 0 0 4 0 0 -3 0.3\n";
  auto alt =
      trace(lamp_below + mirror_scene("void mirror mir 1 pink 0 3 .8 .8 .8\n"), {from_below});
  auto plain = trace(lamp_below + mirror_scene("void mirror mir 0 0 3 .8 .8 .8\n"), {from_below});
  auto pink = trace(lamp_below + mirror_scene("void alias mir pink\n"), {from_below});
  EXPECT_EQ(plain[0][0], 0.0);
  ASSERT_GT(pink[0][0], 0.0);
  EXPECT_NEAR(alt[0][0], pink[0][0], 1e-5 * pink[0][0]);
}
