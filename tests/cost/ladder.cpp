// The ladder: its families, in order of rising cost, each run's options complete.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "radcl/cost/ladder.h"
#include "radcl/util/error.h"

using namespace radcl;
using namespace radcl::cost;

TEST(Ladder, FamiliesAndOrder) {
  const std::vector<Step> all = make_ladder(5, parse_families("all"));
  std::map<std::string, int> n;
  for (const Step& s : all)
    ++n[s.family];
  EXPECT_EQ(n["cache"], 4);
  EXPECT_EQ(n["mc"], 4);
  EXPECT_EQ(n["ab"], 4); // -ab 1, 2, 3 and 7
  EXPECT_EQ(n["lw"], 2);
  for (std::size_t i = 1; i < all.size(); ++i) {
    if (all[i].family == all[i - 1].family && all[i].family != "ab" && all[i].family != "lw") {
      EXPECT_GT(all[i].cost_hint, all[i - 1].cost_hint) << all[i].label();
    }
  }
  EXPECT_EQ(all.front().label(), "-ab 5 -aa 0.25 -ad 256 -as 64 -ar 128 -lw 1e-3");
  EXPECT_EQ(make_ladder(2, {"mc"}).back().label(), "-ab 2 -aa 0 -ad 16384 -as 0 -lw 1e-4");
  // Every step sets the same options, so no step inherits another's.
  for (const Step& s : all)
    for (const char* o : {"-ab", "-aa", "-ad", "-as", "-lw"})
      EXPECT_NE(std::find(s.options.begin(), s.options.end(), o), s.options.end()) << s.label();
}

TEST(Ladder, BadInput) {
  EXPECT_THROW(parse_families("cache,fast"), FatalError);
  EXPECT_THROW(parse_families(""), FatalError);
  EXPECT_THROW(make_ladder(0, {"cache"}), FatalError);
  EXPECT_EQ(parse_families("mc,cache,mc"), (std::vector<std::string>{"mc", "cache"}));
}
