// The .amb file as bytes (../shared/docs/radiance/ambient-file.md §1, §5): information header,
// magic number 559, then 67-byte records. Parsing here has no side effects; AmbientFile adds
// locking and appending.
#pragma once

#include <array>
#include <ctime>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radcl/ambient/record.h"
#include "radcl/image/picture_header.h"

namespace radcl::ambient {

// formatval(): the value of a "FORMAT=" line with a non-empty value, else nullopt.
std::optional<std::string> format_value(std::string_view line);

// checkheader(): the header at the start of `bytes` (lines verbatim, FORMAT lines included)
// and the offset just after its empty line; nullopt where Radiance's getheader() fails (first
// byte not printable, no empty line before the end).
struct HeaderSpan {
  image::PictureHeader header;
  std::size_t end = 0;
};
std::optional<HeaderSpan> read_header(std::string_view bytes);

// The last FORMAT value in the header, "" if there is none (checkheader's rule).
std::string header_format(const image::PictureHeader& h);

struct AmbientContents {
  image::PictureHeader header;        // as read, FORMAT lines included
  std::size_t data_start = 0;         // first record: just after the magic number
  std::vector<AmbientRecord> records; // the valid prefix
  std::size_t valid_end = 0;          // data_start + records.size() * kRecordSize
};

// Reads header, magic and records up to the first record that is incomplete or fails
// record_ok(), as Radiance's loaders do. A header that is not Radiance's, a FORMAT other than
// Radiance_ambval (none is accepted) or a magic other than 559 throws FatalError(bad_message).
AmbientContents parse_ambient(std::string_view bytes, const std::string& bad_message);

// What initambfile() writes into a new file's header: the -a settings for humans and getinfo.
struct AmbientSettings {
  std::string progname;                    // argv[0] as invoked
  std::array<double, 3> av{0.0, 0.0, 0.0}; // -av
  int aw = 0;                              // -aw
  int ab = 0;                              // -ab
  double aa = 0.1;                         // -aa
  int ad = 1024;                           // -ad
  int as = 512;                            // -as
  int ar = 256;                            // -ar
  std::optional<std::string> octree;       // none: the line ends in a space
  std::string software;                    // SOFTWARE= value
  std::time_t time = 0;                    // CAPDATE (local) and GMT
};
image::PictureHeader new_file_header(const AmbientSettings& s);

// Header lines, "FORMAT=Radiance_ambval", the empty line and the magic number: everything a
// new file holds before its first record.
std::string file_prologue(const image::PictureHeader& h);

} // namespace radcl::ambient
