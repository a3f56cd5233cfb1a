// brightdata, colordata, texdata and colorpict against hand-computed interpolation
// (scene-format.md §4.1): a glowing floor (z = 0) seen straight down shows the pattern's value
// itself; texdata tilts a plastic floor's normal under a sun overhead.
#include "radcl/luminance.h"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "radcl/device/context.h"
#include "radcl/geometry/scene_geometry.h"
#include "radcl/image/picture.h"
#include "radcl/render/compile/compiled_scene.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/util/error.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;

namespace {

const char* kCal = R"(
twice(v) = 2 * v;
scaled(v) = v * A1;
sum3(r, g, b) = r + g + b;
tx(a, b, c) = a;  ty(a, b, c) = b;  tz(a, b, c) = c;
)";

// 1-D, evenly spaced: x = 0 1 2 3 4.
const char* kLine = "# a line\n1\n0 4 5\n3 2 4 8 16 # values\n";
// 2-D: first axis explicit (0 1 3), second evenly spaced (0, 10); last axis varies fastest.
const char* kGrid = "2\n0 0 3  0 1 3\n0 10 2\n1 2\n3 5\n7 11\n";

class PatternData : public radcl::test::SceneDir {
protected:
  void SetUp() override {
    SceneDir::SetUp();
    std::ofstream(dir / "d.cal") << kCal;
    std::ofstream(dir / "line.dat") << kLine;
    std::ofstream(dir / "grid.dat") << kGrid;
    std::ofstream(dir / "r.dat") << "1\n0 1 2\n1 3\n";
    std::ofstream(dir / "g.dat") << "1\n0 1 2\n10 20\n";
    std::ofstream(dir / "b.dat") << "1\n0 1 2\n100 200\n";
  }
  // The glowing floor's radiance seen from above each (x, y): the pattern's colour.
  std::vector<std::array<double, 3>> glow(const std::string& mods, const std::string& chain,
                                          const std::vector<std::array<double, 2>>& at) {
    std::ofstream(dir / "scene.rad")
        << mods << "\n"
        << chain << " glow lit 0 0 4 1 1 1 0\n"
        << "lit polygon floor 0 0 12 -20 -20 0 20 -20 0 20 20 0 -20 20 0\n";
    return render_down(at);
  }
  std::vector<std::array<double, 3>> render_down(const std::vector<std::array<double, 2>>& at) {
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    return render_values("scene.rad", rays_down(at, 1), st);
  }
  void fails(const std::string& mods, const std::string& want) {
    try {
      glow(mods, "p", {{0, 0}});
      ADD_FAILURE() << "no error for " << mods;
    } catch (const FatalError& e) {
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
    }
  }
};

} // namespace

// Inside, at grid points, linear extrapolation up to one step beyond the ends, then the
// 1/distance fall-off: (2*y1 - y0) / (x - (i-1)) above, (2*y0 - y1) / (i - x) below.
TEST_F(PatternData, BrightdataOneDimension) {
  auto v = glow("void brightdata p 4 noop line.dat . Px 0 0", "p",
                {{2, 0}, {2.5, 0}, {0.25, 0}, {4, 0}, {4.5, 0}, {6, 0}, {-0.5, 0}, {-3, 0}});
  const double want[] = {4, 6, 2.75, 16, 20, 6, 3.5, 4.0 / 3};
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_NEAR(v[i][0], want[i], 1e-5 * want[i]) << i;
    EXPECT_NEAR(v[i][1], want[i], 1e-5 * want[i]) << i;
  }
}

// The function of the value, with the pattern's real arguments and a transform: function
// coordinates are world minus (1, 0, 0).
TEST_F(PatternData, BrightdataFunctionArgumentsAndTransform) {
  auto v = glow("void brightdata p 8 twice line.dat d.cal Px -t 1 0 0 0 0", "p", {{3.5, 0}});
  EXPECT_NEAR(v[0][0], 2 * 6, 1e-4);
  auto w = glow("void brightdata q 4 scaled line.dat d.cal Px 0 1 0.5", "q", {{2.5, 0}});
  EXPECT_NEAR(w[0][0], 0.5 * 6, 1e-5);
}

