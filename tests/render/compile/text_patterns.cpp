// Text patterns (brighttext, colortext, mixtext; scene-format.md §4, §4.2) with the small font
// tests/data/fonts/test.fnt, found on RAYPATH. The text lies on a grey plastic floor (z = 0)
// under a sun straight above; a pattern's effect is the ratio of the floor's radiance with it
// to the radiance without it, which is the foreground or background value exactly.
//
// The font's glyphs (256 x 256 cells): 'I' the bar x 100..155; 'L' the bar x 30..90 with the
// foot x 30..200, y 0..60; 'O' the ring between the squares 20..235 and 80..175; '.' a small
// square; ' ' no vertices. Mean glyph width (255 - extents as Radiance records them): 120.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

#include "radcl/device/context.h"
#include "radcl/render/compile/font_file.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/scene/mesh_writer.h"
#include "radcl/util/error.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;
namespace fs = std::filesystem;

namespace {

using Rgb = std::array<double, 3>;
using Pt = std::array<double, 2>;

std::string font_path() {
  return radcl::test::data("fonts/test.fnt");
}

render::Font test_font() {
  return render::read_font_file(font_path(), "test.fnt");
}

// The FatalError message of f(), or "" if it does not throw one.
template <class F> std::string fatal(F f) {
  try {
    f();
  } catch (const FatalError& e) {
    return e.what();
  }
  return "";
}

class TextPatterns : public radcl::test::SceneDir {
protected:
  std::string old_raypath;
  bool had_raypath = false;
  void SetUp() override {
    SceneDir::SetUp();
    if (const char* rp = std::getenv("RAYPATH")) old_raypath = rp, had_raypath = true;
    // The current directory (text files), then the fonts.
    setenv("RAYPATH", (":" + radcl::test::data("fonts")).c_str(), 1);
  }
  void TearDown() override {
    if (had_raypath)
      setenv("RAYPATH", old_raypath.c_str(), 1);
    else
      unsetenv("RAYPATH");
    SceneDir::TearDown();
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
  }
  // The radiance seen straight down from z = 2 at each point, in a scene of the sun, the test
  // materials and `rest`.
  std::vector<Rgb> render(const std::string& rest, const std::vector<Pt>& at) {
    write("scene.rad", "void light sunmat 0 0 3 1000 1000 1000\n"
                       "sunmat source sun 0 0 4 0 0 1 1\n"
                       "void plastic red 0 0 5 0.6 0.2 0.2 0 0\n"
                       "void plastic blue 0 0 5 0.1 0.1 0.5 0 0\n" +
                           rest + "\n");
    scene::LoadedScene ls = scene::load_scene({"scene.rad"});
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    render::Renderer r(ls, st, device::default_context());
    std::vector<render::PrimaryRay> pr;
    for (const auto& p : at)
      pr.push_back({{p[0], p[1], 2}, {0, 0, -1}, 0});
    std::vector<render::PrimaryResult> res(pr.size());
    r.render(pr, res);
    std::vector<Rgb> out;
    for (const auto& x : res)
      out.push_back(x.value);
    return out;
  }
  // A grey floor modified by `pattern` (whose name is "txt"), against the same floor without.
  // Returns the per-channel ratio at each point.
  std::vector<Rgb> ratios(const std::string& pattern, const std::vector<Pt>& at) {
    const std::string floor = " plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
                              "grey polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
    std::vector<Rgb> plain = render("void" + floor, at);
    std::vector<Rgb> pat = render(pattern + "\ntxt" + floor, at);
    std::vector<Rgb> out;
    for (std::size_t i = 0; i < at.size(); ++i) {
      Rgb q{};
      for (int c = 0; c < 3; ++c) {
        EXPECT_GT(plain[i][c], 0);
        q[c] = pat[i][c] / plain[i][c];
      }
      out.push_back(q);
    }
    return out;
  }
  static void expect_grey(const std::vector<Rgb>& got, const std::vector<double>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[i][c], want[i], 1e-5 * want[i]) << "point " << i << " channel " << c;
  }
};

// Text block: top-left corner (0, 4, 0), one unit to the right per character cell, one unit
// down (-y) per line, so line 0 covers 3 < y <= 4 and character k of it k <= x < k + 1 (with
// 255-unit cells); glyph coordinates there are ((x - k) 255, (y - 3) 255).
const char* kBlock = "0 4 0  1 0 0  0 -1 0";

} // namespace

