// Mixtures beyond two materials (scene-format.md §4, §4.1; Radiance's raymixture, mx_data):
// mixdata and mixpict coefficients, mixtures of patterns and textures (the sides' colours and
// normal perturbations blended), nested mixtures, mixtures after a material, more side types,
// and Radiance's errors. Most sides are glows seen straight down, whose radiance is their
// colour exactly, so the expected values are computed by hand from the coefficients.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

#include "radcl/device/context.h"
#include "radcl/image/picture.h"
#include "radcl/render/pipeline/renderer.h"
#include "radcl/util/error.h"
#include "scene_dir.h"
#include "test_env.h"

using namespace radcl;
namespace fs = std::filesystem;

namespace {

using Rgb = std::array<double, 3>;

// ga, gb, gc, gd: glows of known colour; ca, cb: colour patterns.
const char* kModifiers = "void glow ga 0 0 4 2 0 0 0\n"
                         "void glow gb 0 0 4 0 0 4 0\n"
                         "void glow gc 0 0 4 0 3 0 0\n"
                         "void glow gd 0 0 4 1 1 1 0\n"
                         "void colorfunc ca 4 1 0.5 0.25 . 0 0\n"
                         "void colorfunc cb 4 0.2 0.4 0.8 . 0 0\n";

const char* kCal = "half(v) = v / 2;\n"
                   "big(v) = 4 * v;\n"
                   "redv(r, g, b) = r;\n"
                   "greenv(r, g, b) = g;\n"
                   "one(x) = x;\n"
                   "sel = if(Px, 1, 0);\n";

Rgb mix(double c, const Rgb& a, const Rgb& b) {
  return {c * a[0] + (1 - c) * b[0], c * a[1] + (1 - c) * b[1], c * a[2] + (1 - c) * b[2]};
}
Rgb times(const Rgb& a, const Rgb& b) {
  return {a[0] * b[0], a[1] * b[1], a[2] * b[2]};
}
Rgb plus(const Rgb& a, const Rgb& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Rgb scale(double s, const Rgb& a) {
  return {s * a[0], s * a[1], s * a[2]};
}

const Rgb kGa{2, 0, 0}, kGb{0, 0, 4}, kGc{0, 3, 0}, kGd{1, 1, 1};
const Rgb kCa{1, 0.5, 0.25}, kCb{0.2, 0.4, 0.8};

class Mixtures : public radcl::test::SceneDir {
protected:
  void SetUp() override {
    SceneDir::SetUp();
    std::ofstream(dir / "mix.cal") << kCal;
    for (const char* f : {"mix_ramp.dat", "mix_grid.dat"})
      fs::copy_file(test::data(std::string("render/") + f), dir / f);
  }
  // The radiance seen straight down from z = 2 at each (x, y), in a scene of a sun overhead,
  // the test modifiers and `rest` (rtrace -ab 0 -dj 0).
  std::vector<Rgb> render(const std::string& rest, const std::vector<std::array<double, 2>>& at,
                          bool irradiance = false) {
    std::ofstream(dir / "scene.rad") << "void light sunmat 0 0 3 1000 1000 1000\n"
                                     << "sunmat source sun 0 0 4 0 0 1 1\n"
                                     << kModifiers << rest << "\n";
    render::RenderSettings st;
    st.ab = 0;
    st.dj = 0;
    st.irradiance_i = irradiance;
    return render_values("scene.rad", rays_down(at, 2), st);
  }
  Rgb render1(const std::string& rest, double x = 0.5, double y = 0.5) {
    return render(rest, {{x, y}})[0];
  }
  static std::string floor(const std::string& mod) {
    return mod + " polygon floor 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n";
  }
  static std::string screen(const std::string& mod) {
    return mod + " polygon screen 0 0 12 -10 -10 1 10 -10 1 10 10 1 -10 10 1\n";
  }
  static void expect_rgb(const Rgb& got, const Rgb& want, double rel = 1e-5) {
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(got[c], want[c], rel * std::abs(want[c]) + 1e-6) << "channel " << c;
  }
  void fails(const std::string& rest, const std::string& want) {
    try {
      render(rest, {{0.5, 0.5}});
      ADD_FAILURE() << "no error for " << rest;
    } catch (const FatalError& e) {
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
    }
  }
};

} // namespace

// mixdata: the coefficient is func(value interpolated at the coordinates), clamped to [0, 1].
TEST_F(Mixtures, MixdataInterpolatesTheCoefficient) {
  // mix_ramp.dat: 0 0.2 0.6 1.0 0.4 at x = 0..4; half() halves it.
  auto v = render("void mixdata m 6 ga gb half mix_ramp.dat mix.cal Px 0 0\n" + floor("m"),
                  {{1.5, 0}, {2.5, 3}, {3.25, -2}, {0, 1}});
  expect_rgb(v[0], mix(0.2, kGa, kGb));
  expect_rgb(v[1], mix(0.4, kGa, kGb));
  expect_rgb(v[2], mix(0.425, kGa, kGb));
  expect_rgb(v[3], kGb);
  // big() = 4 v goes past 1 and is clamped; coordinates after a transform argument count.
  auto b = render("void mixdata m 10 ga gb big mix_ramp.dat mix.cal Px -t 1 0 0 0 0\n" + floor("m"),
                  {{1.25, 0}, {2, 0}, {3, 0}});
  expect_rgb(b[0], mix(0.2, kGa, kGb)); // Px = x - 1 = 0.25: value 0.05, coefficient 0.2
  expect_rgb(b[1], mix(0.8, kGa, kGb)); // Px = 1: value 0.2
  expect_rgb(b[2], kGa);                // Px = 2: value 0.6, 4 v = 2.4 clamped to 1
}

// A 2-D data file: the first coordinate goes with the first axis (explicit points 0 1 3).
TEST_F(Mixtures, MixdataTwoDimensions) {
  auto v = render("void mixdata m 7 ga gb one mix_grid.dat mix.cal Px Py 0 0\n" + floor("m"),
                  {{1, 0.5}, {2, 1}, {0.5, 2}});
  expect_rgb(v[0], mix(0.35, kGa, kGb));
  expect_rgb(v[1], mix(0.6, kGa, kGb));
  expect_rgb(v[2], mix(0.35, kGa, kGb)); // halfway between 0.2 and 0.5
}

// mixpict: the coefficient is func(r, g, b) of the picture's colour at (u, v); a function of
// one parameter gets the red channel.
TEST_F(Mixtures, MixpictUsesThePictureColour) {
  // 3 x 2 pixels: u in [0, 1.5], v in [0, 1], bottom row at v = 0; top row first here.
  std::vector<image::Color> px = {{0.25, 0.5, 0}, {0.5, 0.125, 0}, {1, 0, 0},
                                  {0, 1, 0},      {0.75, 0.25, 0}, {0.125, 0.5, 0}};
  std::vector<image::Rgbe> rgbe;
  for (const auto& c : px)
    rgbe.push_back(image::to_rgbe(c));
  image::PictureHeader h;
  h.add_id().add_format();
  image::write_picture("m.hdr", h, 3, 2, rgbe);
  auto c = [&](int i) { return image::to_color(rgbe[i]); };

  auto red = render("void mixpict m 7 ga gb redv m.hdr mix.cal Px Py 0 0\n" + floor("m"),
                    {{0.75, 1}, {0, 0}, {0.375, 0.5}, {1.5, 0}});
  expect_rgb(red[0], mix(c(1)[0], kGa, kGb));
  expect_rgb(red[1], mix(c(3)[0], kGa, kGb));
  expect_rgb(red[2], mix((c(0)[0] + c(1)[0] + c(3)[0] + c(4)[0]) / 4, kGa, kGb));
  expect_rgb(red[3], mix(c(5)[0], kGa, kGb));
  auto green = render("void mixpict m 7 ga gb greenv m.hdr mix.cal Px Py 0 0\n" + floor("m"),
                      {{0.75, 1}, {0, 1}});
  expect_rgb(green[0], mix(c(1)[1], kGa, kGb));
  expect_rgb(green[1], mix(c(0)[1], kGa, kGb));
  auto one = render1("void mixpict m 7 ga gb one m.hdr mix.cal Px Py 0 0\n" + floor("m"), 0.75, 0);
  expect_rgb(one, mix(c(4)[0], kGa, kGb));
}

// Two colour patterns mixed over one material: the colours are blended by the coefficient,
// whether the mixture comes before the material or after it (in its own modifiers).
TEST_F(Mixtures, PatternSidesBlendTheColours) {
  Rgb want = times(kGd, mix(0.3, kCa, kCb));
  // After the material (among its own modifiers), then before it.
  expect_rgb(render1("void mixfunc m 4 ca cb 0.3 . 0 0\nm glow g 0 0 4 1 1 1 0\n" + floor("g")),
             want);
  expect_rgb(render1("void glow g 0 0 4 1 1 1 0\ng mixfunc m 4 ca cb 0.3 . 0 0\n" + floor("m")),
             want);
  // A void side leaves the colour as it is: 0.3 ca + 0.7.
  expect_rgb(render1("void glow g 0 0 4 1 1 1 0\ng mixfunc m 4 ca void 0.3 . 0 0\n" + floor("m")),
             mix(0.3, kCa, {1, 1, 1}));
  // A pattern before the mixture multiplies both sides; the coefficient may vary.
  auto v = render("void glow g 0 0 4 1 1 1 0\ng mixfunc m 4 ca cb sel mix.cal 0 0\n"
                  "m brightfunc dim 2 0.5 . 0 0\n" +
                      floor("dim"),
                  {{3, 1}, {-3, 1}});
  expect_rgb(v[0], scale(0.5, kCa));
  expect_rgb(v[1], scale(0.5, kCb));
}

// A texture on one side and void on the other: the normal perturbation is scaled by the
// coefficient (a plastic floor under the sun overhead gets cos = 1 / |n + c D|).
TEST_F(Mixtures, TextureSidesBlendThePerturbation) {
  auto plain = render1("void plastic p 0 0 5 0.5 0.5 0.5 0 0\n" + floor("p"), 3, 2);
  auto tex = render1("void texfunc t 4 0.5 0 0 . 0 0\n"
                     "void plastic p 0 0 5 0.5 0.5 0.5 0 0\n"
                     "p mixfunc m 4 t void 0.5 . 0 0\n" +
                         floor("m"),
                     3, 2);
  ASSERT_GT(plain[0], 0);
  EXPECT_NEAR(tex[0] / plain[0], 1 / std::sqrt(1 + 0.25 * 0.25), 1e-3);
}

// Nested mixtures of materials: each leaf gets the product of the coefficients on its path.
TEST_F(Mixtures, NestedMixturesOfMaterials) {
  Rgb inner = mix(0.25, kGa, kGb);
  expect_rgb(render1("void mixfunc in 4 ga gb 0.25 . 0 0\nvoid mixfunc out 4 in gc 0.6 . 0 0\n" +
                     floor("out")),
             mix(0.6, inner, kGc));
  expect_rgb(render1("void mixfunc in 4 ga gb 0.25 . 0 0\nvoid mixfunc out 4 gc in 0.6 . 0 0\n" +
                     floor("out")),
             mix(0.6, kGc, inner));
  // A void leaf lets its share (0.6 x 0.5) through to the floor behind.
  expect_rgb(render1("void mixfunc in 4 ga void 0.5 . 0 0\nvoid mixfunc out 4 in gc 0.6 . 0 0\n" +
                     screen("out") + floor("gd")),
             plus(plus(scale(0.3, kGa), scale(0.4, kGc)), scale(0.3, kGd)));
  // Three levels, with a mixdata in the middle: 0.5 (0.2 ga + 0.8 (0.75 gb + 0.25 gc)) + 0.5 gd.
  Rgb deep = mix(0.5, mix(0.2, kGa, mix(0.75, kGb, kGc)), kGd);
  expect_rgb(render1("void mixfunc l3 4 gb gc 0.75 . 0 0\n"
                     "void mixdata l2 6 ga l3 half mix_ramp.dat mix.cal Px 0 0\n"
                     "void mixfunc l1 4 l2 gd 0.5 . 0 0\n" +
                         floor("l1"),
                     1.5, 0),
             deep);
}

// Nested mixtures of patterns, and patterns on a path to a material.
TEST_F(Mixtures, NestedMixturesOfPatterns) {
  Rgb inner = mix(0.5, kCa, kCb);
  expect_rgb(render1("void mixfunc p1 4 ca cb 0.5 . 0 0\nvoid mixfunc p2 4 p1 void 0.25 . 0 0\n"
                     "p2 glow g 0 0 4 1 1 1 0\n" +
                     floor("g")),
             mix(0.25, inner, {1, 1, 1}));
  // One side is a pattern over a glow (before it in the chain), the other a glow whose own
  // modifier is a pattern; a pattern before the mixture applies to both.
  expect_rgb(render1("void glow w 0 0 4 1 1 1 0\nw colorfunc cw 4 1 0.5 0.25 . 0 0\n"
                     "cb glow gp 0 0 4 1 1 1 0\n"
                     "void mixfunc m 4 cw gp 0.4 . 0 0\nm brightfunc dim 2 0.5 . 0 0\n" +
                     floor("dim")),
             scale(0.5, mix(0.4, kCa, kCb)));
  // A mixture of patterns as a side of a mixture of materials.
  expect_rgb(render1("void mixfunc pm 4 ca cb 0.5 . 0 0\npm glow g 0 0 4 1 1 1 0\n"
                     "void mixfunc m 4 g ga 0.5 . 0 0\n" +
                     floor("m")),
             mix(0.5, inner, kGa));
}

// Light, illum and dielectric sides; the reported material is the void mixture.
TEST_F(Mixtures, MoreSideMaterials) {
  expect_rgb(render1("void light lt 0 0 3 5 6 7\nvoid mixfunc m 4 lt ga 0.5 . 0 0\n" + floor("m")),
             mix(0.5, {5, 6, 7}, kGa));
  // illum without an alternate lets its share through, as Radiance's passed illum.
  expect_rgb(render1("void illum il 0 0 3 5 5 5\nvoid mixfunc m 4 il gc 0.5 . 0 0\n" + screen("m") +
                     floor("gd")),
             mix(0.5, kGd, kGc));
  Rgb diel = render1("void dielectric d 0 0 5 1 1 1 1.5 0\n" + screen("d") + floor("gd"));
  ASSERT_GT(diel[0], 0.5);
  expect_rgb(render1("void dielectric d 0 0 5 1 1 1 1.5 0\nvoid mixfunc m 4 d gc 0.25 . 0 0\n" +
                     screen("m") + floor("gd")),
             mix(0.25, diel, kGc));
}

// Radiance's messages for what it refuses, and radcl's limits.
TEST_F(Mixtures, Errors) {
  fails("void mixdata m 5 ga gb half mix_ramp.dat mix.cal 0 0\n" + floor("m"), "bad # arguments");
  fails("void mixpict m 6 ga gb redv m.hdr mix.cal Px 0 0\n" + floor("m"), "bad # arguments");
  fails("void mixdata m 6 ga gb one mix_grid.dat mix.cal Px 0 0\n" + floor("m"),
        "mixdata \"m\": too few string arguments");
  fails("void mixdata m 6 ga gb half nosuch.dat mix.cal Px 0 0\n" + floor("m"),
        "cannot find data file \"nosuch.dat\"");
  fails("void mixpict m 7 ga gb redv nosuch.hdr mix.cal Px Py 0 0\n" + floor("m"),
        "cannot find picture file \"nosuch.hdr\"");
  fails("void mixdata m 6 ga nosuch half mix_ramp.dat mix.cal Px 0 0\n" + floor("m"),
        "mixdata \"m\": undefined modifier \"nosuch\"");
  // A mixture of materials (or a material) among a material's own modifiers.
  fails("void mixfunc mm 4 ga gb 0.5 . 0 0\nmm glow g 0 0 4 1 1 1 0\n" + floor("g"),
        "polygon \"floor\": conflicting material \"mm\"");
  fails("ga glow g 0 0 4 1 1 1 0\n" + floor("g"), "polygon \"floor\": conflicting material \"ga\"");
  fails("void brightfunc b 2 0.5 . 0 0\nb mixdata m 6 ga gb half mix_ramp.dat mix.cal Px 0 0\n" +
            floor("m"),
        "mixdata \"m\": inappropriate modifier");
  fails("void mixfunc n1 4 ga gb 0.5 . 0 0\nvoid mixfunc n2 4 n1 gb 0.5 . 0 0\n"
        "void mixfunc n3 4 n2 gb 0.5 . 0 0\nvoid mixfunc n4 4 n3 gb 0.5 . 0 0\n"
        "void mixfunc n5 4 n4 gb 0.5 . 0 0\n" +
            floor("n5"),
        "nested more than 4 deep (radcl's limit)");
  fails("void antimatter am 1 ga 0 0\nvoid mixfunc m 4 am gb 0.5 . 0 0\n" + floor("m"),
        "in a mixture is not supported yet");
}

// -i: a mixture is an irradiance meter whole, even with a clear or void side (raytirrad).
TEST_F(Mixtures, IrradianceMeterAtAMixture) {
  Rgb meter = render("void plastic p 0 0 5 0.5 0.5 0.5 0 0\n" + floor("p"), {{3, 2}}, true)[0];
  ASSERT_GT(meter[0], 0);
  Rgb mixed =
      render("void glass gl 0 0 3 0.9 0.9 0.9\nvoid mixfunc m 4 gl void 0.5 . 0 0\n" + floor("m"),
             {{3, 2}}, true)[0];
  expect_rgb(mixed, meter);
}
