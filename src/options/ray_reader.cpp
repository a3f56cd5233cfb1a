// rtrace's ray input: 6 numbers per ray in ascii words or host-order binary.
#include "radcl/options/ray_io.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace radcl::options {
namespace {
constexpr double kFtiny = 1e-6;
constexpr std::size_t kMaxWord = 31; // Radiance reads words into a 32-byte buffer
using Traits = std::char_traits<char>;
bool space(int c) {
  return c != Traits::eof() && std::isspace(c);
}
} // namespace

double normalize_direction(Vec3& v) {
  double d = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  if (d == 0.0) return 0.0;
  double len;
  if (d <= 1.0 + kFtiny && d >= 1.0 - kFtiny) { // Radiance's first-order shortcut
    len = 0.5 + 0.5 * d;
    d = 2.0 - len;
  } else {
    len = std::sqrt(d);
    d = 1.0 / len;
  }
  for (double& c : v)
    c *= d;
  return len;
}

// Radiance's fgetword(): skips whitespace, honours one level of quotes, stops at 31
// characters (the rest becomes the next word).
bool RayReader::read_word(std::string& w) {
  std::streambuf* sb = in_.rdbuf();
  w.clear();
  int c;
  do
    c = sb->sbumpc();
  while (space(c));
  int quote = 0;
  if (c == '"' || c == '\'') {
    quote = c;
    c = sb->sbumpc();
  }
  while (c != Traits::eof() && !(quote ? c == quote : space(c))) {
    if (w.size() >= kMaxWord) break;
    w.push_back(static_cast<char>(c));
    c = sb->sbumpc();
  }
  if (c == Traits::eof()) return !w.empty();
  if (!quote) sb->sungetc();
  return true;
}

bool RayReader::read_vec(Vec3& v) {
  switch (format_) {
  case 'a': {
    std::string w;
    for (double& c : v) {
      if (!read_word(w) || !is_real(w)) return false;
      c = std::atof(w.c_str());
    }
    return true;
  }
  case 'f': {
    float f[3];
    if (in_.rdbuf()->sgetn(reinterpret_cast<char*>(f), sizeof f) != sizeof f) return false;
    v = {f[0], f[1], f[2]};
    return true;
  }
  case 'd': {
    double d[3];
    if (in_.rdbuf()->sgetn(reinterpret_cast<char*>(d), sizeof d) != sizeof d) return false;
    v = {d[0], d[1], d[2]};
    return true;
  }
  }
  return false;
}

bool RayReader::read(Vec3& origin, Vec3& direction) {
  return read_vec(origin) && read_vec(direction);
}

} // namespace radcl::options
