#include "radcl/ambient/ambient_file.h"

#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "radcl/util/error.h"

namespace radcl::ambient {
namespace {

std::string read_range(int fd, long long from, long long to) {
  std::string s(static_cast<std::size_t>(to - from), '\0');
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t n =
        ::pread(fd, s.data() + done, s.size() - done, from + static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break; // shorter than fstat said: someone cut the file; parse what we have
    done += static_cast<std::size_t>(n);
  }
  s.resize(done);
  return s;
}

bool write_all(int fd, const std::string& s, long long at) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::pwrite(fd, s.data() + done, s.size() - done, at + static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

long long file_end(int fd) {
  const off_t end = ::lseek(fd, 0, SEEK_END);
  if (end < 0) throw FatalError("seek failed in ambsync");
  return end;
}

void set_lock(int fd, short type) {
  struct flock fl {};
  fl.l_type = type;
  fl.l_whence = SEEK_SET; // whole file: start 0, length 0
  while (::fcntl(fd, F_SETLKW, &fl) == -1)
    if (errno != EINTR) throw FatalError("cannot (un)lock ambient file");
}

// Releases the lock on every way out of a locked section.
class LockGuard {
public:
  LockGuard(int fd, short type) : fd_(fd) { set_lock(fd, type); }
  ~LockGuard() {
    struct flock fl {};
    fl.l_type = F_UNLCK;
    fl.l_whence = SEEK_SET;
    ::fcntl(fd_, F_SETLK, &fl);
  }
  LockGuard(const LockGuard&) = delete;
  LockGuard& operator=(const LockGuard&) = delete;

private:
  int fd_;
};

} // namespace

AmbientFile::~AmbientFile() {
  close();
}

void AmbientFile::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::vector<AmbientRecord> AmbientFile::open(const std::string& path,
                                             const image::PictureHeader& header) {
  close();
  path_ = path;
  read_only_ = false;
  // Radiance's order: read/write, else read-only, else create. A file that does not exist is
  // created at once (no O_TRUNC or O_EXCL: if another process creates it first, we find its
  // header below): trying read-only first could meet a file another process has just created
  // and leave this one unable to write (Radiance has that race).
  bool writable = true;
  fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0 && errno == ENOENT) fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    writable = false;
  }
  if (fd_ < 0) throw FatalError("cannot open ambient file \"" + path + "\"");
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || S_ISDIR(st.st_mode)) { // a directory opens read-only
    close();
    throw FatalError("bad ambient file \"" + path + "\" (a directory)");
  }
  try {
    return load(writable, header);
  } catch (...) {
    close();
    throw;
  }
}

std::vector<AmbientRecord> AmbientFile::load(bool writable, const image::PictureHeader& header) {
  std::vector<AmbientRecord> records;
  {
    LockGuard guard(fd_, writable ? F_WRLCK : F_RDLCK);
    const long long size = file_end(fd_);
    if (size == 0 && writable) {
      // New, or created by a process that has not written its header yet (it will wait for
      // our lock and then find ours).
      const std::string prologue = file_prologue(header);
      if (!write_all(fd_, prologue, 0)) {
        [[maybe_unused]] int rc = ::ftruncate(fd_, 0);
        throw FatalError("error writing to ambient file");
      }
      data_start_ = known_end_ = static_cast<long long>(prologue.size());
      return records;
    }
    AmbientContents c = parse_ambient(read_range(fd_, 0, size), "bad ambient file");
    records = std::move(c.records);
    data_start_ = static_cast<long long>(c.data_start);
    known_end_ = static_cast<long long>(c.valid_end);
    if (writable && size != known_end_) {
      warning("ignoring last " + std::to_string((size - known_end_) / kRecordSize) +
              " values in ambient file (corrupted)");
      if (::ftruncate(fd_, known_end_) != 0) throw FatalError("cannot truncate ambient file");
    }
  }
  if (!writable) {
    warning("loaded " + std::to_string(records.size()) + " values from read-only ambient file");
    close();
    read_only_ = true;
  }
  return records;
}

std::vector<AmbientRecord> AmbientFile::append(std::span<const AmbientRecord> records) {
  std::vector<AmbientRecord> others;
  if (fd_ < 0) return others;
  std::string out;
  out.reserve(records.size() * kRecordSize);
  std::size_t skipped = 0;
  for (const AmbientRecord& r : records) {
    if (!record_writable(r)) {
      ++skipped;
      continue;
    }
    const RecordBytes b = encode_record(r);
    out.append(reinterpret_cast<const char*>(b.data()), b.size());
  }
  if (skipped)
    warning(std::to_string(skipped) + " invalid ambient values not written to \"" + path_ + "\"");

  LockGuard guard(fd_, out.empty() ? F_RDLCK : F_WRLCK);
  const long long flen = file_end(fd_);
  if (flen < known_end_) {
    // Another process cut a corrupted tail we had read past: go back to a record boundary.
    const long long valid = flen > data_start_ ? flen - data_start_ : 0;
    known_end_ = data_start_ + valid / static_cast<long long>(kRecordSize) * kRecordSize;
  }
  long long left = flen - known_end_;
  if (left > 0) {
    const std::string grown = read_range(fd_, known_end_, flen);
    const auto* p = reinterpret_cast<const unsigned char*>(grown.data());
    std::size_t pos = 0;
    while (left >= static_cast<long long>(kRecordSize)) {
      auto r = read_record(p + pos, grown.size() - pos);
      if (!r) {
        warning("ambient file \"" + path_ + "\" corrupted near character " +
                std::to_string(flen - left));
        break;
      }
      others.push_back(*r);
      pos += kRecordSize;
      left -= static_cast<long long>(kRecordSize);
    }
    known_end_ = flen - left;
  }
  if (!out.empty()) {
    // Whatever follows the last good record (a partial or bad one) is replaced by ours.
    if (left > 0 && ::ftruncate(fd_, known_end_) != 0)
      throw FatalError("cannot truncate ambient file");
    if (!write_all(fd_, out, known_end_)) {
      [[maybe_unused]] int rc = ::ftruncate(fd_, known_end_);
      throw FatalError("error writing to ambient file");
    }
    known_end_ += static_cast<long long>(out.size());
  }
  return others;
}

} // namespace radcl::ambient
