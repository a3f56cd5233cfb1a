// BSDF and aBSDF on the reference scene `bsdf` (a room lit by sun and sky through five windows
// of XML BSDFs: a Klems venetian blind with thickness 0, the same as a 6 cm proxy of modelled
// slats, as aBSDF; a tensor-tree diffusing film as BSDF and as aBSDF; an opaque glossy
// tensor-tree floor tile), against Radiance 5.4a's stored outputs (tests/data/README.md), and
// energy in a closed box of BSDF walls.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

#include "files.h"
#include "golden_draws.h"
#include "golden_scene.h"
#include "radcl/render/pipeline/renderer.h"
#include "reference_data.h"
#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

using namespace radcl;
using namespace radcl::test::golden;

namespace {

// The mean luminance of each ray over Radiance's stored runs results/radiance_runs/<stem>_k.
std::vector<double> radiance_mean(const std::string& stem, int runs) {
  std::vector<double> mean;
  for (int k = 1; k <= runs; ++k) {
    auto v = lums("results/radiance_runs/" + stem + "_" + std::to_string(k) + ".txt");
    if (mean.empty()) mean.assign(v.size(), 0.0);
    for (std::size_t i = 0; i < v.size() && i < mean.size(); ++i)
      mean[i] += v[i] / runs;
  }
  return mean;
}

// rtrace's output for `rays` on a scene written to a temporary folder (files: name, text; "@DIR@"
// in a text stands for that folder), run in tests/data/scenes, where the XML files are: RAYPATH
// is left as the caller has it (radcl's own library, or Radiance's, must stay on it).
std::string run_scene(std::vector<std::pair<std::string, std::string>> files,
                      const std::string& options, const std::string& rays, int* rc) {
  const test::TempFolder dir("bsdf");
  for (auto& [name, text] : files) {
    for (std::size_t at; (at = text.find("@DIR@")) != std::string::npos;)
      text.replace(at, 5, dir.str());
    test::write_file(dir / name, text);
  }
  const test::ProgramRun r = test::Program("rtrace").input(rays).merge_err().run(
      "-h " + options + " " + (dir / "scene.rad").string());
  *rc = r.rc;
  return r.out;
}

} // namespace

// -ab 0: rays the reference finds noiseless agree to 1e-4 (all 149: direct light through and
// off the BSDFs is deterministic at -dj 0, as is the blinds' and the tile's look); on the 43
// noisy ones (specular samples of the windows) radcl's mean of 8 lies within 3 standard
// deviations of Radiance's mean of 8 for 90%, and the whole image's light within 2%. Through the
// aBSDF film a sample leaves the through peak about one time in six in both programs, and
// adds half the sky's radiance when it does: 8 runs see that rarely, so those rays are the
// misses.
TEST(GoldenBsdf, CameraRaysAb0) {
  auto ours = mean_run("bsdf.oct", "scenes/bsdf_rays.txt", ab0_settings(), 8);
  auto ref = lums("results/bsdf_rays_ab0.txt");
  auto sd = lums("results/bsdf_rays_ab0_sd.txt");
  ASSERT_EQ(ours.size(), ref.size());
  RayAgreement a = ray_agreement(ours, ref, sd, std::sqrt(1.0 / 8 + 1.0 / 8));
  EXPECT_GE(a.quiet_ok, a.quiet - 2) << a.quiet << " noiseless rays";
  EXPECT_GE(a.noisy_ok, 0.9 * a.noisy) << a.noisy << " noisy rays";
  EXPECT_NEAR(sum(ours), sum(ref), 0.02 * sum(ref));
}

// -ab 1 -aa 0 -ad 2048 on the camera rays against the mean of 8 Radiance runs: the total within
// 3%, the median ray within 4%. Radiance's own runs scatter that much: two means of 4 of them
// differ by 3.4% at the median ray (a hemisphere sample from the tile that meets a film window
// where it looks at the sun brings 15,000 times the sky's radiance, one run in four).
TEST(GoldenBsdf, CameraRaysAa0) {
  render::RenderSettings st = aa0_settings();
  auto ours = mean_run("bsdf.oct", "scenes/bsdf_rays.txt", st, 4);
  auto ref = radiance_mean("bsdf_aa0", 8);
  ASSERT_EQ(ours.size(), ref.size());
  EXPECT_LE(median_error(ours, ref), 0.04);
  EXPECT_NEAR(sum(ours), sum(ref), 0.03 * sum(ref));
}

// The sensors (16 on the work plane, 5 facing the windows) at -ab 1 -aa 0 -ad 4096 against the
// mean of 4 Radiance runs: mean relative error within 3%, 90% within 3 standard deviations.
TEST(GoldenBsdf, GridAb1) {
  render::RenderSettings st = grid_ab1_settings();
  auto ours = mean_run("bsdf.oct", "scenes/bsdf_grid.pts", st, 4);
  auto ref = lums("results/bsdf_grid_ab1.txt");
  auto sd = lums("results/bsdf_grid_ab1_sd.txt");
  ASSERT_EQ(ours.size(), ref.size());
  double err = 0;
  int within = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    err += std::fabs(ours[i] - ref[i]) / ref[i];
    within += std::fabs(ours[i] - ref[i]) <= 3.0 * sd[i] * std::sqrt(1.0 / 4 + 1.0 / 4);
  }
  EXPECT_LE(err / ref.size(), 0.03);
  EXPECT_GE(within, 0.9 * ref.size());
}

