#include "golden_draws.h"
#include "radcl/luminance.h"

#include <array>
#include <cmath>
#include <filesystem>

#include "reference_data.h"
#include "temp_dir.h"
#include "test_env.h"

namespace radcl::test {

namespace {

double lum(const std::array<double, 3>& c) {
  return radcl::bright(c);
}

std::pair<double, double> mean_var(const std::vector<double>& v) {
  double m = 0, q = 0;
  for (double x : v)
    m += x / v.size();
  for (double x : v)
    q += (x - m) * (x - m) / (v.size() - 1);
  return {m, q};
}

} // namespace

double grid_error(const std::vector<std::array<double, 3>>& run, const std::vector<double>& conv) {
  if (run.size() != conv.size()) return INFINITY;
  double e = 0;
  for (std::size_t i = 0; i < conv.size(); ++i)
    e += std::fabs(lum(run[i]) - conv[i]) / conv[i] / conv.size();
  return e;
}

DrawComparison default_grid_draws(const std::string& options, const std::string& octree,
                                  const std::string& grid, const std::string& conv_file,
                                  const std::string& runs, int seeds, int radiance_runs) {
  DrawComparison c;
  std::vector<double> conv;
  for (const auto& v : read_rgb(data("results/" + conv_file)))
    conv.push_back(lum(v));
  std::vector<double> ours, theirs;
  const TempFolder tmp("draws");
  for (int seed = 1; seed <= seeds; ++seed) {
    const std::filesystem::path out = tmp / std::to_string(seed);
    int rc = run_command("cd " + data("scenes") + " && RADCL_SEED=" + std::to_string(seed) + " " +
                             bin_dir() + "/rtrace -h -I " + options + " " + octree + " < " + grid +
                             " > " + out.string(),
                         &c.log);
    if (rc != 0) return c;
    ours.push_back(grid_error(read_rgb(out.string()), conv));
  }
  for (int i = 1; i <= radiance_runs; ++i)
    theirs.push_back(grid_error(
        read_rgb(data("results/radiance_runs/" + runs + "_" + std::to_string(i) + ".txt")), conv));
  auto [mo, vo] = mean_var(ours);
  auto [mt, vt] = mean_var(theirs);
  c.ours = mo;
  c.theirs = mt;
  c.se = std::sqrt(vo / ours.size() + vt / theirs.size());
  c.ok = true;
  return c;
}

BlockStats block_stats(const std::vector<double>& ours, const std::vector<double>& ref, int w,
                       int h, const std::string& se_file, double precision) {
  BlockStats s;
  auto se = read_table(se_file);
  double sa = 0, sb = 0, e2 = 0;
  for (int by = 0; by < h / 8; ++by)
    for (int bx = 0; bx < w / 8; ++bx) {
      double a = 0, b = 0;
      for (int y = by * 8; y < by * 8 + 8; ++y)
        for (int x = bx * 8; x < bx * 8 + 8; ++x) {
          const std::size_t i = std::size_t(y) * w + x;
          a += ours[i];
          b += ref[i];
        }
      sa += a;
      sb += b;
      if (b <= 0) continue;
      ++s.lit;
      if (std::size_t(by) >= se.size() || std::size_t(bx) >= se[by].size() ||
          se[by][bx] >= precision)
        continue;
      e2 += (a - b) * (a - b) / (b * b);
      ++s.blocks;
    }
  s.mean_ratio = sb > 0 ? sa / sb : 0;
  s.rms = s.blocks ? std::sqrt(e2 / s.blocks) : INFINITY;
  return s;
}

} // namespace radcl::test
