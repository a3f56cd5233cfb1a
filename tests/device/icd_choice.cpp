// Which driver's .icd file RADCL_DEVICE names (radcl then has the ICD loader open that one
// alone): a driver library whose path holds the text, only when exactly one does.
#include "radcl/device/icd_choice.h"

#include <fstream>
#include <gtest/gtest.h>

#include "temp_dir.h"

using radcl::device::icd_file_for;

namespace {
class IcdChoice : public radcl::test::TempDir {};
} // namespace

TEST_F(IcdChoice, NamedDriverOnly) {
  std::ofstream(dir / "pocl.icd") << "libpocl.so.2.10.0\n";
  std::ofstream(dir / "nvidia.icd") << "/usr/local/nvidia/lib64/libnvidia-opencl.so.1\n";
  std::ofstream(dir / "notes.txt") << "libpocl-notes\n";
  const std::string d = dir.string();
  EXPECT_EQ(icd_file_for(d, "pocl"), (dir / "pocl.icd").string());
  EXPECT_EQ(icd_file_for(d, "PoCL"), (dir / "pocl.icd").string());
  EXPECT_EQ(icd_file_for(d, "nvidia"), (dir / "nvidia.icd").string());
  // A device name or an index says nothing of the driver: every one is loaded.
  EXPECT_EQ(icd_file_for(d, "H200"), "");
  EXPECT_EQ(icd_file_for(d, "1"), "");
  EXPECT_EQ(icd_file_for(d, ""), "");
  // Text both libraries hold: ambiguous, so no choice.
  EXPECT_EQ(icd_file_for(d, "lib"), "");
  EXPECT_EQ(icd_file_for((dir / "missing").string(), "pocl"), "");
}