// The default settings with the irradiance cache: no farther from the converged answer
// (Radiance's mean of 90 -ab 5 -aa 0 runs, standard error 0.75% on average) than Radiance's
// own default runs are (12 stored, 1.1-2.0% mean error): radcl's mean error over six seeds against
// theirs, with three standard errors of the difference as the comparison's noise.
TEST(GoldenBsdf, GridDefaultNoFartherThanRadiance) {
  auto c = test::default_grid_draws("-ab 5 -ad 1024 -as 256 -ar 256 -aa 0.15 -lw 1e-3", "bsdf.oct",
                                    "bsdf_grid.pts", "bsdf_grid_mc5.txt", "bsdf_default", 6, 12);
  EXPECT_TRUE(no_farther_than_radiance(c));
}

// The view (rpict -ab 1 with the cache) against the mean of 48 Radiance renders: the whole
// within 5%, and the 8x8 blocks that mean knows to 2% within 5% RMS. Those are 77% of the lit
// blocks: the windows' specular samples and the patches they light scatter so much from render
// to render that 48 renders leave the rest less certain.
TEST(GoldenBsdf, ViewMeanAndReducedPicture) {
  auto st =
      view_against_radiance("-vf bsdf.vf -x 256 -y 192 -ab 1 -ad 1024 -as 256 -aa 0.1 -ar 64 -ps 1",
                            "bsdf.oct", 4, "bsdf_view_u48");
  ASSERT_TRUE(st.ok) << st.log;
  EXPECT_NEAR(st.mean_ratio, 1.0, 0.05);
  EXPECT_GE(st.blocks, 0.75 * st.lit);
  EXPECT_LE(st.rms, 0.05);
}

// Energy: a closed 1 m box of BSDF walls (reflection plus transmission at most 1) inside a
// bubble of uniform glow L = 1, looked at from inside after 8 bounces. Light that comes in
// through the walls and bounces between them can only approach L (R + T = 1) and never pass
// it: every ray's value stays at most 1, for a Klems file and a tensor tree (0.72 to 0.92 here,
// as Radiance gives on the same box). aBSDF is the exception Radiance shares: its through
// component, estimated from 29 directions about the peak, and the samples it excludes near it
// do not add up exactly, and rays along the peak come back 2% above L (Radiance 5.4a: 1.024).
TEST(GoldenBsdf, ClosedBoxNeverAmplifies) {
  const std::string rays = "0.5 0.5 0.5 1 0.2 0.1\n0.5 0.5 0.5 -0.3 1 0.2\n0.5 0.5 0.5 0.1 "
                           "-0.2 1\n0.5 0.5 0.5 0.2 0.1 -1\n0.5 0.5 0.5 -1 -0.3 0.2\n";
  for (const char* mat : {"void BSDF w\n6 0 blinds_klems.xml 1 .5 .3 .\n0\n0\n",
                          "void BSDF w\n6 0 film_t3.xml 1 .5 .3 .\n0\n0\n",
                          "void aBSDF w\n5 film_t3.xml 1 .5 .3 .\n0\n0\n"}) {
    std::string scene = std::string("void glow g\n0\n0\n4 1 1 1 0\ng bubble b\n0\n0\n4 .5 .5 .5 "
                                    "20\n") +
                        mat;
    // The box's six faces.
    const char* faces[] = {"0 0 0 0 1 0 1 1 0 1 0 0", "0 0 1 1 0 1 1 1 1 0 1 1",
                           "0 0 0 1 0 0 1 0 1 0 0 1", "0 1 0 0 1 1 1 1 1 1 1 0",
                           "0 0 0 0 0 1 0 1 1 0 1 0", "1 0 0 1 1 0 1 1 1 1 0 1"};
    for (int k = 0; k < 6; ++k)
      scene += "w polygon f" + std::to_string(k) + "\n0\n0\n12 " + faces[k] + "\n";
    int rc = 0;
    std::string out = run_scene({{"scene.rad", scene}}, "-ab 8 -aa 0 -ad 512 -lw 1e-6", rays, &rc);
    ASSERT_EQ(rc, 0) << out;
    std::istringstream in(out);
    double r, g, b, most = 0;
    int n = 0;
    while (in >> r >> g >> b) {
      most = std::max({most, r, g, b});
      EXPECT_GT(r + g + b, 0.0) << mat;
      ++n;
    }
    EXPECT_EQ(n, 5) << mat;
    EXPECT_LE(most, std::string(mat).find("aBSDF") != std::string::npos ? 1.03 : 1.001) << mat;
  }
}

// Radiance's refusals, as fatal errors naming the file or the material.
TEST(GoldenBsdf, BadArgumentsAreFatal) {
  auto fails = [](const std::string& mat, const std::string& what) {
    int rc = 0;
    std::string out =
        run_scene({{"scene.rad", mat + "\nm polygon p\n0\n0\n12 0 0 0 1 0 0 1 1 0 0 1 0\n"},
                   {"bad.xml", "<"}},
                  "", "0.5 0.5 1 0 0 -1\n", &rc);
    EXPECT_NE(rc, 0) << mat;
    EXPECT_NE(out.find(what), std::string::npos) << out;
    EXPECT_EQ(out.find("internal error"), std::string::npos) << out;
  };
  fails("void BSDF m\n6 0 nowhere.xml 0 0 1 .\n0\n0", "nowhere.xml");
  fails("void BSDF m\n6 0 @DIR@/bad.xml 0 0 1 .\n0\n0", "bad.xml");
  fails("void BSDF m\n5 0 film_t3.xml 0 0 1\n0\n0", "\"m\"");
  fails("void aBSDF m\n5 film_t3.xml 0 0 1 .\n0\n2 .1 .1", "\"m\"");
  fails("void aBSDF m\n5 film_t3.xml 0 0 1 nowhere.cal\n0\n0", "nowhere.cal");
}
