// Four processes append to one file at the same time, as rtrace -n or several rtrace/rpict
// runs do with -af: every record must arrive exactly once, whole, and the file must pass the
// reader. Each process also checks that it saw every other process's records at its syncs.
#include <cstdio>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <string>
#include <sys/wait.h>
#include <tuple>
#include <unistd.h>

#include "amb_test_util.h"
#include "radcl/ambient/ambient_file.h"
#include "radcl/ambient/dircode.h"

using namespace radcl::ambient;
namespace rt = radcl::test;

namespace {

// Any header will do: the first process to create the file writes its own.
radcl::image::PictureHeader image_header() {
  AmbientSettings s;
  s.progname = "concurrent";
  s.software = "radcl test";
  return new_file_header(s);
}

constexpr int kProcesses = 4;
constexpr int kBatches = 60;

// Record j of batch b of process p: its identity is in the position, the rest varies too.
AmbientRecord record(int p, int b, int j) {
  AmbientRecord r;
  r.pos = {static_cast<float>(p), static_cast<float>(b), static_cast<float>(j)};
  r.ndir = encode_dir({0.0, p % 2 ? -1.0 : 1.0, 0.0});
  r.udir = encode_dir({1.0, 0.0, 0.0});
  r.lvl = static_cast<std::int16_t>(j % 4);
  r.weight = 1.0f / static_cast<float>(1 + j);
  r.rad = {0.1f + 0.01f * static_cast<float>(b), 0.2f + 0.01f * static_cast<float>(b)};
  r.val = {0.5f * static_cast<float>(p + 1), 0.25f, 0.125f * static_cast<float>(j + 1)};
  r.gpos = {0.01f * static_cast<float>(j), -0.02f};
  r.gdir = {0.03f, -0.04f * static_cast<float>(p)};
  r.corral = static_cast<std::uint32_t>(p << 16 | b << 4 | j);
  return r;
}

int batch_size(int p, int b) {
  return 1 + (p * 7 + b * 3) % 9; // 1..9 records, different per process and batch
}

// One writer; returns a bit mask of failures (0 = fine).
int writer(const std::string& path, int p, int start_fd) {
  char go;
  if (::read(start_fd, &go, 1) < 0) return 32; // wait for the start signal (EOF)
  AmbientFile f;
  std::size_t seen = f.open(path, image_header()).size();
  std::size_t mine = 0;
  for (int b = 0; b < kBatches; ++b) {
    std::vector<AmbientRecord> batch;
    for (int j = 0; j < batch_size(p, b); ++j)
      batch.push_back(record(p, b, j));
    const std::vector<AmbientRecord> others = f.append(batch);
    for (const auto& r : others)
      if (static_cast<int>(r.pos[0]) == p) return 1; // our own records never come back
    seen += others.size();
    mine += batch.size();
    if (b % 7 == 0) seen += f.sync().size();
    ::usleep(static_cast<useconds_t>(100 * ((p + b) % 3)));
  }
  seen += f.sync().size();
  // Everything in the file is either ours or was reported to us.
  const AmbientContents c = parse_ambient(rt::read_file(path), "bad ambient file");
  if (c.records.size() < seen + mine) return 2;
  return 0;
}

} // namespace

TEST(AmbientConcurrency, FourProcessesAppendWithoutLossOrTearing) {
  rt::TempFolder dir("concurrent");
  const std::string path = dir / "shared.amb";
  int start[2];
  ASSERT_EQ(::pipe(start), 0);
  std::vector<pid_t> pids;
  for (int p = 0; p < kProcesses; ++p) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::close(start[1]);
      int rc = 64;
      try {
        rc = writer(path, p, start[0]);
      } catch (...) {
        rc = 16;
      }
      ::_exit(rc);
    }
    pids.push_back(pid);
  }
  ::close(start[0]);
  ::close(start[1]); // all children start now (their read() sees EOF)
  for (pid_t pid : pids) {
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "writer failure bits (1 echo, 2 missed, 16 threw)";
  }

  rt::CapturedWarnings log;
  const std::string bytes = rt::read_file(path);
  const AmbientContents c = parse_ambient(bytes, "bad ambient file");
  std::size_t expected = 0;
  for (int p = 0; p < kProcesses; ++p)
    for (int b = 0; b < kBatches; ++b)
      expected += static_cast<std::size_t>(batch_size(p, b));
  ASSERT_EQ(c.records.size(), expected);
  EXPECT_EQ(c.valid_end, bytes.size()) << "bytes after the last whole record";
  // Each record exactly once and bit-identical to what its writer encoded; within a process,
  // batches appear in order and a batch is contiguous (appended under one lock).
  std::set<std::tuple<int, int, int>> found;
  std::map<int, int> last_batch;
  for (std::size_t i = 0; i < c.records.size(); ++i) {
    const AmbientRecord& r = c.records[i];
    const int p = static_cast<int>(r.pos[0]), b = static_cast<int>(r.pos[1]),
              j = static_cast<int>(r.pos[2]);
    ASSERT_TRUE(found.emplace(p, b, j).second) << "duplicate record " << p << " " << b << " " << j;
    const RecordBytes want = encode_record(record(p, b, j));
    ASSERT_TRUE(std::equal(want.begin(), want.end(),
                           reinterpret_cast<const unsigned char*>(bytes.data()) + c.data_start +
                               i * kRecordSize))
        << "record " << i << " torn";
    if (j == 0) {
      EXPECT_GT(b, last_batch.count(p) ? last_batch[p] : -1);
      last_batch[p] = b;
    } else {
      ASSERT_GT(i, 0u);
      const AmbientRecord& prev = c.records[i - 1];
      EXPECT_EQ(prev.pos[0], r.pos[0]);
      EXPECT_EQ(prev.pos[1], r.pos[1]);
      EXPECT_EQ(prev.pos[2] + 1, r.pos[2]);
    }
  }
  // How much the writers interleaved (not asserted: the scheduler decides).
  int switches = 0;
  for (std::size_t i = 1; i < c.records.size(); ++i)
    switches += c.records[i].pos[0] != c.records[i - 1].pos[0];
  ::testing::Test::RecordProperty("writer_switches", switches);
  std::printf("writer switches in the file: %d of %zu batches\n", switches,
              static_cast<std::size_t>(kProcesses * kBatches));
  // Reopening as a writer finds nothing to repair.
  AmbientFile f;
  EXPECT_EQ(f.open(path, image_header()).size(), expected);
  EXPECT_TRUE(log.list().empty());
}
