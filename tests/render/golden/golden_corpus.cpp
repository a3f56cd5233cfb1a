// The differential corpus (issue 54 point 6), in four shards: 64 small random scenes from
// tests/tools/corpus_gen.py covering every surface type and the material, pattern, texture,
// mixture, source, medium, BSDF, instance and mesh families, rooms 3-60 m deep, skies with and
// without sun and closed rooms. For each, Radiance's 8 independent -aa 0 draws over 12 upward
// sensors are stored (tests/tools/corpus_radiance.sh); radcl's rtrace draws 8 more, and each
// sensor group (6 near the light, 6 far) must agree: Welch's t of the two sets of 8 group
// means within 4.5 (about 1 in 2,000 by chance for each of the 128 groups at 14 degrees of
// freedom; 3.25 at most on 2026-12-07). A difference found is fixed at its cause or listed in
// kKnown with its reason (docs/differences.md).
#include "radcl/luminance.h"
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "files.h"
#include "reference_data.h"
#include "run_program.h"
#include "test_env.h"

using radcl::test::data;

namespace {

constexpr int kSensors = 12, kReps = 8, kGroup = 6;
const char* kOptions = "-ab 1 -aa 0 -ad 512 -lw 1e-4"; // as corpus_radiance.sh's CORPUS_AA0

// Scenes whose difference from Radiance is known and explained (none yet).
const std::map<std::string, std::string> kKnown = {};

struct Scene {
  std::string name, family, extra;
};

std::vector<Scene> index() {
  std::vector<Scene> out;
  std::ifstream in(data("corpus/index.tsv"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    Scene s;
    std::getline(ls, s.name, '\t');
    std::getline(ls, s.family, '\t');
    std::getline(ls, s.extra);
    out.push_back(s);
  }
  return out;
}

double lum(const std::vector<double>& row) {
  return radcl::bright(row);
}

// Group means of each draw: out[g][k] for group g (0 near, 1 far) and draw k.
std::vector<std::vector<double>> group_means(const std::vector<std::vector<double>>& rows) {
  std::vector<std::vector<double>> g(2, std::vector<double>(kReps, 0.0));
  for (int k = 0; k < kReps; ++k)
    for (int i = 0; i < kSensors; ++i)
      g[i / kGroup][k] += lum(rows[k * kSensors + i]) / kGroup;
  return g;
}

void mean_var(const std::vector<double>& v, double* m, double* var) {
  *m = 0;
  for (double x : v)
    *m += x / v.size();
  *var = 0;
  for (double x : v)
    *var += (x - *m) * (x - *m) / (v.size() - 1);
}

// radcl's 8 draws of the scene's sensors, or empty with *log set.
std::vector<std::vector<double>> radcl_draws(const Scene& s, std::string* log) {
  const std::string pts = radcl::test::read_file(data("corpus/" + s.name + ".pts"));
  std::string input;
  for (int k = 0; k < kReps; ++k)
    input += pts;
  const radcl::test::ProgramRun run =
      radcl::test::Program("rtrace")
          .in(data("corpus"))
          .env("RADCL_SEED=54 ")
          .input(input)
          .run(std::string("-h -I -u+ ") + kOptions + " " + s.extra + " " + s.name + ".rad");
  const int rc = run.rc;
  const std::string& out = run.out;
  std::vector<std::vector<double>> rows;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<double> r(3);
    if (ls >> r[0] >> r[1] >> r[2]) rows.push_back(r);
  }
  if (rc != 0 || rows.size() != std::size_t(kReps) * kSensors) {
    *log = "rtrace exit " + std::to_string(rc) + ", " + std::to_string(rows.size()) + " values";
    return {};
  }
  return rows;
}

// The scenes whose number is `shard` modulo 4 (every variant of a family falls in one shard,
// so each compiles one program), so that ctest can run the shards side by side.
void check_shard(int shard) {
  const std::vector<Scene> scenes = index();
  ASSERT_GE(scenes.size(), 60u);
  int groups = 0;
  std::vector<std::string> failures;
  for (std::size_t i = shard; i < scenes.size(); i += 4) {
    const Scene& s = scenes[i];
    const auto ref = radcl::test::read_table(data("corpus/results/" + s.name + "_aa0.txt"));
    ASSERT_EQ(ref.size(), std::size_t(kReps) * kSensors) << s.name;
    std::string log;
    const auto ours = radcl_draws(s, &log);
    if (ours.empty()) {
      failures.push_back(s.name + " (" + s.family + "): " + log);
      continue;
    }
    const auto gr = group_means(ref), gc = group_means(ours);
    for (int g = 0; g < 2; ++g, ++groups) {
      double mr, vr, mc, vc;
      mean_var(gr[g], &mr, &vr);
      mean_var(gc[g], &mc, &vc);
      const double se = std::sqrt(vr / kReps + vc / kReps);
      // Noiseless groups (direct light only, all draws alike) must agree to float rounding.
      const double t = se > 1e-6 * std::max(std::fabs(mr), 1e-12)
                           ? (mc - mr) / se
                           : (std::fabs(mc - mr) <= 1e-4 * std::fabs(mr) + 1e-9 ? 0.0 : 1e9);
      if (std::fabs(t) > 4.5 && !kKnown.count(s.name)) {
        char buf[256];
        std::snprintf(buf, sizeof buf, "%s (%s) group %s: radcl %.6g, Radiance %.6g, t = %.2f",
                      s.name.c_str(), s.family.c_str(), g ? "far" : "near", mc, mr, t);
        failures.push_back(buf);
      }
    }
  }
  EXPECT_GE(groups, 30);
  std::string all;
  for (const auto& f : failures)
    all += "\n  " + f;
  EXPECT_TRUE(failures.empty()) << failures.size() << " groups differ:" << all;
}

} // namespace

TEST(GoldenCorpus, Shard0) {
  check_shard(0);
}
TEST(GoldenCorpus, Shard1) {
  check_shard(1);
}
TEST(GoldenCorpus, Shard2) {
  check_shard(2);
}
TEST(GoldenCorpus, Shard3) {
  check_shard(3);
}
