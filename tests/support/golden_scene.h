// Helpers of the golden tests on the second-wave reference scenes (golden_aniso, golden_bsdf,
// golden_prism, golden_medium, golden_mist): mean luminances of repeated renders through the
// library and through rpict, and the checks of a default-settings grid and of a view against
// Radiance's runs.
#pragma once

#include "radcl/luminance.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>
#include <vector>

#include "golden_draws.h"
#include "radcl/device/context.h"
#include "radcl/image/picture.h"
#include "radcl/render/pipeline/renderer.h"
#include "reference_data.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::test::golden {

using Rgb = std::array<double, 3>;

inline double lum(const Rgb& c) {
  return radcl::bright(c);
}

inline std::vector<double> lums(const std::string& file) {
  std::vector<double> out;
  for (const Rgb& c : read_rgb(data(file)))
    out.push_back(lum(c));
  return out;
}

inline double sum(const std::vector<double>& v) {
  double s = 0;
  for (double x : v)
    s += x;
  return s;
}

// Each ray (or sensor) of `rays_file` rendered `reps` times on tests/data/scenes/`octree`; the
// mean luminance of each and, if asked, one repetition's standard deviation (n - 1).
inline std::vector<double> mean_run(const std::string& octree, const std::string& rays_file,
                                    const render::RenderSettings& st, int reps,
                                    std::vector<double>* sd = nullptr) {
  char cwd[4096];
  if (!getcwd(cwd, sizeof cwd) || chdir(data("scenes").c_str()) != 0) return {};
  scene::LoadedScene ls = scene::load_scene({octree});
  render::Renderer r(ls, st, device::default_context());
  std::vector<render::PrimaryRay> rays;
  const auto in = read_rays(data(rays_file));
  for (int k = 0; k < reps; ++k)
    for (const auto& s : in)
      rays.push_back({{s[0], s[1], s[2]}, {s[3], s[4], s[5]}, 0});
  std::vector<render::PrimaryResult> res(rays.size());
  r.render(rays, res);
  if (chdir(cwd) != 0) return {};
  std::vector<double> out(in.size(), 0.0), sq(in.size(), 0.0);
  for (std::size_t i = 0; i < res.size(); ++i) {
    out[i % in.size()] += lum(res[i].value) / reps;
    sq[i % in.size()] += lum(res[i].value) * lum(res[i].value);
  }
  if (sd)
    for (std::size_t i = 0; i < in.size(); ++i)
      sd->push_back(std::sqrt(std::max(0.0, (sq[i] - reps * out[i] * out[i]) / (reps - 1))));
  return out;
}

// The mean luminance picture of `reps` renders `rpict -u+ <options> -o ... <octree>` with
// RADCL_SEED 1..reps, each w x h; empty (and *log set) if a render fails or has another size.
inline std::vector<double> mean_view(const std::string& options, const std::string& octree,
                                     int reps, int w, int h, std::string* log) {
  namespace fs = std::filesystem;
  std::vector<double> ours(std::size_t(w) * h, 0.0);
  const TempFolder tmp("view");
  for (int k = 0; k < reps; ++k) {
    const fs::path out = tmp / (std::to_string(k) + ".hdr");
    int rc =
        run_command("cd " + data("scenes") + " && RADCL_SEED=" + std::to_string(k + 1) + " " +
                        bin_dir() + "/rpict -u+ " + options + " -o " + out.string() + " " + octree,
                    log);
    if (rc != 0) return {};
    image::Picture pic = image::read_picture(out.string());
    if (pic.width != w || pic.height != h) {
      *log = "picture of " + std::to_string(pic.width) + " x " + std::to_string(pic.height);
      return {};
    }
    auto c = pic.colors();
    for (std::size_t i = 0; i < c.size(); ++i)
      ours[i] += lum({c[i][0], c[i][1], c[i][2]}) / reps;
  }
  return ours;
}

// A picture's luminances, or empty if it is not w x h.
inline std::vector<double> picture_luminance(const std::string& file, int w, int h) {
  image::Picture p = image::read_picture(file);
  if (p.width != w || p.height != h) return {};
  std::vector<double> v;
  for (const auto& c : p.colors())
    v.push_back(lum({c[0], c[1], c[2]}));
  return v;
}

