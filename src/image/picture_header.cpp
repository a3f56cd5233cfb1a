#include "radcl/image/picture_header.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "radcl/util/error.h"

namespace radcl::image {
namespace {

// Radiance's MAXLINE: fgets() into a 2048-byte buffer, one byte held back to avoid a false end.
constexpr std::size_t kMaxLineChars = 2046;

std::string printf_line(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
    s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
    s.remove_suffix(1);
  return s;
}

// fputword(): quote a word holding spaces, or quotes past its first character.
std::string quote_word(const std::string& w) {
  bool space = false;
  char quote = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const char c = w[i];
    if (std::isspace(static_cast<unsigned char>(c)))
      space = true;
    else if (i > 0 && c == '"' && i + 1 < w.size())
      quote = '\'';
    else if (i > 0 && c == '\'' && i + 1 < w.size())
      quote = '"';
  }
  if (!space && !quote) return w;
  if (!quote) quote = '"';
  return quote + w + quote;
}

} // namespace

bool is_variable_line(std::string_view line) {
  const auto eq = line.find('=');
  if (eq == 0 || eq == std::string_view::npos) return false;
  for (std::size_t i = 0; i < eq; ++i)
    if (std::isspace(static_cast<unsigned char>(line[i]))) return false;
  return !starts_with(line, "#?");
}

PictureHeader& PictureHeader::add(std::string line) {
  lines.push_back(std::move(line));
  return *this;
}

PictureHeader& PictureHeader::add_id(std::string_view id) {
  return add("#?" + std::string(id));
}

PictureHeader& PictureHeader::add_command(const std::vector<std::string>& argv) {
  std::string line;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    if (i) line += ' ';
    line += quote_word(argv[i]);
  }
  return add(std::move(line));
}

PictureHeader& PictureHeader::add_software(std::string_view s) {
  return add("SOFTWARE= " + std::string(s));
}

PictureHeader& PictureHeader::add_frame(int n) {
  return add("FRAME=" + std::to_string(n));
}

PictureHeader& PictureHeader::add_view(std::string_view v) {
  return add("VIEW=" + std::string(v));
}

PictureHeader& PictureHeader::add_exposure(double e) {
  return add(printf_line("EXPOSURE=%e", e));
}

PictureHeader& PictureHeader::add_pixaspect(double pa) {
  return add(printf_line("PIXASPECT=%f", pa));
}

PictureHeader& PictureHeader::add_dates(std::time_t t) {
  char buf[64];
  std::tm tm{};
  if (localtime_r(&t, &tm)) {
    std::strftime(buf, sizeof buf, "CAPDATE= %Y:%m:%d %H:%M:%S", &tm);
    add(buf);
  }
  if (gmtime_r(&t, &tm)) {
    std::strftime(buf, sizeof buf, "GMT= %Y:%m:%d %H:%M:%S", &tm);
    add(buf);
  }
  return *this;
}

PictureHeader& PictureHeader::add_primaries(const std::array<float, 8>& p) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "PRIMARIES= %.4f %.4f %.4f %.4f %.4f %.4f %.4f %.4f", p[0], p[1],
                p[2], p[3], p[4], p[5], p[6], p[7]);
  return add(buf);
}

PictureHeader& PictureHeader::add_format(PixelFormat f) {
  return add(f == PixelFormat::xyze ? "FORMAT=32-bit_rle_xyze" : "FORMAT=32-bit_rle_rgbe");
}

std::optional<std::string> PictureHeader::value(std::string_view name) const {
  std::optional<std::string> v;
  for (const auto& l : lines)
    if (l.size() > name.size() && starts_with(l, name) && l[name.size()] == '=')
      v = l.substr(name.size() + 1);
  return v;
}

std::string PictureHeader::format() const {
  // formatval(): the first word after "FORMAT=" and any spaces.
  const auto v = value("FORMAT");
  if (!v) return "";
  std::string_view s = trim(*v);
  return std::string(s.substr(0, s.find_first_of(" \t\r")));
}

