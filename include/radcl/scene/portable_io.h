// Radiance's portable binary encodings (octrees, meshes, ambient files): big-endian integers,
// 5-byte reals, NUL-terminated strings, and the text information header that precedes them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace radcl::scene {

// Appends `value` as an n-byte (1..8) big-endian two's-complement integer.
void put_int(std::string& out, std::int64_t value, int n);
// Decodes n bytes (1..8), sign-extending the first.
std::int64_t decode_int(const unsigned char* bytes, int n);

// Radiance's 5-byte real: 32-bit mantissa of frexp()'s fraction, 8-bit exponent.
void put_flt(std::string& out, double value);
double decode_flt(const unsigned char* bytes);

// Appends the bytes of `s` and a NUL.
void put_str(std::string& out, std::string_view s);

// Whole contents of a file, or of a command's standard output when `spec` starts with '!'
// (run by /bin/sh, as Radiance does). Throws FatalError("cannot open <what> \"<spec>\"").
std::string read_input_bytes(const std::string& spec, const std::string& what);

// Reads from an in-memory copy of a file. Every read that runs past the end throws
// FatalError("(<name>): <truncation message>").
class ByteReader {
public:
  ByteReader(std::string data, std::string name, std::string truncated = "truncated file");

  const std::string& name() const { return name_; }
  void set_truncation_message(std::string msg) { truncated_ = std::move(msg); }
  const std::string& truncation_message() const { return truncated_; }

  // Throws FatalError("(<name>): <msg>").
  [[noreturn]] void fail(const std::string& msg) const;
  [[noreturn]] void truncated() const { fail(truncated_); }

  bool at_end() const { return pos_ >= data_.size(); }
  std::size_t position() const { return pos_; }
  std::size_t remaining() const { return data_.size() - pos_; }

  int peek() const; // next byte or -1 at the end, like getc without consuming
  int get();        // next byte or -1 at the end
  std::uint8_t byte();
  std::int64_t getint(int n);
  double getflt();
  std::string getstr();
  // One header line without its '\n' (a final "\r" is kept); nullopt at the end of data
  // before a '\n'.
  std::optional<std::string> getline();

private:
  void need(std::size_t n) const;

  std::string data_;
  std::string name_;
  std::string truncated_;
  std::size_t pos_ = 0;
};

struct InfoHeader {
  std::vector<std::string> lines; // every line except FORMAT=, without '\n'
  std::string format;             // value of FORMAT=, "" if there was none
};

// Reads a Radiance information header up to and including its empty line. Returns nullopt
// where Radiance's getheader() fails: first byte not printable, or no empty line before EOF.
std::optional<InfoHeader> read_info_header(ByteReader& in);

} // namespace radcl::scene
