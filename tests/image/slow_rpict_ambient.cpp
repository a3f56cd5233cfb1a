// rpict with indirect light (-aa 0 until the irradiance cache exists) against Radiance's
// pictures: mean luminance within 5%; and the picture paths end to end (other formats, -z,
// recover). Without a cache every bounce's rays carry their real weight, so -lw 1e-3 (rpict's
// default) would end the third bounce that Radiance's cached run keeps: these runs use
// -lw 1e-4. The mean over the picture needs no more than 64 x 64 pixels (the Cornell runs at
// 128 x 128 and 96 x 96 were a fifth of the suite's time on two cores). -as 0: super-sampling
// only moves noise around (tests/render/pipeline/ambient_supersampling.cpp checks it) and would
// double these runs.
#include "radcl/luminance.h"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

#include "radcl/ambient/ambient_file.h"
#include "radcl/image/depth.h"
#include "radcl/image/image_io.h"
#include "radcl/image/picture.h"
#include "temp_dir.h"
#include "test_env.h"

using radcl::test::run_command;
namespace fs = std::filesystem;

namespace {

fs::path temp(const std::string& name) {
  static const radcl::test::TempFolder dir("rpict_ambient"); // removed at exit
  return dir / name;
}

void rpict(const std::string& args, const std::string& octree) {
  std::string log;
  int rc = run_command("cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                           "/rpict " + args + " " + octree,
                       &log);
  ASSERT_EQ(rc, 0) << log;
}

double mean_luminance(const std::vector<radcl::image::Color>& c) {
  double s = 0;
  for (const auto& p : c)
    s += radcl::bright(p);
  return s / c.size();
}

double mean_luminance(const std::string& path) {
  return mean_luminance(radcl::image::read_picture(path).colors());
}

} // namespace

TEST(SlowRpictAmbient, CornellMeanLuminance) {
  fs::path out = temp("cornell.hdr");
  fs::remove(out);
  rpict("-as 0 -vf cornell.vf -x 64 -y 64 -ab 3 -aa 0 -ad 512 -lw 1e-4 -ps 2 -pt 0.05 -o " +
            out.string(),
        "cornell.oct");
  double ours = mean_luminance(out.string());
  double ref = mean_luminance(radcl::test::data("results/cornell_view.hdr"));
  EXPECT_NEAR(ours, ref, 0.05 * ref) << "vs Radiance -ab 3: " << ours << " / " << ref;
  fs::remove(out);
}

// cornell_high is Radiance near convergence (-ab 5 -ad 2048 -lw 1e-4): the same bounces here.
TEST(SlowRpictAmbient, CornellHighMeanLuminance) {
  fs::path out = temp("cornell_high.hdr");
  fs::remove(out);
  rpict("-as 0 -vf cornell.vf -x 64 -y 64 -ab 5 -aa 0 -ad 1024 -lw 1e-4 -ps 2 -pt 0.05 -o " +
            out.string(),
        "cornell.oct");
  double ours = mean_luminance(out.string());
  double high = mean_luminance(radcl::test::data("results/cornell_high.hdr"));
  EXPECT_NEAR(ours, high, 0.05 * high) << "vs Radiance near-converged: " << ours << " / " << high;
  fs::remove(out);
}

TEST(SlowRpictAmbient, LuminairesMeanLuminance) {
  fs::path out = temp("luminaires.hdr");
  fs::remove(out);
  rpict("-as 0 -vf luminaires.vf -x 120 -y 83 -ab 2 -aa 0 -ad 512 -lw 1e-4 -o " + out.string(),
        "luminaires.oct");
  double ours = mean_luminance(out.string());
  double ref = mean_luminance(radcl::test::data("results/luminaires_view.hdr"));
  EXPECT_NEAR(ours, ref, 0.05 * ref) << ours << " / " << ref;
  fs::remove(out);
}

// The same render as .hdr, .exr (with Z from -z), .tif and .png.
TEST(SlowRpictAmbient, OtherFormatsAndDepth) {
  const std::string view = "-vf cornell.vf -x 64 -y 64 -ab 0 -ps 1 -pj 0 ";
  fs::path hdr = temp("f.hdr"), exr = temp("f.exr"), tif = temp("f.tif"), png = temp("f.png"),
           z = temp("f.z"), z2 = temp("f2.z");
  for (const fs::path& p : {hdr, exr, tif, png, z, z2})
    fs::remove(p);
  rpict(view + "-o " + hdr.string() + " -z " + z.string(), "cornell.oct");
  rpict(view + "-o " + exr.string() + " -z " + z2.string(), "cornell.oct");
  rpict(view + "-o " + tif.string(), "cornell.oct");
  rpict(view + "-o " + png.string(), "cornell.oct");
  radcl::image::Picture pic = radcl::image::read_picture(hdr.string());
  radcl::image::FloatImage e = radcl::image::read_image(exr.string());
  ASSERT_EQ(e.width, 64);
  ASSERT_EQ(e.height, 64);
  std::vector<radcl::image::Color> c = pic.colors();
  for (std::size_t i = 0; i < c.size(); ++i) {
    // RGBE shares one exponent: each channel is exact to 1/256 of the pixel's largest.
    float big = std::max({c[i][0], c[i][1], c[i][2]});
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(e.rgb[i][k], c[i][k], 0.01 * big + 1e-6) << "pixel " << i;
  }
  std::vector<float> depth = radcl::image::read_depth(z.string(), 64, 64);
  ASSERT_EQ(e.depth.size(), depth.size());
  for (std::size_t i = 0; i < depth.size(); ++i)
    EXPECT_FLOAT_EQ(e.depth[i], depth[i]);
  EXPECT_GT(depth[64 * 32 + 32], 0.5f); // the back wall is about 1 m away
  for (const fs::path& p : {tif, png}) {
    radcl::image::FloatImage im = radcl::image::read_image(p.string());
    EXPECT_EQ(im.width, 64) << p;
    EXPECT_EQ(im.height, 64) << p;
  }
  // Never overwrite an existing picture.
  std::string log;
  EXPECT_EQ(run_command("cd " + radcl::test::data("scenes") + " && " + radcl::test::bin_dir() +
                            "/rpict " + view + "-o " + hdr.string() + " cornell.oct",
                        &log),
            1);
  EXPECT_NE(log.find("cannot open output file"), std::string::npos) << log;
  for (const fs::path& p : {hdr, exr, tif, png, z, z2})
    fs::remove(p);
}

