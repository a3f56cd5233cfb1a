// The study's arithmetic: errors, their summary, the Pareto front and the fastest run within
// a target.
#include <gtest/gtest.h>

#include <cmath>

#include "radcl/cost/score.h"
#include "radcl/util/error.h"

using namespace radcl;
using namespace radcl::cost;

TEST(Score, RelativeLuminanceErrors) {
  const std::vector<Rgb> ref{{1, 1, 1}, {2, 2, 2}, {0, 0, 0}};
  const std::vector<Rgb> v{{1.1, 1.1, 1.1}, {1, 1, 1}, {5, 5, 5}};
  const std::vector<double> e = relative_errors(v, ref);
  ASSERT_EQ(e.size(), 2u); // the black reference sensor is left out
  EXPECT_NEAR(e[0], 0.1, 1e-12);
  EXPECT_NEAR(e[1], 0.5, 1e-12);
  EXPECT_THROW(relative_errors(std::vector<Rgb>(2), ref), FatalError);
}

TEST(Score, SummaryByNearestRank) {
  std::vector<double> e;
  for (int i = 1; i <= 100; ++i)
    e.push_back(i / 100.0);
  const Score s = summarise(e);
  EXPECT_EQ(s.counted, 100u);
  EXPECT_NEAR(s.mean, 0.505, 1e-12);
  EXPECT_DOUBLE_EQ(s.p95, 0.95);
  EXPECT_DOUBLE_EQ(s.worst, 1.0);
  EXPECT_NEAR(s.rms, std::sqrt(338350.0 / 1e4 / 100), 1e-12);
  // 20 values: the 19th smallest.
  std::vector<double> f(20);
  for (int i = 0; i < 20; ++i)
    f[i] = 20 - i;
  EXPECT_DOUBLE_EQ(summarise(f).p95, 19);
  EXPECT_EQ(summarise({}).counted, 0u);
}

TEST(Score, Metrics) {
  Score s{0.01, 0.02, 0.03, 0.04, 5};
  EXPECT_EQ(pick(s, parse_metric("mean")), 0.01);
  EXPECT_EQ(pick(s, parse_metric("p95")), 0.02);
  EXPECT_EQ(pick(s, parse_metric("max")), 0.03);
  EXPECT_EQ(pick(s, parse_metric("rms")), 0.04);
  EXPECT_THROW(parse_metric("median"), FatalError);
}

TEST(Score, ParetoFront) {
  const std::vector<double> t{1, 2, 3, 4, 2};
  const std::vector<double> e{0.10, 0.05, 0.06, 0.01, 0.05};
  const std::vector<bool> f = pareto_front(t, e);
  // Run 2 is slower and worse than run 1; runs 1 and 4 tie and stay on the front together.
  EXPECT_EQ(f, (std::vector<bool>{true, true, false, true, true}));
}

TEST(Score, FastestWithinTarget) {
  const std::vector<double> t{5, 1, 3, 2};
  const std::vector<double> e{0.01, 0.05, 0.015, 0.03};
  EXPECT_EQ(fastest_within(t, e, 0.02), std::optional<std::size_t>(2));
  EXPECT_EQ(fastest_within(t, e, 0.05), std::optional<std::size_t>(1));
  EXPECT_FALSE(fastest_within(t, e, 0.001).has_value());
}
