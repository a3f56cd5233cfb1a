// rpict -z files: raw native floats, one scanline after another, no header.
#include <gtest/gtest.h>

#include <filesystem>

#include "radcl/image/depth.h"
#include "radcl/util/error.h"
#include "temp_dir.h"

using namespace radcl::image;

TEST(Depth, WritesRawFloatsAndResumes) {
  const radcl::test::TempFolder dir("depth");
  const std::string path = (dir / "z.dat").string();
  const int w = 4;
  {
    DepthWriter z(path, w);
    for (int y = 0; y < 3; ++y) {
      const float line[w] = {y + 0.5f, 1e-3f, 1e30f, 0.0f};
      z.write_scanline(line);
    }
    z.close();
  }
  EXPECT_EQ(std::filesystem::file_size(path), 3u * w * sizeof(float));
  auto v = read_depth(path, w, 3);
  EXPECT_EQ(v[4], 1.5f);
  EXPECT_EQ(v[10], 1e30f);

  // Recovery after 1 scanline: the writer continues after it and keeps the rest of the file.
  {
    DepthWriter z(path, w, 1);
    const float line[w] = {7, 7, 7, 7};
    z.write_scanline(line);
  }
  v = read_depth(path, w, 3);
  EXPECT_EQ(v[0], 0.5f);
  EXPECT_EQ(v[4], 7.0f);
  EXPECT_EQ(v[8], 2.5f);
  EXPECT_THROW(read_depth(path, w, 4), radcl::FatalError);
  EXPECT_THROW(DepthWriter("/nonexistent/z", w), radcl::FatalError);
}
