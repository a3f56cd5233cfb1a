// When rcontrib's outputs are flushed: every -x records (never with -x 0), never inside a -x -y
// picture, after the record a zero-direction ray ends, and the header at once when a flush is
// due. What reached the file is read from disk while the stream is still open.
#include "radcl/contrib/output.h"

#include "files.h"
#include "temp_dir.h"

#include <chrono>
#include <filesystem>
#include <gtest/gtest.h>
#include <thread>

using namespace radcl::contrib;

namespace {

constexpr int kRecordBytes = 3 * sizeof(double);

class Flushing : public radcl::test::TempDir {
protected:
  // A -h- double stream (no header, so the flushed size counts records) for -x/-y.
  void start(int xres, int yres, bool header = false) {
    OutputSettings s;
    s.format = 'd';
    s.header = header;
    s.force_open = true; // a test may start again on the same file
    s.xres = xres;
    s.yres = yres;
    out = std::make_unique<Outputs>(s);
    out->add_modifier(file().string(), "sky", 1);
  }
  std::filesystem::path file() const { return dir / "out.dat"; }
  // Writes one record and returns the bytes on disk after it.
  std::uintmax_t record() {
    out->write_record(std::vector<double>{1, 2, 3});
    out->end_record();
    return std::filesystem::file_size(file());
  }
  std::unique_ptr<Outputs> out;
};

} // namespace

TEST_F(Flushing, EveryRecordWithX1) {
  start(1, 0);
  for (int k = 1; k <= 3; ++k)
    EXPECT_EQ(record(), k * kRecordBytes) << k;
}

TEST_F(Flushing, EveryXRecords) {
  start(3, 0);
  EXPECT_EQ(record(), 0);
  EXPECT_EQ(record(), 0);
  EXPECT_EQ(record(), 3 * kRecordBytes);
  EXPECT_EQ(record(), 3 * kRecordBytes);
  EXPECT_EQ(record(), 3 * kRecordBytes);
  EXPECT_EQ(record(), 6 * kRecordBytes);
}

// -x 1 -y N is a column, not a picture: flushed every record.
TEST_F(Flushing, ColumnIsFlushed) {
  start(1, 4);
  EXPECT_EQ(record(), 10 + kRecordBytes); // "-Y 4 +X 1\n" and the record
}

TEST_F(Flushing, NeverWithoutX) {
  start(0, 0);
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(record(), 0);
  out->finish();
  EXPECT_EQ(std::filesystem::file_size(file()), 4 * kRecordBytes);
}

// A zero-direction ray asks for a flush after the record it ends; the count starts again.
TEST_F(Flushing, RequestedFlush) {
  start(0, 0);
  EXPECT_EQ(record(), 0);
  out->request_flush();
  EXPECT_EQ(record(), 2 * kRecordBytes);
  EXPECT_EQ(record(), 2 * kRecordBytes); // -x 0: no more flushes
  start(4, 0);
  EXPECT_EQ(record(), 0);
  out->request_flush();
  EXPECT_EQ(record(), 2 * kRecordBytes);
  EXPECT_EQ(record(), 2 * kRecordBytes); // counting 4 again from here
  EXPECT_EQ(record(), 2 * kRecordBytes);
  EXPECT_EQ(record(), 2 * kRecordBytes);
  EXPECT_EQ(record(), 6 * kRecordBytes);
}

// A -x -y picture is written in one go: neither the count nor a request flushes it.
TEST_F(Flushing, PictureNeverFlushed) {
  start(2, 3);
  out->request_flush();
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(record(), 0) << k;
}

// When a flush is due (-x over 0) the header goes out as the stream opens.
TEST_F(Flushing, HeaderFlushedWhenFlushing) {
  start(2, 0, true);
  out->write_record(std::vector<double>{1, 2, 3});
  const auto header = std::filesystem::file_size(file());
  EXPECT_GT(header, 0u);
  out->end_record();
  EXPECT_EQ(std::filesystem::file_size(file()), header);
  start(0, 0, true);
  out->write_record(std::vector<double>{1, 2, 3});
  EXPECT_EQ(std::filesystem::file_size(file()), 0u);
}

// Through a command: a flushed record reaches `cat` while rcontrib goes on.
TEST_F(Flushing, PipeGetsFlushedRecords) {
  const auto target = dir / "piped.txt";
  OutputSettings s;
  s.header = false;
  s.xres = 1;
  Outputs pipe_out(s);
  pipe_out.add_modifier("!cat > " + target.string(), "sky", 1);
  pipe_out.write_record(std::vector<double>{1, 2, 3});
  pipe_out.end_record();
  const std::string expected = "1.000000e+00\t2.000000e+00\t3.000000e+00\t\n";
  std::string got;
  for (int k = 0; k < 500 && got != expected; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    got = radcl::test::read_file(target);
  }
  EXPECT_EQ(got, expected);
  pipe_out.finish();
}

TEST_F(Flushing, PipeKeepsUnflushedRecords) {
  const auto target = dir / "piped.txt";
  OutputSettings s;
  s.header = false;
  Outputs pipe_out(s);
  pipe_out.add_modifier("!cat > " + target.string(), "sky", 1);
  pipe_out.write_record(std::vector<double>{1, 2, 3});
  pipe_out.end_record();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(radcl::test::read_file(target), "");
  pipe_out.finish();
  EXPECT_EQ(radcl::test::read_file(target), "1.000000e+00\t2.000000e+00\t3.000000e+00\t\n");
}
