// radcl driven the ways Radiance's own tools and users drive rtrace and rpict: the command
// lines `rad` writes for a .rif (an overture run that fills the cache, then the main run at
// twice the resolution, options in an `@file` one per line), camera rays from a view piped into
// `rtrace -ffc -x -y` to make a picture (what `vwrays -ff | rtrace` does), and a makefile that
// finds radcl's programs first on PATH and rebuilds only what changed. Each checks the output
// itself: sizes, headers, pixel values.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "radcl/image/picture.h"
#include "radcl/image/view_ray.h"
#include "radcl/options/view.h"
#include "temp_dir.h"
#include "test_env.h"

namespace fs = std::filesystem;
using radcl::test::bin_dir;
using radcl::test::data;
using radcl::test::run_command;

namespace {

class RadianceWorkflows : public radcl::test::TempDir {
protected:
  // Runs `cmd` in the reference scenes' folder (the octrees name their files from there).
  static int in_scenes(const std::string& cmd, std::string* out = nullptr) {
    return run_command("cd " + data("scenes") + " && " + cmd, out);
  }

  static bool has_line(const radcl::image::Picture& p, const std::string& line) {
    for (const std::string& l : p.header.lines)
      if (l == line) return true;
    return false;
  }
  static std::string header_text(const radcl::image::Picture& p) {
    std::string t;
    for (const std::string& l : p.header.lines)
      t += l + "\n";
    return t;
  }
  static std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> w;
    std::istringstream in(s);
    for (std::string x; in >> x;)
      w.push_back(x);
    return w;
  }
  static double mean_red(const radcl::image::Picture& p) {
    double s = 0;
    for (const auto& c : p.colors())
      s += c[0];
    return s / static_cast<double>(p.pixels.size());
  }
};

} // namespace

// rad's two rpict runs for one view: the overture (64x64, -ps 1, output thrown away) builds
// the irradiance cache the main run (twice the resolution, -ps 8 -pt .08) then reuses; the
// options come from the .rif's option file, one option a line as rad writes it.
TEST_F(RadianceWorkflows, RadOvertureThenMainRun) {
  const std::string amb = (dir / "cornell.amb").string(), opt = (dir / "cornell.opt").string();
  // rad's form: each option on its own line (rad.c's option file), medium detail values.
  const std::string opts = "-dp 512\n-ar 41\n-ms 0.19\n-ds .3\n-dt .1\n-dc .5\n-dr 1\n-ss 1\n"
                           "-st .1\n-ab 1\n-af " +
                           amb +
                           "\n-aa .2\n-ad 256\n-as 128\n-av 0.01 0.01 0.01\n-lr 6\n-lw .002\n";
  std::ofstream(opt) << opts;
  const std::string rpict = bin_dir() + "/rpict";
  std::string out;
  ASSERT_EQ(
      in_scenes(rpict + " -vf cornell.vf @" + opt + " -x 64 -y 64 -ps 1 cornell.oct > /dev/null",
                &out),
      0)
      << out;
  ASSERT_TRUE(fs::exists(amb));
  const auto overture_size = fs::file_size(amb);
  EXPECT_GT(overture_size, 67u * 20) << "the overture wrote few records";
  const std::string pic = (dir / "cornell.unf").string();
  ASSERT_EQ(in_scenes(rpict + " -vf cornell.vf -x 128 -y 128 @" + opt +
                          " -ps 8 -pt .08 cornell.oct > " + pic,
                      &out),
            0)
      << out;

  // Read back as pfilt reads it: the size, the header's command line (words expanded, the
  // program named as Radiance names it), the view, the format.
  radcl::image::Picture p = radcl::image::read_picture(pic);
  EXPECT_EQ(p.width, 128);
  EXPECT_EQ(p.height, 128);
  std::string words;
  for (const std::string& w : split(opts))
    words += " " + w;
  EXPECT_TRUE(has_line(p, "rpict -vf cornell.vf -x 128 -y 128" + words + " -ps 8 -pt .08"))
      << header_text(p);
  EXPECT_TRUE(has_line(p, "VIEW= -vtv -vp 0.5 0.02 0.5 -vd 0 1 0 -vu 0 0 1 -vh 70 -vv 70 -vo 0 "
                          "-va 0 -vs 0 -vl 0"))
      << header_text(p);
  EXPECT_TRUE(has_line(p, "FORMAT=32-bit_rle_rgbe")) << header_text(p);

  // The same two runs with the options written out on the command line: the same picture.
  fs::remove(amb);
  std::string inline_opts = words;
  ASSERT_EQ(in_scenes(rpict + " -vf cornell.vf" + inline_opts +
                      " -x 64 -y 64 -ps 1 cornell.oct > /dev/null"),
            0);
  EXPECT_EQ(fs::file_size(amb), overture_size);
  const std::string pic2 = (dir / "cornell2.unf").string();
  ASSERT_EQ(in_scenes(rpict + " -vf cornell.vf -x 128 -y 128" + inline_opts +
                      " -ps 8 -pt .08 cornell.oct > " + pic2),
            0);
  radcl::image::Picture q = radcl::image::read_picture(pic2);
  ASSERT_EQ(q.pixels.size(), p.pixels.size());
  EXPECT_TRUE(q.pixels == p.pixels) << "the option file changed the picture";
  EXPECT_GT(mean_red(p), 0.0);
}

