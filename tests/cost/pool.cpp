// Pooling the reference's runs: by paths (sensors, with their own standard errors) and by
// spread (pictures).
#include <gtest/gtest.h>

#include <random>

#include "radcl/cost/pool.h"
#include "radcl/luminance.h"

using namespace radcl::cost;

TEST(PathPool, WeighsByPaths) {
  PathPool p;
  p.add(std::vector<Rgb>{{1, 2, 3}}, std::vector<Rgb>{{0.2, 0.2, 0.2}}, 1000);
  p.add(std::vector<Rgb>{{4, 5, 6}}, std::vector<Rgb>{{0.1, 0.1, 0.1}}, 3000);
  EXPECT_EQ(p.runs(), 2);
  EXPECT_DOUBLE_EQ(p.paths(), 4000);
  EXPECT_NEAR(p.mean()[0][0], (1000 * 1 + 3000 * 4) / 4000.0, 1e-12);
  // sqrt(1000^2 0.2^2 + 3000^2 0.1^2) / 4000
  EXPECT_NEAR(p.std_error()[0][1], std::sqrt(4e4 + 9e4) / 4000, 1e-12);
  // Luminance's relative error: the channels' errors move together.
  EXPECT_NEAR(p.relative_std_error()[0], p.std_error()[0][0] / radcl::bright(p.mean()[0]), 1e-12);
}

TEST(RunPool, ErrorFromTheSpread) {
  // Draws of known spread: the pooled error tracks sigma / sqrt(n).
  std::mt19937 g(5);
  std::normal_distribution<double> d(10, 2);
  RunPool p;
  for (int k = 0; k < 400; ++k) {
    const double x = d(g);
    p.add(std::vector<Rgb>{{x, x, x}});
  }
  EXPECT_NEAR(p.mean()[0][0], 10, 0.3);
  EXPECT_NEAR(p.std_error()[0][0], 2 / std::sqrt(400.0), 0.015);
  RunPool one;
  one.add(std::vector<Rgb>{{1, 1, 1}});
  EXPECT_EQ(one.std_error()[0][0], 0);
}