// 2-D with an explicit first axis: inside, at a grid point, beyond the explicit axis (fall-off)
// and within one step before the even axis (linear).
TEST_F(PatternData, BrightdataTwoDimensionsExplicitAxis) {
  auto v = glow("void brightdata p 5 noop grid.dat . Px Py 0 0", "p",
                {{2, 2.5}, {1, 10}, {8, 0}, {0, -5}, {0.5, 5}});
  EXPECT_NEAR(v[0][0], 5.75, 1e-5);
  EXPECT_NEAR(v[1][0], 5.0, 1e-5);
  EXPECT_NEAR(v[2][0], 11.0 / 4.5, 1e-5);
  EXPECT_NEAR(v[3][0], 0.5, 1e-5);
  // (0.5, 5): halfway on both axes between 1 2 / 3 5.
  EXPECT_NEAR(v[4][0], (1 + 2 + 3 + 5) / 4.0, 1e-5);
}

// colordata: one data file per channel; a function of 1 parameter gets its own channel's
// value, one of 3 parameters gets all three.
TEST_F(PatternData, ColordataChannelsAndFunctionArity) {
  auto v =
      glow("void colordata p 8 sum3 noop twice r.dat g.dat b.dat d.cal Px 0 0", "p", {{0.5, 0}});
  EXPECT_NEAR(v[0][0], 2 + 15 + 150, 1e-3);
  EXPECT_NEAR(v[0][1], 15, 1e-4);
  EXPECT_NEAR(v[0][2], 300, 1e-3);
}

// texdata: the three values through 3-parameter functions perturb the normal like texfunc:
// (0.5, 0, 0) under a sun overhead gives cos = 1/sqrt(1.25). The coordinate is a constant
// inside the data's range.
TEST_F(PatternData, TexdataTiltsTheNormal) {
  std::ofstream(dir / "half.dat") << "1\n0 1 2\n0.5 0.5\n";
  std::ofstream(dir / "zero.dat") << "1\n0 1 2\n0 0\n";
  auto floor = [&](const std::string& mods, const std::string& chain) {
    std::ofstream(dir / "scene.rad")
        << "void light sunmat 0 0 3 1000 1000 1000\n"
        << "sunmat source sun 0 0 4 0 0 1 1\n"
        << mods << "\n"
        << chain << " plastic grey 0 0 5 0.5 0.5 0.5 0 0\n"
        << "grey polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
    return render_down({{3, 2}});
  };
  auto plain = floor("", "void");
  auto tex = floor("void texdata t 8 tx ty tz half.dat zero.dat zero.dat d.cal 0.5 0 0", "t");
  ASSERT_GT(plain[0][0], 0);
  EXPECT_NEAR(tex[0][0] / plain[0][0], 1 / std::sqrt(1.25), 1e-3);
}

