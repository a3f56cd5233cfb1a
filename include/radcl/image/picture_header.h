// A Radiance information header (../shared/docs/radiance/picture-format.md §2): text lines ending
// at an empty line. The lines are kept verbatim, in order, so a header read and written again is
// unchanged; the values Radiance's tools look at are parsed from them on demand.
#pragma once

#include <array>
#include <ctime>
#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace radcl::image {

enum class PixelFormat { rgbe, xyze };

constexpr std::array<float, 8> kRadiancePrimaries = {0.640f, 0.330f, 0.290f,   0.600f,
                                                     0.150f, 0.060f, 1.0f / 3, 1.0f / 3};

class PictureHeader {
public:
  // Every line without its '\n', the "#?RADIANCE" id line included, the empty end line not.
  std::vector<std::string> lines;

  // Builders, each appending one line in the form Radiance's writers use.
  PictureHeader& add(std::string line);
  PictureHeader& add_id(std::string_view id = "RADIANCE");          // "#?RADIANCE"
  PictureHeader& add_command(const std::vector<std::string>& argv); // words quoted as fputword
  PictureHeader& add_software(std::string_view s);                  // "SOFTWARE= <s>"
  PictureHeader& add_frame(int n);                                  // "FRAME=<n>"
  PictureHeader& add_view(std::string_view v); // "VIEW=" + v (v starts with a space: " -vtv ...")
  PictureHeader& add_exposure(double e);       // "EXPOSURE=%e"
  PictureHeader& add_pixaspect(double pa);     // "PIXASPECT=%f"
  PictureHeader& add_dates(std::time_t t);     // "CAPDATE= ..." local, then "GMT= ..."
  PictureHeader& add_primaries(const std::array<float, 8>& p = kRadiancePrimaries);
  PictureHeader& add_format(PixelFormat f = PixelFormat::rgbe); // "FORMAT=32-bit_rle_rgbe"

  // Parsed values. FORMAT: the last FORMAT= value ("" if none). The others multiply over all
  // their lines, as Radiance's readers do, and are 1 when absent.
  std::string format() const;
  std::optional<PixelFormat> pixel_format() const; // from format(); rgbe when there is none
  double exposure() const;
  double pixaspect() const;
  std::array<double, 3> colorcorr() const;
  std::optional<std::array<float, 8>> primaries() const; // the last PRIMARIES= line
  std::vector<std::string> views() const; // each VIEW= value in order (apply them in turn)
  std::string software() const;           // the last SOFTWARE= value, trimmed
  std::optional<int> frame() const;
  std::string id() const;                    // "RADIANCE" for "#?RADIANCE", "" without id
  std::vector<std::string> commands() const; // lines that are neither id nor NAME=value

  // The value of the last "NAME=" line (text after '='), if any.
  std::optional<std::string> value(std::string_view name) const;
};

// True for "NAME=value" lines: an identifier-like name without spaces directly before '='.
bool is_variable_line(std::string_view line);

// Writes the lines and the empty end line. Throws FatalError on a stream error.
void write_header(std::ostream& out, const PictureHeader& h);

// Reads up to and including the empty line, as Radiance's getheader(): the first byte must be
// printable, "\r\n" also ends the header, lines over 2047 bytes are split. Throws FatalError
// (naming `name`) when the stream is not a header or ends inside it.
PictureHeader read_header(std::istream& in, const std::string& name);

} // namespace radcl::image
