// AmbientFile: creating, loading, appending and syncing a shared .amb file, and Radiance's
// rules for a killed writer's partial record, a corrupted record, a read-only file and a file
// that is not an ambient file (ambient-file.md §4, §5).
#include <gtest/gtest.h>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "amb_test_util.h"
#include "radcl/ambient/ambient_file.h"
#include "radcl/ambient/dircode.h"
#include "radcl/util/error.h"

using namespace radcl::ambient;
namespace rt = radcl::test;
using rt::CapturedWarnings;

namespace {

AmbientRecord make_record(float x, float y, float z) {
  AmbientRecord r;
  r.pos = {x, y, z};
  r.ndir = encode_dir({0.0, 0.0, 1.0});
  r.udir = encode_dir({1.0, 0.0, 0.0});
  r.lvl = 1;
  r.weight = 0.5f;
  r.rad = {0.25f, 0.5f};
  r.val = {0.5f, 0.25f, 0.125f};
  r.gpos = {0.1f, 0.2f};
  r.gdir = {0.3f, 0.4f};
  r.corral = 5;
  return r;
}

radcl::image::PictureHeader header() {
  AmbientSettings s;
  s.progname = "radcl-test";
  s.octree = "scene.oct";
  s.software = "radcl test";
  return new_file_header(s);
}

// The office cache copied to a scratch file, with its contents parsed.
struct OfficeCopy {
  std::string path;
  std::string bytes;
  AmbientContents contents;
};

OfficeCopy office_copy(const rt::TempFolder& dir) {
  OfficeCopy c;
  c.path = dir / "office.amb";
  c.bytes = rt::read_file(rt::office_amb());
  c.contents = parse_ambient(c.bytes, "bad ambient file");
  rt::write_file(c.path, c.bytes);
  return c;
}

std::size_t record_offset(const OfficeCopy& c, std::size_t i) {
  return c.contents.data_start + i * kRecordSize;
}

std::string fatal_message(const std::string& path) {
  try {
    AmbientFile f;
    f.open(path, header());
  } catch (const radcl::FatalError& e) {
    return e.what();
  }
  return "(no error)";
}

} // namespace

TEST(AmbientFile, CreatesAppendsAndReloads) {
  rt::TempFolder dir("create");
  const std::string path = dir / "new.amb";
  CapturedWarnings log;
  {
    AmbientFile f;
    EXPECT_TRUE(f.open(path, header()).empty());
    EXPECT_FALSE(f.read_only());
    const std::string prologue = file_prologue(header());
    EXPECT_EQ(rt::read_file(path), prologue);
    const std::vector<AmbientRecord> batch = {make_record(1, 2, 3), make_record(4, 5, 6)};
    EXPECT_TRUE(f.append(batch).empty());
    EXPECT_TRUE(f.sync().empty());
    EXPECT_EQ(rt::read_file(path).size(), prologue.size() + 2 * kRecordSize);
    EXPECT_EQ(f.known_end(), static_cast<long long>(prologue.size() + 2 * kRecordSize));
  }
  AmbientFile g;
  const std::vector<AmbientRecord> again = g.open(path, header());
  ASSERT_EQ(again.size(), 2u);
  EXPECT_EQ(again[0].pos, make_record(1, 2, 3).pos);
  EXPECT_EQ(again[1].corral, 5u);
  const AmbientContents c = parse_ambient(rt::read_file(path), "bad ambient file");
  EXPECT_EQ(header_format(c.header), "Radiance_ambval");
  EXPECT_EQ(c.header.lines[1], "radcl-test -av 0 0 0 -aw 0 -ab 0 -aa 0.1 -ad 1024 -as 512 "
                               "-ar 256 scene.oct");
  EXPECT_TRUE(log.list().empty());
}

TEST(AmbientFile, LoadsRadiancesFileAndSeesOthersRecords) {
  rt::TempFolder dir("others");
  const OfficeCopy c = office_copy(dir);
  CapturedWarnings log;
  AmbientFile a, b; // one process: locks do not exclude, but the data flow is the same
  EXPECT_EQ(a.open(c.path, header()).size(), 2253u);
  EXPECT_EQ(b.open(c.path, header()).size(), 2253u);
  const std::vector<AmbientRecord> mine = {make_record(1, 1, 1), make_record(2, 2, 2),
                                           make_record(3, 3, 3)};
  EXPECT_TRUE(b.append(mine).empty());
  // a's next append first picks up b's three records, then writes its own after them.
  const std::vector<AmbientRecord> theirs = a.append(std::vector{make_record(9, 9, 9)});
  ASSERT_EQ(theirs.size(), 3u);
  EXPECT_EQ(theirs[2].pos, mine[2].pos);
  EXPECT_EQ(b.sync().size(), 1u);
  const AmbientContents after = parse_ambient(rt::read_file(c.path), "bad ambient file");
  ASSERT_EQ(after.records.size(), 2257u);
  EXPECT_EQ(after.valid_end, rt::read_file(c.path).size());
  EXPECT_EQ(after.records.back().pos, make_record(9, 9, 9).pos);
  // Radiance's records are untouched.
  EXPECT_EQ(rt::read_file(c.path).substr(0, c.bytes.size()), c.bytes);
  EXPECT_TRUE(log.list().empty());
}

