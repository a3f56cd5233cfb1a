// Radiance pictures: header, resolution string, scanlines. Writing streams scanline by
// scanline (rpict writes as it renders); reading returns pixels in top-down, left-to-right
// order whatever the file's orientation.
#pragma once

#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "radcl/image/picture_header.h"
#include "radcl/image/resolution.h"
#include "radcl/image/rgbe.h"

namespace radcl::image {

// Writes the header, the resolution string, then one scanline per call in the file's order,
// each encoded as Radiance's writer does. Throws FatalError on a write error.
class PictureWriter {
public:
  PictureWriter(std::ostream& out, const PictureHeader& header, const Resolution& res);
  // Scanlines only: for a stream whose header and resolution are already written.
  PictureWriter(std::ostream& out, const Resolution& res);

  void write_scanline(std::span<const Rgbe> pixels);
  void write_scanline(std::span<const Color> pixels); // converted with to_rgbe()
  void flush();

  const Resolution& resolution() const { return res_; }
  int scanlines_written() const { return written_; }

private:
  std::ostream& out_;
  Resolution res_;
  int written_ = 0;
  std::vector<unsigned char> buf_;
  std::vector<Rgbe> conv_;
};

// Reads a picture's header and resolution on construction, then scanlines on demand.
class PictureReader {
public:
  // `name` only labels error messages.
  PictureReader(std::istream& in, std::string name);

  const PictureHeader& header() const { return header_; }
  const Resolution& resolution() const { return res_; }
  int scanlines_read() const { return read_; }

  // The next scanline, in file order. Throws FatalError when the data is truncated or corrupt,
  // or when every scanline has been read.
  void read_scanline(std::span<Rgbe> pixels);
  // As read_scanline(), but returns false (consuming an unknown amount) instead of throwing on
  // truncated or corrupt data.
  bool try_read_scanline(std::span<Rgbe> pixels);

private:
  std::istream& in_;
  std::string name_;
  PictureHeader header_;
  Resolution res_;
  int read_ = 0;
};

struct Picture {
  PictureHeader header;
  Resolution resolution; // as the file had it
  int width = 0;
  int height = 0;
  std::vector<Rgbe> pixels; // width * height, top row first, each row left to right

  const Rgbe& at(int x, int row) const { return pixels[std::size_t(row) * width + x]; }
  Rgbe& at(int x, int row) { return pixels[std::size_t(row) * width + x]; }
  std::vector<Color> colors() const; // to_color() of every pixel, same order
};

// Reads a whole picture, reoriented to top-down. Throws FatalError for any defect.
Picture read_picture(std::istream& in, const std::string& name);
Picture read_picture(const std::string& path);

// Writes `pixels` (width * height, top-down) as a standard "-Y h +X w" picture.
void write_picture(std::ostream& out, const PictureHeader& header, int width, int height,
                   std::span<const Rgbe> pixels);
void write_picture(const std::string& path, const PictureHeader& header, int width, int height,
                   std::span<const Rgbe> pixels);

// What rpict -r finds in an interrupted picture: its header, its resolution, and the complete
// scanlines at its start (file order). Throws FatalError if the file cannot be opened or has no
// valid header and resolution string ("bad recover file").
struct Salvage {
  PictureHeader header;
  Resolution resolution;
  int complete = 0;         // whole scanlines found
  std::vector<Rgbe> pixels; // complete * scanline_length()
};
Salvage salvage_picture(const std::string& path);

} // namespace radcl::image
