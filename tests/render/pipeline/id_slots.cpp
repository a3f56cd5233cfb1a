// IdSlots finds each id's slot, for compact ranges (flat table) and scattered ids (hash map),
// and reports an id that is not in the batch.
#include <gtest/gtest.h>
#include <vector>

#include "radcl/render/pipeline/id_slots.h"

using radcl::render::IdSlots;

TEST(IdSlots, CompactAndScatteredIds) {
  for (std::uint32_t step : {1u, 3u, 100000u}) { // flat table, flat with holes, hash map
    std::vector<std::uint32_t> ids;
    for (std::uint32_t k = 0; k < 5000; ++k)
      ids.push_back(7 + static_cast<std::uint32_t>(std::uint64_t{k} * 761 % 5000) *
                            step); // a permutation
    IdSlots s;
    s.assign(ids);
    EXPECT_FALSE(s.empty());
    for (std::size_t k = 0; k < ids.size(); ++k)
      ASSERT_EQ(s.at(ids[k]), k) << "step " << step;
    EXPECT_THROW(s.at(6), radcl::FatalError);
    EXPECT_THROW(s.at(7 + 5000 * step), radcl::FatalError);
    if (step == 3) EXPECT_THROW(s.at(8), radcl::FatalError); // a hole in the range
  }
  IdSlots s;
  s.assign({});
  EXPECT_TRUE(s.empty());
}