TEST(FontFile, ReadsGlyphsAndExtentsAsRadiance) {
  render::Font f = test_font();
  ASSERT_TRUE(f.glyphs['O']);
  EXPECT_EQ(f.glyphs['O']->vertices(), 10);
  EXPECT_EQ(f.glyphs['O']->left, 20);
  EXPECT_EQ(f.glyphs['O']->right, 235);
  EXPECT_EQ(f.glyphs['L']->coords[8], 90);
  ASSERT_TRUE(f.glyphs[' ']);
  EXPECT_EQ(f.glyphs[' ']->vertices(), 0);
  EXPECT_EQ(f.glyphs['.']->top, 128); // each bound starts at the cell's middle
  EXPECT_EQ(f.glyphs['.']->bottom, 0);
  EXPECT_FALSE(f.glyphs['A']);
  EXPECT_EQ(f.mean_width, 120);  // (55 + 170 + 215 + 40) / 4
  EXPECT_EQ(f.mean_height, 213); // (255 + 255 + 215 + 128) / 4
}

// The three spacings, worked by hand from Radiance's rules with the test font.
TEST(FontFile, LineSpacing) {
  render::Font f = test_font();
  render::LineSpacing u = render::uniform_spacing("LOI", f);
  EXPECT_EQ(u.offset, (std::vector<int>{0, 255, 255, 255}));
  EXPECT_EQ(u.width, 765);
  u = render::uniform_spacing("LAI", f); // no glyph for 'A': it takes no room
  EXPECT_EQ(u.offset, (std::vector<int>{0, 255, 0, 255}));
  EXPECT_EQ(u.width, 510);
  // Squeezed, 51 between glyphs: 25 + 25 - 30 to L's left edge, 200 + 25 + 25 - 100 from L's
  // right edge to I's left edge, then 155 + 25 + 25 after I.
  render::LineSpacing s = render::squeezed_spacing("LI", f, 51);
  EXPECT_EQ(s.offset, (std::vector<int>{20, 150, 205}));
  EXPECT_EQ(s.width, 375);
  // A space advances the mean width (120) from the end of the previous glyph's gap.
  s = render::squeezed_spacing("L I", f, 51);
  EXPECT_EQ(s.offset, (std::vector<int>{20, 225, 45, 205}));
  EXPECT_EQ(s.width, 495);
  // Proportional: the run "LI" takes 2 (120 + 51) = 342 after the lead of 20; the squeezed
  // advances (150 + 205 = 355) lose 13, spread as -6 and -7.
  render::LineSpacing p = render::proportional_spacing("LI", f, 51, 3);
  EXPECT_EQ(p.offset, (std::vector<int>{20, 144, 198}));
  EXPECT_EQ(p.width, 362);
  // A glyph followed by more than 3 spaces ends a run: "L" and its 4 spaces take 5 (120 + 51)
  // = 855 (squeezed: 225 + 3 120 + 45 = 630, so each of the 5 advances gains 45), then "I"
  // alone 171 (squeezed 205).
  p = render::proportional_spacing("L    I", f, 51, 3);
  EXPECT_EQ(p.offset, (std::vector<int>{20, 270, 165, 165, 165, 90, 171}));
  EXPECT_EQ(p.width, 1046);
}

TEST(FontFile, BadFilesAreFatalWithTheirName) {
  const radcl::test::TempFolder dir("bad_font");
  const fs::path p = dir / "bad.fnt";
  auto check = [&](const std::string& text, const std::string& message) {
    std::ofstream(p) << text;
    std::string got = fatal([&] { render::read_font_file(p.string(), "bad.fnt"); });
    EXPECT_NE(got.find(message + " in font file \"" + p.string() + "\""), std::string::npos) << got;
  };
  check("65 3 0 0 10 10 300 0\n", "bad vertex for character (65)");
  check("65 3 0 0 10 10 20\n", "bad vertex for character (65)"); // ends early
  check("65 x\n", "bad # vertices for character (65)");
  check("65 -1\n", "bad # vertices for character (65)");
  check("65 0 0.5 0\n", "non-integer");
  check("256 0\n", "illegal character (256)");
  check("0 0\n", "illegal character (0)");
  check("65 0\n65 0\n", "duplicate character (65)");
  EXPECT_NE(fatal([] {
              render::read_font_file("/nonexistent/x.fnt", "x.fnt");
            }).find("cannot open font file \"x.fnt\""),
            std::string::npos);
}

