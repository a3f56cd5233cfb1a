// rcontrib with a large matrix: 10,000 sensors x 2,306 bins (Reinhart MF:4), 277 MB of float
// output, streamed in batches whose bins stay bounded in memory rather than held whole.
#include <gtest/gtest.h>
#include <string>

#include "files.h"
#include "run_program.h"
#include "temp_dir.h"
#include "test_env.h"

namespace t = radcl::test;

TEST(RcontribLargeMatrix, TenThousandSensorsOfMF4Stream) {
  const std::string grid = t::read_file(t::data("scenes/office_grid.pts"));
  std::string input;
  for (int k = 0; k < 130; ++k)
    input += grid;
  std::size_t pos = 0; // 130 x 77 lines: the first 10,000
  for (int line = 0; line < 10000; ++line)
    pos = input.find('\n', pos) + 1;
  input.resize(pos);
  t::TempFolder dir("rcontrib_large");
  const std::string mem = (dir.path() / "maxrss").string();
  const std::string count = (dir.path() / "count").string();
  // GNU time's %M: the peak resident memory in KB. The matrix goes to a command (-o '!cmd').
  const t::ProgramRun r =
      t::Program("rcontrib")
          .env("/usr/bin/time -f %M -o " + mem + " ")
          .input(input)
          .run("-n 2 -h -faf -I -ab 1 -ad 16 -lw 1e-3 -e MF:4 -f reinhart.cal -b rbin -bn "
               "Nrbins -o '!wc -c > " +
               count + "' -m skyglow office_dome.oct");
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(std::stoull(t::read_file(count)), 10000ull * 2306 * 3 * sizeof(float));
  // One batch's bins (at most 256 MB) held twice (the renderer's sums and the results handed
  // on) plus the scene and the program: well under the 1.1 GB the whole matrix would take.
  EXPECT_LT(std::stoull(t::read_file(mem)), 1000ull * 1024);
}
