#include "radcl/scene/portable_io.h"
#include "radcl/scene/command.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "radcl/util/error.h"

namespace radcl::scene {

void put_int(std::string& out, std::int64_t value, int n) {
  const auto u = static_cast<std::uint64_t>(value);
  for (int i = n - 1; i >= 0; --i)
    out.push_back(static_cast<char>((u >> (8 * i)) & 0xff));
}

std::int64_t decode_int(const unsigned char* bytes, int n) {
  // Start from the sign of the first byte so that short integers are sign-extended.
  std::int64_t r = static_cast<std::int8_t>(bytes[0]);
  for (int i = 1; i < n; ++i)
    r = static_cast<std::int64_t>(static_cast<std::uint64_t>(r) << 8 | bytes[i]);
  return r;
}

void put_flt(std::string& out, double value) {
  constexpr double kScale = 2147483647.0; // 0x7fffffff
  std::int64_t m = 0;
  int e = 0;
  if (std::isnan(value)) {
    m = 0;
  } else if (std::isinf(value)) {
    m = value > 0 ? 2147483647 : -2147483647;
    e = 127;
  } else {
    const double frac = std::frexp(value, &e);
    m = static_cast<std::int64_t>(frac * kScale); // truncates toward zero, as C's (long)
    if (e > 127) {
      m = m > 0 ? 2147483647 : -2147483647;
      e = 127;
    } else if (e < -128) {
      m = 0;
      e = 0;
    }
  }
  put_int(out, m, 4);
  put_int(out, e, 1);
}

double decode_flt(const unsigned char* bytes) {
  const std::int64_t m = decode_int(bytes, 4);
  if (m == 0) return 0.0;
  const int e = static_cast<std::int8_t>(bytes[4]);
  // Half-LSB reconstruction: the writer truncated toward zero.
  const double mm = static_cast<double>(m) + (m < 0 ? -0.5 : 0.5);
  return std::ldexp(mm / 2147483647.0, e);
}

void put_str(std::string& out, std::string_view s) {
  out.append(s);
  out.push_back('\0');
}

std::string read_input_bytes(const std::string& spec, const std::string& what) {
  if (!spec.empty() && spec[0] == '!') {
    std::FILE* p = open_command(spec.substr(1));
    if (!p) throw FatalError("cannot open " + what + " \"" + spec + "\"");
    std::string data;
    char buf[65536];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0)
      data.append(buf, n);
    ::pclose(p);
    return data;
  }
  std::error_code ec;
  if (std::filesystem::is_directory(spec, ec)) // opens, then fails on the first read
    throw FatalError("cannot open " + what + " \"" + spec + "\": a directory");
  std::ifstream f(spec, std::ios::binary);
  if (!f) throw FatalError("cannot open " + what + " \"" + spec + "\"");
  std::ostringstream ss;
  ss << f.rdbuf();
  if (f.bad()) throw FatalError("read error on " + what + " \"" + spec + "\"");
  return std::move(ss).str();
}

ByteReader::ByteReader(std::string data, std::string name, std::string truncated)
    : data_(std::move(data)), name_(std::move(name)), truncated_(std::move(truncated)) {}

void ByteReader::fail(const std::string& msg) const {
  throw FatalError("(" + name_ + "): " + msg);
}

void ByteReader::need(std::size_t n) const {
  if (remaining() < n) truncated();
}

int ByteReader::peek() const {
  return at_end() ? -1 : static_cast<unsigned char>(data_[pos_]);
}

int ByteReader::get() {
  return at_end() ? -1 : static_cast<unsigned char>(data_[pos_++]);
}

std::uint8_t ByteReader::byte() {
  need(1);
  return static_cast<std::uint8_t>(data_[pos_++]);
}

std::int64_t ByteReader::getint(int n) {
  need(static_cast<std::size_t>(n));
  const auto* p = reinterpret_cast<const unsigned char*>(data_.data() + pos_);
  pos_ += static_cast<std::size_t>(n);
  return decode_int(p, n);
}

double ByteReader::getflt() {
  need(5);
  const auto* p = reinterpret_cast<const unsigned char*>(data_.data() + pos_);
  pos_ += 5;
  return decode_flt(p);
}

std::string ByteReader::getstr() {
  const auto end = data_.find('\0', pos_);
  if (end == std::string::npos) truncated();
  std::string s = data_.substr(pos_, end - pos_);
  pos_ = end + 1;
  return s;
}

std::optional<std::string> ByteReader::getline() {
  const auto end = data_.find('\n', pos_);
  if (end == std::string::npos) return std::nullopt;
  std::string s = data_.substr(pos_, end - pos_);
  pos_ = end + 1;
  return s;
}

namespace {

// Radiance's formatval(): "FORMAT=" then optional white space, value up to white space.
// A FORMAT= line with no value is an ordinary header line.
std::optional<std::string> format_value(const std::string& line) {
  constexpr std::string_view kTag = "FORMAT=";
  if (line.compare(0, kTag.size(), kTag) != 0) return std::nullopt;
  std::size_t i = kTag.size();
  while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
    ++i;
  if (i == line.size()) return std::nullopt;
  std::size_t j = i;
  while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])))
    ++j;
  return line.substr(i, j - i);
}

} // namespace

std::optional<InfoHeader> read_info_header(ByteReader& in) {
  const int first = in.peek();
  if (first < 0 || !std::isprint(first)) return std::nullopt;
  InfoHeader h;
  for (;;) {
    auto line = in.getline();
    if (!line) return std::nullopt;
    if (line->empty() || *line == "\r") return h;
    if (auto fmt = format_value(*line))
      h.format = *fmt;
    else
      h.lines.push_back(std::move(*line));
  }
}

} // namespace radcl::scene
