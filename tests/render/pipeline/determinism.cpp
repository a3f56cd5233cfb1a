// The same inputs and seed give bit-identical results whatever the wave size or the number of
// host threads (random numbers are keyed by ray, sample, depth and seed; outputs go to fixed
// offsets; sums run in a fixed order).
#include <cstring>
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include "radcl/device/context.h"
#include "radcl/render/pipeline/renderer.h"
#include "reference_data.h"
#include "test_env.h"

using namespace radcl;

namespace {

std::vector<render::PrimaryResult> run(std::size_t wave, int threads, std::uint32_t seed,
                                       const render::PipelineTuning& tuning = {}) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  std::string dir = test::data("scenes");
  char cwd[4096];
  EXPECT_NE(getcwd(cwd, sizeof cwd), nullptr);
  EXPECT_EQ(chdir(dir.c_str()), 0);
  scene::LoadedScene ls = scene::load_scene({"luminaires.oct"});
  render::RenderSettings st;
  st.ab = 1;
  st.ad = 64;
  st.dj = 0.7; // jittered source samples use random numbers too
  st.irradiance_I = true;
  st.seed = seed;
  st.wave_size = wave;
  st.tuning = tuning;
  render::Renderer r(ls, st, device::default_context());
  std::vector<render::PrimaryRay> rays;
  for (const auto& s : test::read_rays(test::data("scenes/luminaires_grid.pts")))
    rays.push_back({{s[0], s[1], s[2]}, {s[3], s[4], s[5]}, 0});
  std::vector<render::PrimaryResult> res(rays.size());
  r.render(rays, res);
  EXPECT_EQ(chdir(cwd), 0);
  return res;
}

bool identical(const std::vector<render::PrimaryResult>& a,
               const std::vector<render::PrimaryResult>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(a[i].value.data(), b[i].value.data(), sizeof a[i].value) != 0) return false;
  return true;
}

} // namespace

TEST(Determinism, SameAcrossWaveSizesAndThreads) {
  auto base = run(1 << 18, 2, 42);
  EXPECT_TRUE(identical(base, run(1 << 18, 2, 42))) << "repeat run";
  EXPECT_TRUE(identical(base, run(7, 2, 42))) << "wave of 7 primaries";
  EXPECT_TRUE(identical(base, run(1 << 18, 1, 42))) << "one host thread";
}

// Waves whose shadow and child rays exceed the device's allocation limit are shaded in slices;
// a tiny limit (tuning.slice_bytes) slices every wave and must not change a bit.
TEST(Determinism, SameWhenWavesAreSliced) {
  auto base = run(1 << 18, 2, 42);
  render::PipelineTuning tiny;
  tiny.slice_bytes = 4096;
  auto sliced = run(1 << 18, 2, 42, tiny);
  EXPECT_TRUE(identical(base, sliced));
}

// The chunk size's test (RADCL_CHUNK_RAYS, from 1 ray up) is
// StabilityDeterminism.SameWhateverTheChunkSize: through the programs, so it also checks that
// the variable reaches the pipeline.

TEST(Determinism, SeedChangesTheNoise) {
  auto a = run(1 << 18, 2, 1), b = run(1 << 18, 2, 2);
  EXPECT_FALSE(identical(a, b));
}