// -r: a picture cut off after 20 complete scanlines is finished to the same bytes a full render
// gives (-pj 0 -ps 1: every pixel traced at its centre, nothing depends on neighbours).
TEST(SlowRpictAmbient, RecoverFinishesAnInterruptedPicture) {
  const std::string view = "-vf cornell.vf -x 64 -y 64 -ab 0 -ps 1 -pj 0 ";
  fs::path full = temp("full.hdr"), cut = temp("cut.hdr"), done = temp("done.hdr");
  for (const fs::path& p : {full, cut, done})
    fs::remove(p);
  rpict(view + "-o " + full.string(), "cornell.oct");
  radcl::image::Picture p = radcl::image::read_picture(full.string());
  {
    radcl::image::PictureHeader h = p.header;
    std::ofstream out(cut, std::ios::binary);
    radcl::image::PictureWriter w(out, h, radcl::image::Resolution::standard(64, 64));
    for (int y = 0; y < 20; ++y)
      w.write_scanline(std::span<const radcl::image::Rgbe>(p.pixels.data() + y * 64, 64));
    w.flush();
    out << "garbage of a killed run";
  }
  rpict(view + "-r " + cut.string() + " -o " + done.string(), "cornell.oct");
  radcl::image::Picture q = radcl::image::read_picture(done.string());
  ASSERT_EQ(q.pixels.size(), p.pixels.size());
  int differ = 0;
  for (std::size_t i = 0; i < p.pixels.size(); ++i)
    differ += p.pixels[i] != q.pixels[i];
  EXPECT_EQ(differ, 0);
  EXPECT_FALSE(fs::exists(cut)) << "the recover file is removed on success";
  for (const fs::path& f : {full, cut, done})
    fs::remove(f);
}

// Scenes with patterns (issue 6): the sky is skybright.cal through the kernels.
TEST(SlowRpictAmbient, OfficeViewMeanLuminance) {
  fs::path out = temp("office.hdr");
  fs::remove(out);
  rpict("-as 0 -vf office.vf -x 64 -y 64 -ab 2 -aa 0 -ad 256 -lw 1e-4 -ps 1 -o " + out.string(),
        "office_clear.oct");
  double ours = mean_luminance(out.string());
  double ref = mean_luminance(radcl::test::data("results/office_view.hdr"));
  EXPECT_NEAR(ours, ref, 0.05 * ref) << "vs Radiance -ab 2: " << ours << " / " << ref;
  fs::remove(out);
}

TEST(SlowRpictAmbient, MaterialsViewMeanLuminance) {
  fs::path out = temp("materials.hdr");
  fs::remove(out);
  rpict("-as 0 -vf materials.vf -x 96 -y 64 -ab 2 -aa 0 -ad 256 -lw 1e-4 -ps 1 -o " + out.string(),
        "materials.oct");
  double ours = mean_luminance(out.string());
  double ref = mean_luminance(radcl::test::data("results/materials_view.hdr"));
  EXPECT_NEAR(ours, ref, 0.05 * ref) << "vs Radiance -ab 2: " << ours << " / " << ref;
  fs::remove(out);
}

// Radiance's own office_view options (-ab 2 -aa 0.15 -ar 128, cache built as it renders) at
// 128 x 128: mean luminance within 5% of Radiance's picture, with the overture (the view at an
// eighth of the resolution rendered first, only for its records) and without it; the -af file
// loads with records on both levels.
TEST(SlowRpictAmbient, OfficeViewCacheWithAndWithoutOverture) {
  double ref = mean_luminance(radcl::test::data("results/office_view.hdr"));
  for (const char* overture : {"1", "0"}) {
    fs::path out = temp("office-cache.hdr"), amb = temp("office-cache.amb");
    fs::remove(out);
    fs::remove(amb);
    std::string log;
    int rc = run_command("cd " + radcl::test::data("scenes") + " && RADCL_OVERTURE=" + overture +
                             " " + radcl::test::bin_dir() +
                             "/rpict -vf office.vf -x 128 -y 128 -ab 2 -ad 1024 -as 256 -aa 0.15 "
                             "-ar 128 -af " +
                             amb.string() + " -o " + out.string() + " office_clear.oct",
                         &log);
    ASSERT_EQ(rc, 0) << log;
    double ours = mean_luminance(out.string());
    EXPECT_NEAR(ours, ref, 0.05 * ref) << "overture " << overture << ": " << ours << " / " << ref;
    radcl::ambient::AmbientFile f;
    auto recs = f.open(amb.string(), {});
    f.close();
    int lvl[2] = {0, 0};
    for (const auto& a : recs)
      if (a.lvl >= 0 && a.lvl < 2) ++lvl[a.lvl];
    EXPECT_GT(lvl[0], 100) << "overture " << overture;
    EXPECT_GT(lvl[1], 100) << "overture " << overture;
    fs::remove(out);
    fs::remove(amb);
  }
}