// brighttext, one line of words from the string arguments, uniform 255-unit cells.
TEST_F(TextPatterns, BrighttextInsideAndOutsideGlyphs) {
  std::vector<Pt> at = {
      {0.25, 3.5}, // L's bar (63.75, 127.5)
      {0.5, 3.5},  // right of L's bar, above its foot (127.5, 127.5)
      {0.5, 3.1},  // L's foot (127.5, 25.5)
      {1.1, 3.5},  // O's ring (25.5, 127.5)
      {1.5, 3.5},  // O's hole (127.5, 127.5)
      {2.5, 3.5},  // I (127.5, 127.5)
      {2.2, 3.5},  // left of I (51, 127.5)
      {3.5, 3.5},  // past the end of the line
      {-0.5, 3.5}, // before its start
      {0.25, 4.2}, // above the block
      {0.25, 2.5}, // below the only line
  };
  expect_grey(
      ratios("void brighttext txt 3 test.fnt . LOI 0 11 " + std::string(kBlock) + " 0.8 0.2", at),
      {0.8, 0.2, 0.8, 0.8, 0.2, 0.8, 0.2, 0.2, 0.2, 0.2, 0.2});
  // Words join with single spaces; the space glyph takes a cell: "I I" puts I in cells 0 and 2.
  expect_grey(
      ratios("void brighttext txt 4 test.fnt . I I 0 11 " + std::string(kBlock) + " 0.8 0.2",
             {{0.5, 3.5}, {1.5, 3.5}, {2.5, 3.5}}),
      {0.8, 0.2, 0.8});
}

