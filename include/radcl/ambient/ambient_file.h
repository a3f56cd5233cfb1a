// A .amb file shared with other radcl and Radiance processes
// (../shared/docs/radiance/ambient-file.md §4): an append-only log of 67-byte records. Every access
// takes a POSIX fcntl() lock on the whole file, the lock Radiance's ambsync() uses, so radcl and
// rtrace/rpict can share one file.
//
// fcntl() locks belong to a process, not to a descriptor: two AmbientFile objects on the same
// path in one process do not exclude each other, and closing either releases both locks.
// Share one object per process (threads serialise through it).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "radcl/ambient/format.h"
#include "radcl/ambient/record.h"

namespace radcl::ambient {

class AmbientFile {
public:
  AmbientFile() = default;
  ~AmbientFile();
  AmbientFile(const AmbientFile&) = delete;
  AmbientFile& operator=(const AmbientFile&) = delete;

  // Opens `path` and returns the records it holds (setambient()). A file that exists is
  // checked (FatalError "bad ambient file") and its valid prefix is loaded; trailing bytes
  // after it (a killed writer's partial record, or a bad record and everything after it) are
  // reported ("ignoring last N values in ambient file (corrupted)") and cut off. A file that
  // can only be read is loaded, reported ("loaded N values from read-only ambient file") and
  // closed: append() and sync() then do nothing. A missing (or empty) file is created with
  // `header` (new_file_header()) and the magic number.
  std::vector<AmbientRecord> open(const std::string& path, const image::PictureHeader& header);

  // ambsync() with records to flush: under an exclusive lock, reads the records other
  // processes appended since our last sync (a bad one ends that with the warning "ambient
  // file "<path>" corrupted near character N"), then appends `records` at the end of the
  // valid data. Returns the others' records. Records that a reader would reject
  // (record_writable() false) are not written; a warning counts them. A write error removes
  // what was written of the batch and throws, so the file only ever gains whole records.
  std::vector<AmbientRecord> append(std::span<const AmbientRecord> records);

  // ambsync() with nothing to flush: a shared lock, and the records others added.
  std::vector<AmbientRecord> sync() { return append({}); }

  void close();

  bool is_open() const { return fd_ >= 0; }
  bool read_only() const { return read_only_; }
  const std::string& path() const { return path_; }
  // Offset just after the last record we know of (Radiance's lastpos).
  long long known_end() const { return known_end_; }

private:
  std::vector<AmbientRecord> load(bool writable, const image::PictureHeader& header);

  std::string path_;
  int fd_ = -1;
  bool read_only_ = false;
  long long data_start_ = 0;
  long long known_end_ = 0;
};

} // namespace radcl::ambient
