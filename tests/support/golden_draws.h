// Comparisons of Monte-Carlo draws with Radiance's, shared by the golden tests of the
// second-wave scenes: the default-settings grid over several seeds against stored Radiance
// runs, and a view's 8x-reduced picture against a mean of Radiance renders.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace radcl::test {

// Mean relative luminance error of the rgb rows in `run` against the luminances `conv`.
double grid_error(const std::vector<std::array<double, 3>>& run, const std::vector<double>& conv);

struct DrawComparison {
  double ours = 0, theirs = 0; // mean errors over the seeds, over Radiance's runs
  double se = 0;               // standard error of their difference (from the spreads)
  bool ok = false;             // every radcl run succeeded
  std::string log;             // the failing run's messages
};

// `rtrace -h -I <options> <octree> < <grid>` in tests/data/scenes with RADCL_SEED 1..seeds,
// each run's error against results/<conv>; Radiance's from results/radiance_runs/<runs>_1..n.
DrawComparison default_grid_draws(const std::string& options, const std::string& octree,
                                  const std::string& grid, const std::string& conv,
                                  const std::string& runs, int seeds, int radiance_runs);

struct BlockStats {
  double mean_ratio = 0; // sum of ours / sum of the reference
  double rms = 0;        // relative RMS over the blocks the reference knows to `precision`
  int blocks = 0, lit = 0;
};

// 8x8 blocks of two luminance pictures (w x h, row-major); se_file holds the reference's
// relative standard error per block (h/8 rows of w/8).
BlockStats block_stats(const std::vector<double>& ours, const std::vector<double>& ref, int w,
                       int h, const std::string& se_file, double precision);

} // namespace radcl::test