// colortext from a text file of several lines (line 1 empty), each one unit below the last.
TEST_F(TextPatterns, ColortextLinesFromAFile) {
  write("words.txt", "LI\n\nO\n");
  std::vector<Pt> at = {
      {0.25, 3.5}, // line 0: L
      {1.5, 3.5},  // line 0: I
      {1.2, 3.5},  // line 0: left of I
      {0.25, 2.5}, // line 1: empty
      {0.1, 1.5},  // line 2: O's ring (25.5, 127.5)
      {0.5, 1.5},  // line 2: O's hole
      {0.1, 0.5},  // below the last line
  };
  std::vector<Rgb> q = ratios("void colortext txt 2 test.fnt words.txt 0 15 " +
                                  std::string(kBlock) + " 0.9 0.5 0.25  0.125 0.75 0.5",
                              at);
  const Rgb fg{0.9, 0.5, 0.25}, bg{0.125, 0.75, 0.5};
  const std::vector<Rgb> want = {fg, fg, bg, bg, fg, bg, bg};
  for (std::size_t i = 0; i < at.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(q[i][c], want[i][c], 1e-5 * want[i][c]) << "point " << i << " channel " << c;
}

// Spacing: negative squeezes glyphs 51 units apart, positive spreads them proportionally; with
// either, a world unit spans the mean glyph width plus the spacing (120 + 51 = 171 units).
// "LI" squeezed: L starts at 20, I at 170; proportional: L at 20, I at 164.
TEST_F(TextPatterns, Spacing) {
  const std::string head =
      "void brighttext txt 3 test.fnt . LI 0 12 " + std::string(kBlock) + " 1 0.25 ";
  std::vector<Pt> at = {
      {0.45, 3.5},  // 76.95: L's bar (squeezed and proportional: 56.95)
      {1.75, 3.5},  // 299.25: I (129.25 / 135.25)
      {1.56, 3.5},  // 266.76: squeezed 96.76 left of I, proportional 102.76 inside I
      {1.885, 3.5}, // 322.34: squeezed 152.3 inside I, proportional 158.3 right of it
      {1.2, 3.1},   // 205.2: inside L's foot (185.2, 25.5), I's cell overlaps there
      {1.2, 3.5},   // the same above the foot: neither glyph
      {2.3, 3.5},   // 393.3: past the line (375 squeezed, 362 proportional)
  };
  expect_grey(ratios(head + "-0.2", at), {1, 1, 0.25, 1, 1, 0.25, 0.25});
  expect_grey(ratios(head + "0.2", at), {1, 1, 1, 0.25, 1, 0.25, 0.25});
  // An explicit spacing of 0: uniform 255-unit cells, but measured with the mean width (120
  // units per world unit), as Radiance does: I's bar (610..665) lies at x = 5.08..5.54, and
  // x = 3.2 (384) is in O's hole (129, 127.5).
  expect_grey(
      ratios("void brighttext txt 3 test.fnt . LOI 0 12 " + std::string(kBlock) + " 1 0.25 0",
             {{5.3, 3.5}, {0.55, 3.5}, {3.2, 3.5}}),
      {1, 1, 0.25});
}

// Vectors in any direction: R along +y, D along +x (text reads up the floor, lines advance in
// x); the normal component of a point (here 5 units) does not matter. Line 0 covers
// 0 <= x < 1, character k of it k <= y < k + 1; glyph coordinates ((y - k) 255, (1 - x) 255).
TEST_F(TextPatterns, RotatedMotionVectors) {
  expect_grey(ratios("void brighttext txt 3 test.fnt . LOI 0 11  0 0 5  0 1 0  1 0 0  1 0.5",
                     {{0.5, 2.5}, {0.5, 2.2}, {0.1, 0.25}, {0.9, 0.5}, {0.5, 0.5}}),
              {1, 0.5, 1, 1, 0.5}); // I; left of I; L's bar; L's foot; above the foot
}

// A pattern on a transformed mesh works in the mesh's own coordinates (Radiance's object
// transform): with -rz 90 -t 10 0 0, mesh point (x, y) is world (10 - y, x).
TEST_F(TextPatterns, FollowsTheMeshTransform) {
  scene::TriangleMesh m;
  m.positions = {{-1, -1, 0}, {5, -1, 0}, {5, 5, 0}, {-1, 5, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  scene::write_mesh(m, (dir / "quad.rtm").string());
  std::vector<Rgb> plain = render("void plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
                                  "grey mesh quad 7 quad.rtm -rz 90 -t 10 0 0 0 0",
                                  {{6.5, 0.25}, {6.5, 0.5}, {6.5, 2.5}});
  std::vector<Rgb> pat = render("void brighttext txt 3 test.fnt . LOI 0 11 " + std::string(kBlock) +
                                    " 1 0.25\n"
                                    "txt plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
                                    "grey mesh quad 7 quad.rtm -rz 90 -t 10 0 0 0 0",
                                {{6.5, 0.25}, {6.5, 0.5}, {6.5, 2.5}});
  const double want[3] = {1, 0.25, 1}; // L's bar, beside it, I
  for (int i = 0; i < 3; ++i) {
    ASSERT_GT(plain[i][0], 0);
    EXPECT_NEAR(pat[i][0] / plain[i][0], want[i], 1e-5) << "point " << i;
  }
}

// mixtext: red inside the glyphs, blue outside, each exactly as the material alone.
TEST_F(TextPatterns, MixtextChoosesBetweenTwoMaterials) {
  const std::string floor = " polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
  std::vector<Pt> at = {{0.25, 3.5}, {0.5, 3.5}, {1.1, 3.5}, {1.5, 3.5}, {2.5, 3.5}, {5, 5}};
  std::vector<Rgb> red = render("red" + floor, at);
  std::vector<Rgb> blue = render("blue" + floor, at);
  std::vector<Rgb> mix = render(
      "void mixtext mx 5 red blue test.fnt . LOI 0 9 " + std::string(kBlock) + "\nmx" + floor, at);
  const bool inside[] = {true, false, true, false, true, false};
  for (std::size_t i = 0; i < at.size(); ++i) {
    const Rgb& want = inside[i] ? red[i] : blue[i];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(mix[i][c], want[c], 1e-5 * want[c]) << "point " << i << " channel " << c;
  }
  EXPECT_GT(std::abs(red[0][0] - blue[0][0]), 0.1 * red[0][0]);
}

TEST_F(TextPatterns, Errors) {
  const std::string floor = "\ntxt plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
                            "grey polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
  auto message = [&](const std::string& pattern) {
    return fatal([&] { render(pattern + floor, {{0, 0}}); });
  };
  const std::string reals = " 0 11 " + std::string(kBlock) + " 1 0.5";
  EXPECT_NE(message("void brighttext txt 3 none.fnt . LOI" + reals)
                .find("brighttext \"txt\": cannot find font file \"none.fnt\""),
            std::string::npos);
  write("bad.fnt", "73 2 0 0 10 zz\n");
  EXPECT_NE(
      message("void brighttext txt 3 bad.fnt . LOI" + reals).find("bad vertex for character (73)"),
      std::string::npos);
  EXPECT_NE(message("void brighttext txt 2 test.fnt none.txt" + reals)
                .find("cannot find text file \"none.txt\""),
            std::string::npos);
  // Too few arguments: the reader refuses them before the renderer sees them.
  for (const std::string& bad :
       {"void brighttext txt 3 test.fnt . LOI 0 10 " + std::string(kBlock) + " 1",
        "void colortext txt 3 test.fnt . LOI 0 14 " + std::string(kBlock) + " 1 1 1 1 1",
        "void brighttext txt 1 test.fnt" + reals})
    EXPECT_NE(message(bad).find("bad # arguments for " + bad.substr(5, 10)), std::string::npos)
        << bad;
  EXPECT_NE(message("void mixtext txt 4 red blue test.fnt x.txt 0 8 0 0 0 1 0 0 0 1 0")
                .find("bad # arguments for mixtext \"txt\""),
            std::string::npos);
  EXPECT_NE(message("void brighttext txt 3 test.fnt . LOI 0 11 0 4 0  1 0 0  2 0 0  1 0.5")
                .find("illegal motion vector for brighttext \"txt\""),
            std::string::npos);
}
