#include "radcl/image/picture.h"

#include <fstream>

#include "radcl/image/scanline.h"
#include "radcl/util/error.h"

namespace radcl::image {
namespace {

// Refuse sizes no real picture has before allocating for them (a corrupt resolution string
// must give a clear error, not an allocation failure).
constexpr long long kMaxPixels = 1LL << 31;

void check_size(const Resolution& r, const std::string& name) {
  if (static_cast<long long>(r.xres) * r.yres > kMaxPixels)
    throw FatalError("picture \"" + name + "\" too large: " + r.to_string().substr(0, 40));
}

} // namespace

PictureWriter::PictureWriter(std::ostream& out, const PictureHeader& header, const Resolution& res)
    : out_(out), res_(res) {
  write_header(out_, header);
  write_resolution(out_, res_);
}

PictureWriter::PictureWriter(std::ostream& out, const Resolution& res) : out_(out), res_(res) {}

void PictureWriter::write_scanline(std::span<const Rgbe> pixels) {
  if (static_cast<int>(pixels.size()) != res_.scanline_length())
    throw FatalError("internal error: scanline of " + std::to_string(pixels.size()) +
                     " pixels for a picture " + std::to_string(res_.scanline_length()) + " wide");
  buf_.clear();
  encode_scanline(pixels, buf_);
  out_.write(reinterpret_cast<const char*>(buf_.data()), static_cast<std::streamsize>(buf_.size()));
  if (!out_) throw FatalError("write error on picture");
  ++written_;
}

void PictureWriter::write_scanline(std::span<const Color> pixels) {
  conv_.resize(pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i)
    conv_[i] = to_rgbe(pixels[i]);
  write_scanline(std::span<const Rgbe>(conv_));
}

void PictureWriter::flush() {
  out_.flush();
  if (!out_) throw FatalError("write error on picture");
}

PictureReader::PictureReader(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {
  header_ = read_header(in_, name_);
  if (!header_.pixel_format())
    throw FatalError("\"" + name_ + "\" is not a Radiance picture (FORMAT=" + header_.format() +
                     ")");
  res_ = read_resolution(in_, name_);
  check_size(res_, name_);
}

bool PictureReader::try_read_scanline(std::span<Rgbe> pixels) {
  if (read_ >= res_.num_scanlines() || static_cast<int>(pixels.size()) != res_.scanline_length())
    return false;
  if (decode_scanline(*in_.rdbuf(), pixels) != ScanStatus::ok) return false;
  ++read_;
  return true;
}

void PictureReader::read_scanline(std::span<Rgbe> pixels) {
  const int total = res_.num_scanlines();
  if (read_ >= total) throw FatalError("read past the last scanline of \"" + name_ + "\"");
  if (static_cast<int>(pixels.size()) != res_.scanline_length())
    throw FatalError("internal error: wrong scanline length for \"" + name_ + "\"");
  switch (decode_scanline(*in_.rdbuf(), pixels)) {
  case ScanStatus::ok:
    ++read_;
    return;
  case ScanStatus::truncated:
    throw FatalError("picture \"" + name_ + "\" truncated: " + std::to_string(read_) + " of " +
                     std::to_string(total) + " scanlines complete");
  case ScanStatus::corrupt:
    break;
  }
  throw FatalError("bad scanline encoding in picture \"" + name_ + "\" (scanline " +
                   std::to_string(read_ + 1) + " of " + std::to_string(total) + ")");
}

std::vector<Color> Picture::colors() const {
  std::vector<Color> out(pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i)
    out[i] = to_color(pixels[i]);
  return out;
}

Picture read_picture(std::istream& in, const std::string& name) {
  PictureReader reader(in, name);
  Picture pic;
  pic.header = reader.header();
  pic.resolution = reader.resolution();
  const Resolution& r = pic.resolution;
  pic.width = r.xres;
  pic.height = r.yres;
  // Storage grows with the scanlines actually decoded, so a damaged or truncated file that
  // claims a huge resolution fails without first allocating for all of it.
  const std::size_t len = static_cast<std::size_t>(r.scanline_length());
  std::vector<Rgbe> file_order; // scanlines as the file has them
  for (int s = 0; s < r.num_scanlines(); ++s) {
    file_order.resize(file_order.size() + len);
    reader.read_scanline(std::span<Rgbe>(file_order).subspan(file_order.size() - len, len));
  }
  if (r.is_standard()) { // already top-down, left to right
    pic.pixels = std::move(file_order);
    return pic;
  }
  pic.pixels.resize(file_order.size());
  for (int s = 0; s < r.num_scanlines(); ++s)
    for (int p = 0; p < r.scanline_length(); ++p) {
      int col, row;
      r.to_top_down(s, p, col, row);
      pic.at(col, row) = file_order[std::size_t(s) * len + p];
    }
  return pic;
}

Picture read_picture(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FatalError("cannot open picture \"" + path + "\"");
  return read_picture(in, path);
}

void write_picture(std::ostream& out, const PictureHeader& header, int width, int height,
                   std::span<const Rgbe> pixels) {
  if (pixels.size() != static_cast<std::size_t>(width) * height)
    throw FatalError("internal error: pixel count does not match the picture size");
  PictureWriter w(out, header, Resolution::standard(width, height));
  for (int y = 0; y < height; ++y)
    w.write_scanline(pixels.subspan(std::size_t(y) * width, width));
  w.flush();
}

void write_picture(const std::string& path, const PictureHeader& header, int width, int height,
                   std::span<const Rgbe> pixels) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw FatalError("cannot open picture \"" + path + "\" for writing");
  write_picture(out, header, width, height, pixels);
  out.close();
  if (!out) throw FatalError("write error on picture \"" + path + "\"");
}

Salvage salvage_picture(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FatalError("cannot open recover file \"" + path + "\"");
  Salvage s;
  try {
    PictureReader reader(in, path);
    s.header = reader.header();
    s.resolution = reader.resolution();
    const std::size_t len = s.resolution.scanline_length();
    std::vector<Rgbe> line(len);
    while (reader.try_read_scanline(line))
      s.pixels.insert(s.pixels.end(), line.begin(), line.end());
    s.complete = reader.scanlines_read();
  } catch (const FatalError&) {
    throw FatalError("bad recover file \"" + path + "\"");
  }
  return s;
}

} // namespace radcl::image