TEST(AmbientFile, PartialRecordOfAKilledWriterIsCutOff) {
  rt::TempFolder dir("partial");
  OfficeCopy c = office_copy(dir);
  const std::size_t cut = record_offset(c, 100) + 30; // 30 bytes into record 100
  rt::write_file(c.path, c.bytes.substr(0, cut));
  CapturedWarnings log;
  AmbientFile f;
  const std::vector<AmbientRecord> got = f.open(c.path, header());
  ASSERT_EQ(got.size(), 100u);
  EXPECT_EQ(got.back(), c.contents.records[99]);
  // Radiance counts whole records only: a partial one is "0 values".
  ASSERT_EQ(log.list().size(), 1u);
  EXPECT_EQ(log.list()[0], "ignoring last 0 values in ambient file (corrupted)");
  EXPECT_EQ(rt::read_file(c.path), c.bytes.substr(0, record_offset(c, 100)));
  // Appending continues from the last whole record.
  f.append(std::vector{make_record(1, 2, 3)});
  const AmbientContents after = parse_ambient(rt::read_file(c.path), "bad ambient file");
  EXPECT_EQ(after.records.size(), 101u);
  EXPECT_EQ(after.valid_end, rt::read_file(c.path).size());
}

TEST(AmbientFile, CorruptedRecordEndsLoadingAndIsCutOff) {
  rt::TempFolder dir("corrupt");
  OfficeCopy c = office_copy(dir);
  std::string bytes = c.bytes;
  // Record 500's weight becomes 0 (mantissa bytes at offset 1..4 of the record).
  for (int i = 1; i <= 5; ++i)
    bytes[record_offset(c, 500) + static_cast<std::size_t>(i)] = 0;
  rt::write_file(c.path, bytes);
  CapturedWarnings log;
  AmbientFile f;
  const std::vector<AmbientRecord> got = f.open(c.path, header());
  EXPECT_EQ(got.size(), 500u);
  ASSERT_EQ(log.list().size(), 1u);
  EXPECT_EQ(log.list()[0], "ignoring last 1753 values in ambient file (corrupted)");
  EXPECT_EQ(rt::read_file(c.path).size(), record_offset(c, 500));
}

TEST(AmbientFile, CorruptedRecordFromAnotherWriterStopsTheSync) {
  rt::TempFolder dir("corrupt-sync");
  const OfficeCopy c = office_copy(dir);
  CapturedWarnings log;
  AmbientFile f;
  ASSERT_EQ(f.open(c.path, header()).size(), 2253u);
  // Another writer appends two good records, one with a zero normal code, and a partial one.
  std::string more;
  for (const AmbientRecord& r : {make_record(1, 0, 0), make_record(2, 0, 0)}) {
    const RecordBytes b = encode_record(r);
    more.append(reinterpret_cast<const char*>(b.data()), b.size());
  }
  AmbientRecord bad = make_record(3, 0, 0);
  RecordBytes bb = encode_record(bad);
  for (int i = 21; i < 25; ++i)
    bb[static_cast<std::size_t>(i)] = 0;
  more.append(reinterpret_cast<const char*>(bb.data()), bb.size());
  more.append(20, 'x');
  rt::write_file(c.path, c.bytes + more);
  const std::vector<AmbientRecord> seen = f.sync();
  ASSERT_EQ(seen.size(), 2u);
  const std::size_t bad_at = c.bytes.size() + 2 * kRecordSize;
  ASSERT_EQ(log.list().size(), 1u);
  EXPECT_EQ(log.list()[0],
            "ambient file \"" + c.path + "\" corrupted near character " + std::to_string(bad_at));
  // A sync with nothing to write changes nothing; an append replaces the bad tail with whole
  // records, so the file is valid again.
  EXPECT_EQ(rt::read_file(c.path).size(), c.bytes.size() + more.size());
  log.list().clear();
  EXPECT_TRUE(f.append(std::vector{make_record(4, 0, 0)}).empty());
  EXPECT_EQ(log.list().size(), 1u); // the bad record is seen (and reported) once more
  const std::string now = rt::read_file(c.path);
  const AmbientContents after = parse_ambient(now, "bad ambient file");
  EXPECT_EQ(after.records.size(), 2253u + 3u);
  EXPECT_EQ(after.valid_end, now.size());
  EXPECT_EQ(after.records.back().pos, make_record(4, 0, 0).pos);
}