// rad names its raw pictures view.unf, and restarts an interrupted one with -ro: any name that
// is not another format's is a Radiance picture.
TEST_F(RadianceWorkflows, RawPictureNames) {
  const std::string pic = (dir / "cornell_v.unf").string();
  std::string out;
  ASSERT_EQ(
      in_scenes(bin_dir() + "/rpict -vf cornell.vf -x 32 -y 32 -ab 0 -o " + pic + " cornell.oct",
                &out),
      0)
      << out;
  radcl::image::Picture p = radcl::image::read_picture(pic);
  EXPECT_EQ(p.width, 32);
  EXPECT_GT(mean_red(p), 0.0);
}

// vwrays -ff -vf v.vf -x W -y H | rtrace -n 2 @opts -ffc -x W -y H scene.oct > pic.hdr: the
// rays are written here as vwrays writes them (float origin and direction per pixel, top row
// first, through pixel centres); the picture is rpict's with -pj 0 -ps 1.
TEST_F(RadianceWorkflows, ViewRaysIntoRtracePicture) {
  radcl::options::View v;
  ASSERT_GT(radcl::options::read_view_file(data("scenes/cornell.vf"), v, "rpict"), 0);
  ASSERT_EQ(radcl::options::setup_view(v), "");
  int w = 48, h = 48;
  radcl::image::normalize_aspect(radcl::image::view_aspect(v), w, h, 1.0);
  const std::string rays = (dir / "rays.f").string();
  {
    std::ofstream f(rays, std::ios::binary);
    for (int row = h - 1; row >= 0; --row)
      for (int x = 0; x < w; ++x) {
        auto r = radcl::image::view_ray(v, (x + 0.5) / w, (row + 0.5) / h);
        ASSERT_TRUE(r.has_value());
        float rec[6];
        for (int k = 0; k < 3; ++k) {
          rec[k] = static_cast<float>(r->org[k]);
          rec[3 + k] = static_cast<float>(r->dir[k]);
        }
        f.write(reinterpret_cast<const char*>(rec), sizeof rec);
      }
  }
  const std::string opt = (dir / "direct.opt").string();
  // Deterministic light: no jittered source or specular samples to differ between programs.
  std::ofstream(opt) << "-ab 0 -dj 0\n-ds 0 -dt 0 -ss 0\n";
  const std::string xy = " -x " + std::to_string(w) + " -y " + std::to_string(h);
  const std::string pic = (dir / "rtrace.hdr").string(), ref = (dir / "rpict.hdr").string();
  std::string out;
  ASSERT_EQ(in_scenes(bin_dir() + "/rtrace -n 2 @" + opt + " -ffc" + xy + " cornell.oct < " + rays +
                          " > " + pic,
                      &out),
            0)
      << out;
  ASSERT_EQ(in_scenes(bin_dir() + "/rpict -vf cornell.vf -pj 0 -ps 1 @" + opt + xy +
                          " cornell.oct > " + ref,
                      &out),
            0)
      << out;
  radcl::image::Picture p = radcl::image::read_picture(pic);
  radcl::image::Picture q = radcl::image::read_picture(ref);
  EXPECT_EQ(p.width, w);
  EXPECT_EQ(p.height, h);
  EXPECT_TRUE(has_line(p, "rtrace -n 2 -ab 0 -dj 0 -ds 0 -dt 0 -ss 0 -ffc" + xy)) << header_text(p);
  EXPECT_TRUE(has_line(p, "FORMAT=32-bit_rle_rgbe")) << header_text(p);
  ASSERT_EQ(q.pixels.size(), p.pixels.size());
  const auto a = p.colors(), b = q.colors();
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if (std::fabs(a[i][c] - b[i][c]) > 0.01 * std::max(b[i][c], 1e-3f)) ++differ;
  // The rays went through float32 (as vwrays -ff writes them): a pixel centre on an edge may
  // meet the other surface, nothing else differs.
  EXPECT_LT(differ, a.size() * 3 / 100) << "pixel values that differ from rpict's";
  EXPECT_NEAR(mean_red(p), mean_red(q), 0.005 * mean_red(q));
  EXPECT_GT(mean_red(p), 0.0);
}