// colorpict: a 3x2 picture covers u in [0, 1.5], v in [0, 1], bottom row at v = 0, pixel
// centres on the grid points; with PIXASPECT=2 it covers u in [0, 1], v in [0, 4/3].
TEST_F(PatternData, ColorpictCoordinates) {
  // Top row then bottom row, left to right.
  std::vector<image::Color> px = {{1, 2, 4},   {2, 4, 8},   {4, 8, 16},
                                  {0.5, 1, 2}, {8, 16, 32}, {16, 32, 64}};
  std::vector<image::Rgbe> rgbe;
  for (const auto& c : px)
    rgbe.push_back(image::to_rgbe(c));
  image::PictureHeader h;
  h.add_id().add_format();
  image::write_picture("p.hdr", h, 3, 2, rgbe);
  image::PictureHeader ha = h;
  ha.add_pixaspect(2);
  image::write_picture("pa.hdr", ha, 3, 2, rgbe);
  auto c = [&](int i) { return image::to_color(rgbe[i]); };

  auto v = glow("void colorpict p 7 noop noop noop p.hdr . Px Py 0 0", "p",
                {{0.75, 1}, {0, 0}, {0.375, 0.5}, {1.5, 0}});
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(v[0][ch], c(1)[ch], 1e-5 * c(1)[ch]);
    EXPECT_NEAR(v[1][ch], c(3)[ch], 1e-5 * c(3)[ch]);
    double mid = (c(0)[ch] + c(1)[ch] + c(3)[ch] + c(4)[ch]) / 4;
    EXPECT_NEAR(v[2][ch], mid, 1e-5 * mid);
    EXPECT_NEAR(v[3][ch], c(5)[ch], 1e-5 * c(5)[ch]);
  }
  auto a =
      glow("void colorpict p 7 noop noop noop pa.hdr . Px Py 0 0", "p", {{0.5, 4.0 / 3}, {1, 0}});
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(a[0][ch], c(1)[ch], 1e-5 * c(1)[ch]);
    EXPECT_NEAR(a[1][ch], c(5)[ch], 1e-5 * c(5)[ch]);
  }
  // grey(r, g, b) takes three parameters: every channel gets the grey of the pixel.
  auto g = glow("void colorpict p 7 grey grey grey p.hdr . Px Py 0 0", "p", {{0.75, 1}});
  double grey = radcl::bright(c(1));
  EXPECT_NEAR(g[0][0], grey, 1e-5 * grey);
  EXPECT_NEAR(g[0][2], grey, 1e-5 * grey);
}

// Several primitives using one data file share one copy of it.
TEST_F(PatternData, OneCopyPerFile) {
  auto args_size = [&](const std::string& mods) {
    std::ofstream(dir / "scene.rad") << mods << "\np glow lit 0 0 4 1 1 1 0\n"
                                     << "lit polygon floor 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n";
    scene::LoadedScene ls = scene::load_scene({"scene.rad"});
    geometry::SceneGeometry geom(ls);
    return render::compile_scene(ls, geom).args.size();
  };
  std::size_t one = args_size("void brightdata p 5 noop grid.dat . Px Py 0 0");
  std::size_t two = args_size("void brightdata q 5 noop grid.dat . Py Px 0 0\n"
                              "q brightdata p 5 noop grid.dat . Px Py 0 0");
  // The second pattern adds its transform (25), descriptor (6) and no data (1+4*2+6+3 = 18).
  EXPECT_EQ(two - one, 25u + 6u);
}

TEST_F(PatternData, Errors) {
  std::ofstream(dir / "bad.dat") << "1\n0 1 2\n1 x\n";
  std::ofstream(dir / "short.dat") << "1\n0 1 3\n1 2\n";
  std::ofstream(dir / "dims.dat") << "7\n";
  std::ofstream(dir / "mono.dat") << "1\n0 0 3 0 2 1\n1 2 3\n";
  std::ofstream(dir / "bad.hdr") << "not a picture\n";
  fails("void brightdata p 4 noop nofile.dat . Px 0 0", "cannot find data file \"nofile.dat\"");
  fails("void brightdata p 4 noop bad.dat . Px 0 0", "bad format in data file");
  fails("void brightdata p 4 noop short.dat . Px 0 0", "unexpected EOF in data file");
  fails("void brightdata p 4 noop dims.dat . Px 0 0", "bad number of dimensions for \"dims.dat\"");
  fails("void brightdata p 4 noop mono.dat . Px 0 0", "bad format in data file");
  fails("void brightdata p 4 noop grid.dat . Px 0 0", "brightdata \"p\": too few string arguments");
  fails("void colordata p 8 noop noop noop r.dat grid.dat b.dat . Px 0 0",
        "colordata \"p\": dimension error");
  fails("void brightdata p 4 nosuch line.dat . Px 0 0", "brightdata \"p\"");
  fails("void colorpict p 7 noop noop noop none.hdr . Px Py 0 0",
        "cannot find picture file \"none.hdr\"");
  fails("void colorpict p 7 noop noop noop bad.hdr . Px Py 0 0", "bad picture file \"bad.hdr\"");
  fails("void brightdata p 6 noop line.dat . Px -t 1 0 0", "bad transform for brightdata");
}