TEST(AmbientFile, InvalidRecordsAreNeverWritten) {
  rt::TempFolder dir("invalid");
  const std::string path = dir / "x.amb";
  CapturedWarnings log;
  AmbientFile f;
  f.open(path, header());
  AmbientRecord nan = make_record(1, 1, 1);
  nan.val[0] = std::numeric_limits<float>::quiet_NaN();
  AmbientRecord zero_weight = make_record(2, 2, 2);
  zero_weight.weight = 0.0f;
  f.append(std::vector{make_record(0, 0, 0), nan, zero_weight});
  ASSERT_EQ(log.list().size(), 1u);
  EXPECT_EQ(log.list()[0], "2 invalid ambient values not written to \"" + path + "\"");
  const AmbientContents c = parse_ambient(rt::read_file(path), "bad ambient file");
  EXPECT_EQ(c.records.size(), 1u);
  EXPECT_EQ(c.valid_end, rt::read_file(path).size());
}

TEST(AmbientFile, ReadOnlyFileIsLoadedAndNotWritten) {
  rt::TempFolder dir("readonly");
  const OfficeCopy c = office_copy(dir);
  // Cut mid-record too: a read-only file is neither repaired nor reported as corrupted.
  rt::write_file(c.path, c.bytes.substr(0, c.bytes.size() - 10));
  ASSERT_EQ(::chmod(c.path.c_str(), 0444), 0);
  ASSERT_EQ(::chmod((dir / "").c_str(), 0755), 0);
  // As root every file is writable: check as an unprivileged user in a child process.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    int status = 0;
    try {
      if (::geteuid() == 0 && ::setuid(65534) != 0) ::_exit(10);
      CapturedWarnings log;
      AmbientFile f;
      const std::vector<AmbientRecord> got = f.open(c.path, header());
      if (got.size() != 2252) status |= 1;
      if (!f.read_only() || f.is_open()) status |= 2;
      if (log.list() != std::vector<std::string>{"loaded 2252 values from read-only ambient file"})
        status |= 4;
      if (!f.append(std::vector{make_record(1, 2, 3)}).empty() || !f.sync().empty()) status |= 8;
    } catch (...) {
      status |= 16;
    }
    ::_exit(status);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "bits: 1 count, 2 state, 4 warning, 8 append, 16 threw, "
                                       "10 setuid failed";
  EXPECT_EQ(rt::read_file(c.path), c.bytes.substr(0, c.bytes.size() - 10));
}

TEST(AmbientFile, BadFilesAreFatal) {
  rt::TempFolder dir("bad");
  const std::string bytes = rt::read_file(rt::office_amb());
  const AmbientContents c = parse_ambient(bytes, "bad ambient file");
  std::string old = bytes;
  old[c.data_start - 1] = 0x2d; // magic 557: Radiance 4's format
  rt::write_file(dir / "old.amb", old);
  EXPECT_EQ(fatal_message(dir / "old.amb"), "bad ambient file");
  rt::write_file(dir / "fmt.amb", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n\x02\x2f");
  EXPECT_EQ(fatal_message(dir / "fmt.amb"), "bad ambient file");
  rt::write_file(dir / "binary.amb", std::string("\x02\x2f", 2));
  EXPECT_EQ(fatal_message(dir / "binary.amb"), "bad ambient file");
  rt::write_file(dir / "nomagic.amb", "#?RADIANCE\nFORMAT=Radiance_ambval\n\n\x02");
  EXPECT_EQ(fatal_message(dir / "nomagic.amb"), "bad ambient file");
  rt::write_file(dir / "noend.amb", "#?RADIANCE\nFORMAT=Radiance_ambval\n");
  EXPECT_EQ(fatal_message(dir / "noend.amb"), "bad ambient file");
  EXPECT_EQ(fatal_message(dir / "no/such/folder.amb"),
            "cannot open ambient file \"" + (dir / "no/such/folder.amb").string() + "\"");
  // Nothing was written to the bad files.
  EXPECT_EQ(rt::read_file(dir / "old.amb"), old);
  // No FORMAT line at all is accepted, as checkheader() does.
  rt::write_file(dir / "noformat.amb", "#?RADIANCE\nrtrace\n\n\x02\x2f");
  AmbientFile f;
  EXPECT_TRUE(f.open(dir / "noformat.amb", header()).empty());
}

TEST(AmbientFile, EmptyFileIsInitialised) {
  rt::TempFolder dir("empty");
  rt::write_file(dir / "e.amb", "");
  AmbientFile f;
  EXPECT_TRUE(f.open(dir / "e.amb", header()).empty());
  EXPECT_EQ(rt::read_file(dir / "e.amb"), file_prologue(header()));
}