std::optional<PixelFormat> PictureHeader::pixel_format() const {
  const std::string f = format();
  if (f.empty() || f == "32-bit_rle_rgbe") return PixelFormat::rgbe;
  if (f == "32-bit_rle_xyze") return PixelFormat::xyze;
  return std::nullopt;
}

double PictureHeader::exposure() const {
  double e = 1.0;
  for (const auto& l : lines)
    if (starts_with(l, "EXPOSURE=")) e *= std::atof(l.c_str() + 9);
  return e;
}

double PictureHeader::pixaspect() const {
  double a = 1.0;
  for (const auto& l : lines)
    if (starts_with(l, "PIXASPECT=")) a *= std::atof(l.c_str() + 10);
  return a;
}

std::array<double, 3> PictureHeader::colorcorr() const {
  std::array<double, 3> c{1.0, 1.0, 1.0};
  for (const auto& l : lines) {
    if (!starts_with(l, "COLORCORR=")) continue;
    std::istringstream in(l.substr(10));
    double r, g, b;
    if (in >> r >> g >> b) {
      c[0] *= r;
      c[1] *= g;
      c[2] *= b;
    }
  }
  return c;
}

std::optional<std::array<float, 8>> PictureHeader::primaries() const {
  const auto v = value("PRIMARIES");
  if (!v) return std::nullopt;
  std::istringstream in(*v);
  std::array<float, 8> p{};
  for (auto& x : p)
    if (!(in >> x)) return std::nullopt;
  return p;
}

std::vector<std::string> PictureHeader::views() const {
  std::vector<std::string> out;
  for (const auto& l : lines)
    if (starts_with(l, "VIEW=")) out.push_back(l.substr(5));
  return out;
}

std::string PictureHeader::software() const {
  const auto v = value("SOFTWARE");
  return v ? std::string(trim(*v)) : std::string();
}

std::optional<int> PictureHeader::frame() const {
  const auto v = value("FRAME");
  if (!v) return std::nullopt;
  return std::atoi(v->c_str());
}

std::string PictureHeader::id() const {
  if (lines.empty() || !starts_with(lines.front(), "#?")) return "";
  std::string_view s = std::string_view(lines.front()).substr(2);
  return std::string(s.substr(0, s.find_first_of(" \t\r")));
}

std::vector<std::string> PictureHeader::commands() const {
  std::vector<std::string> out;
  for (const auto& l : lines)
    if (!starts_with(l, "#?") && !is_variable_line(l)) out.push_back(l);
  return out;
}

void write_header(std::ostream& out, const PictureHeader& h) {
  for (const auto& l : h.lines) {
    out.write(l.data(), static_cast<std::streamsize>(l.size()));
    out.put('\n');
  }
  out.put('\n');
  if (!out) throw FatalError("write error on picture header");
}

PictureHeader read_header(std::istream& in, const std::string& name) {
  std::streambuf* sb = in.rdbuf();
  const int first = sb ? sb->sgetc() : EOF;
  if (first == EOF || !std::isprint(first))
    throw FatalError("bad header in \"" + name + "\": not a Radiance file");
  PictureHeader h;
  std::string line;
  for (;;) {
    const int c = sb->sbumpc();
    if (c == EOF) {
      in.setstate(std::ios::eofbit | std::ios::failbit);
      throw FatalError("unexpected end of header in \"" + name + "\"");
    }
    if (c == '\n') {
      if (line.empty() || line == "\r") return h;
      h.lines.push_back(std::move(line));
      line.clear();
      continue;
    }
    line.push_back(static_cast<char>(c));
    // Split long lines as Radiance's reader does; the rest never counts as an empty line.
    if (line.size() == kMaxLineChars && sb->sgetc() != '\n') {
      h.lines.push_back(std::move(line));
      line.clear();
    }
  }
}

} // namespace radcl::image