// The reference's settings (shared/reference/README.md): camera rays at -ab 0 (-dj 0 -ds 0.02
// -dt 0 -dc 1 -ss 1 -st 0.01), camera rays at -ab 1 -aa 0 -ad 2048 -lw 1e-5, sensors (-I) at
// -ab 1 -aa 0 -ad 4096 -lw 1e-5.
inline render::RenderSettings ab0_settings() {
  render::RenderSettings st;
  st.ab = 0;
  st.dj = 0;
  st.ds = 0.02;
  st.dt = 0;
  st.dc = 1;
  st.ss = 1;
  st.st = 0.01;
  return st;
}
inline render::RenderSettings aa0_settings() {
  render::RenderSettings st;
  st.ab = 1;
  st.aa = 0;
  st.ad = 2048;
  st.lw = 1e-5;
  return st;
}
inline render::RenderSettings grid_ab1_settings() {
  render::RenderSettings st = aa0_settings();
  st.ad = 4096;
  st.irradiance_I = true;
  return st;
}

// Per-ray agreement of camera rays with the mean of Radiance's runs: rays the reference finds
// noiseless (sd 0) within 1e-4, the others within 3 standard deviations times `spread`
// (sqrt(1/our runs + 1/theirs) for the standard error of the difference of the two means).
struct RayAgreement {
  int quiet = 0, quiet_ok = 0, noisy = 0, noisy_ok = 0;
};
inline RayAgreement ray_agreement(const std::vector<double>& ours, const std::vector<double>& ref,
                                  const std::vector<double>& sd, double spread) {
  RayAgreement a;
  for (std::size_t i = 0; i < ref.size() && i < ours.size(); ++i) {
    double d = std::fabs(ours[i] - ref[i]);
    if (sd[i] == 0) {
      ++a.quiet;
      a.quiet_ok += d <= 1e-4 * std::fabs(ref[i]) + 1e-9;
    } else {
      ++a.noisy;
      a.noisy_ok += d <= 3.0 * sd[i] * spread;
    }
  }
  return a;
}

// The median relative error over the rays the reference lights.
inline double median_error(const std::vector<double>& ours, const std::vector<double>& ref) {
  std::vector<double> err;
  for (std::size_t i = 0; i < ref.size() && i < ours.size(); ++i)
    if (ref[i] > 0) err.push_back(std::fabs(ours[i] - ref[i]) / ref[i]);
  if (err.empty()) return 0;
  std::nth_element(err.begin(), err.begin() + err.size() / 2, err.end());
  return err[err.size() / 2];
}

// The default-settings grid's check: radcl's mean error from the converged answer over its seeds
// no farther than that of Radiance's runs, three standard errors of the difference allowed.
inline ::testing::AssertionResult no_farther_than_radiance(const DrawComparison& c) {
  if (!c.ok) return ::testing::AssertionFailure() << c.log;
  std::printf("default grid: mean relative error radcl %.4f, Radiance %.4f (se %.4f)\n", c.ours,
              c.theirs, c.se);
  ::testing::Test::RecordProperty("radcl", std::to_string(c.ours));
  ::testing::Test::RecordProperty("radiance", std::to_string(c.theirs));
  if (c.ours <= c.theirs + 3 * c.se) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "mean relative error radcl " << c.ours << ", Radiance " << c.theirs
         << " (standard error of the difference " << c.se << ")";
}

// rpict's 256 x 192 view (`renders` renders of `rpict <options> <octree>` averaged; the options
// set that size) against the mean of Radiance's renders results/<ref>.hdr, on the 8x8 blocks
// that mean knows to 2% (results/<ref>_se.txt). ok is false, with the reason in log, where a
// render or the reference could not be read.
struct ViewComparison : BlockStats {
  bool ok = false;
  std::string log;
};
inline ViewComparison view_against_radiance(const std::string& options, const std::string& octree,
                                            int renders, const std::string& ref) {
  const int w = 256, h = 192;
  ViewComparison v;
  const std::vector<double> ours = mean_view(options, octree, renders, w, h, &v.log);
  if (ours.empty()) return v;
  const std::vector<double> theirs = picture_luminance(data("results/" + ref + ".hdr"), w, h);
  if (theirs.empty()) {
    v.log = "results/" + ref + ".hdr is not a 256 x 192 picture";
    return v;
  }
  static_cast<BlockStats&>(v) =
      block_stats(ours, theirs, w, h, data("results/" + ref + "_se.txt"), 0.02);
  v.ok = true;
  std::printf("view: mean ratio %.4f, RMS %.4f over %d of %d lit blocks\n", v.mean_ratio, v.rms,
              v.blocks, v.lit);
  return v;
}

} // namespace radcl::test::golden