// A makefile with radcl's programs first on PATH: it makes a picture and a sensor result from
// the example room, and `make` again rebuilds only the target whose input changed.
TEST_F(RadianceWorkflows, MakefileRebuildsOnlyWhatChanged) {
  for (const char* f : {"room.rad", "room.vf"})
    fs::copy_file(radcl::test::source_dir() + "/scenes/" + f, dir / f);
  std::ofstream(dir / "grid.pts") << "1 1 0.8 0 0 1\n2 2 0.8 0 0 1\n2.5 1.5 0.8 0 0 1\n";
  std::ofstream(dir / "Makefile")
      << "all: room.hdr grid.out\n"
         "room.hdr: room.rad room.vf\n"
         "\trpict -vf room.vf -x 48 -y 36 -ab 1 -aa 0 -ad 32 room.rad > room.hdr\n"
         "grid.out: room.rad grid.pts\n"
         "\trtrace -h -I -ab 1 -aa 0 -ad 32 room.rad < grid.pts > grid.out\n";
  const std::string make =
      "cd " + dir.string() + " && PATH=" + fs::absolute(bin_dir()).string() + ":$PATH make";
  std::string out;
  ASSERT_EQ(run_command(make, &out), 0) << out;
  radcl::image::Picture p = radcl::image::read_picture((dir / "room.hdr").string());
  EXPECT_EQ(p.width, 48);
  EXPECT_EQ(p.header.software().rfind("radcl ", 0), 0u) << header_text(p); // radcl's rpict ran
  EXPECT_GT(mean_red(p), 0.0);
  std::ifstream g(dir / "grid.out");
  int n = 0;
  for (double r, gr, b; g >> r >> gr >> b; ++n)
    EXPECT_GT(gr, 0.0);
  EXPECT_EQ(n, 3);

  // Up to date: nothing runs.
  out.clear();
  ASSERT_EQ(run_command(make + " -q", &out), 0) << out;
  const auto pic_time = fs::last_write_time(dir / "room.hdr");
  // New sensors: only grid.out is made again.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  std::ofstream(dir / "grid.pts", std::ios::app) << "1.5 2.5 0.8 0 0 1\n";
  out.clear();
  ASSERT_EQ(run_command(make, &out), 0) << out;
  EXPECT_EQ(out.find("rpict"), std::string::npos) << out;
  EXPECT_NE(out.find("rtrace"), std::string::npos) << out;
  EXPECT_EQ(fs::last_write_time(dir / "room.hdr"), pic_time);
  std::ifstream g2(dir / "grid.out");
  n = 0;
  for (double r, gr, b; g2 >> r >> gr >> b;)
    ++n;
  EXPECT_EQ(n, 4);
}
