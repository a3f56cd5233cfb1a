#include <gtest/gtest.h>

#include "radcl/util/hash.h"

TEST(Hasher, StableAndSensitive) {
  using radcl::Hasher;
  EXPECT_EQ(Hasher().add("abc").hex(), Hasher().add("abc").hex());
  EXPECT_EQ(Hasher().add("abc").hex().size(), 32u);
  EXPECT_NE(Hasher().add("abc").hex(), Hasher().add("abd").hex());
  // Concatenation boundaries matter.
  EXPECT_NE(Hasher().add("ab").add("c").hex(), Hasher().add("a").add("bc").hex());
  EXPECT_NE(Hasher().add(std::uint64_t{1}).hex(), Hasher().add(std::uint64_t{2}).hex());
}
