// main() for every test executable: exports the build's paths and cache folders (unless the
// caller already set them) so tests and the programs they start find data and keep caches in
// the build tree.
#include <cstdlib>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
  setenv("POCL_CACHE_DIR", RADCL_TEST_POCL_CACHE, 0);
  setenv("RADCL_CACHE_DIR", RADCL_TEST_CACHE, 0);
  setenv("RADCL_TEST_DATA", RADCL_TEST_DATA_DIR, 0);
  setenv("RADCL_BIN", RADCL_TEST_BIN_DIR, 0);
  setenv("RADCL_SOURCE_DIR", RADCL_TEST_SOURCE_DIR, 0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
