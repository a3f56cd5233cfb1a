#include "radcl/ambient/format.h"

#include <cctype>
#include <cstdio>

#include "radcl/util/error.h"

namespace radcl::ambient {

std::optional<std::string> format_value(std::string_view line) {
  constexpr std::string_view kTag = "FORMAT=";
  if (line.substr(0, kTag.size()) != kTag) return std::nullopt;
  std::size_t i = kTag.size();
  while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
    ++i;
  if (i == line.size()) return std::nullopt;
  std::size_t j = i;
  while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])))
    ++j;
  return std::string(line.substr(i, j - i));
}

std::optional<HeaderSpan> read_header(std::string_view bytes) {
  if (bytes.empty() || !std::isprint(static_cast<unsigned char>(bytes[0]))) return std::nullopt;
  HeaderSpan h;
  std::size_t pos = 0;
  for (;;) {
    const std::size_t nl = bytes.find('\n', pos);
    if (nl == std::string_view::npos) return std::nullopt;
    std::string_view line = bytes.substr(pos, nl - pos);
    pos = nl + 1;
    if (line.empty() || line == "\r") break;
    h.header.add(std::string(line));
  }
  h.end = pos;
  return h;
}

std::string header_format(const image::PictureHeader& h) {
  std::string fmt;
  for (const auto& l : h.lines)
    if (auto v = format_value(l)) fmt = *v;
  return fmt;
}

AmbientContents parse_ambient(std::string_view bytes, const std::string& bad_message) {
  auto hs = read_header(bytes);
  if (!hs) throw FatalError(bad_message);
  const std::string fmt = header_format(hs->header);
  if (!fmt.empty() && fmt != kFormat) throw FatalError(bad_message);
  const std::size_t m = hs->end;
  if (bytes.size() < m + 2) throw FatalError(bad_message);
  const int magic =
      static_cast<unsigned char>(bytes[m]) << 8 | static_cast<unsigned char>(bytes[m + 1]);
  if (magic != kMagic) throw FatalError(bad_message);
  AmbientContents c;
  c.header = std::move(hs->header);
  c.data_start = m + 2;
  std::size_t pos = c.data_start;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  while (auto r = read_record(data + pos, bytes.size() - pos)) {
    c.records.push_back(*r);
    pos += kRecordSize;
  }
  c.valid_end = pos;
  return c;
}

image::PictureHeader new_file_header(const AmbientSettings& s) {
  image::PictureHeader h;
  h.add_id("RADIANCE");
  char buf[512];
  std::snprintf(buf, sizeof buf, "%s -av %g %g %g -aw %d -ab %d -aa %g -ad %d -as %d -ar %d ",
                s.progname.c_str(), s.av[0], s.av[1], s.av[2], s.aw, s.ab, s.aa, s.ad, s.as, s.ar);
  std::string cmd = buf;
  if (s.octree) cmd += *s.octree;
  h.add(std::move(cmd));
  h.add_software(s.software);
  h.add_dates(s.time);
  return h;
}

std::string file_prologue(const image::PictureHeader& h) {
  std::string out;
  for (const auto& l : h.lines) {
    if (format_value(l)) continue; // ours is the only FORMAT line
    out += l;
    out += '\n';
  }
  out += "FORMAT=";
  out += kFormat;
  out += "\n\n";
  out += static_cast<char>(kMagic >> 8);
  out += static_cast<char>(kMagic & 0xff);
  return out;
}

} // namespace radcl::ambient
