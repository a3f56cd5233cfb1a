#include "radcl/ambient/record.h"

#include <cmath>

#include "radcl/image/rgbe.h"

namespace radcl::ambient {
namespace {

constexpr double kHuge = 1e10; // FHUGE
constexpr double kTiny = 1e-6; // FTINY

void put_int(unsigned char*& p, std::uint32_t v, int n) {
  for (int i = n - 1; i >= 0; --i)
    *p++ = static_cast<unsigned char>(v >> (8 * i) & 0xff);
}

std::int32_t get_int4(const unsigned char*& p) {
  const std::uint32_t u = std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 |
                          std::uint32_t{p[2]} << 8 | std::uint32_t{p[3]};
  p += 4;
  return static_cast<std::int32_t>(u);
}

// putflt(): frexp()'s fraction times 0x7fffffff, truncated, and the exponent in one byte.
void put_real(unsigned char*& p, double v) {
  std::int64_t m = 0;
  int e = 0;
  if (std::isfinite(v)) {
    m = static_cast<std::int64_t>(std::frexp(v, &e) * 2147483647.0);
    if (e > 127) {
      m = m > 0 ? 2147483647 : -2147483647;
      e = 127;
    } else if (e < -128) {
      m = 0;
      e = 0;
    }
  } // non-finite values never reach a file (record_writable); write 0 rather than garbage
  put_int(p, static_cast<std::uint32_t>(m), 4);
  put_int(p, static_cast<std::uint32_t>(e), 1);
}

// getflt(): the mantissa's interval centre; computed exactly as Radiance does (times the
// reciprocal) so that the float it rounds to is the same.
double get_real(const unsigned char*& p) {
  const std::int64_t m = get_int4(p);
  const int e = static_cast<signed char>(*p++);
  if (m == 0) return 0.0;
  const double d = (static_cast<double>(m) + 0.5 - (m < 0 ? 1 : 0)) * (1.0 / 2147483647.0);
  return std::ldexp(d, e);
}

bool bad(double x) {
  return x < -kHuge || x > kHuge;
}

bool bad_colour(double c) {
  return c < 0.0 || c >= kHuge;
}

} // namespace

RecordBytes encode_record(const AmbientRecord& r) {
  RecordBytes b{};
  unsigned char* p = b.data();
  *p++ = static_cast<unsigned char>(r.lvl & 0xff);
  put_real(p, r.weight);
  for (float x : r.pos)
    put_real(p, x);
  put_int(p, static_cast<std::uint32_t>(r.ndir), 4);
  put_int(p, static_cast<std::uint32_t>(r.udir), 4);
  for (std::uint8_t c : image::to_rgbe(r.val[0], r.val[1], r.val[2]))
    *p++ = c;
  for (float x : r.rad)
    put_real(p, x);
  for (float x : r.gpos)
    put_real(p, x);
  for (float x : r.gdir)
    put_real(p, x);
  put_int(p, r.corral, 4);
  return b;
}

AmbientRecord decode_record(const unsigned char* bytes) {
  const unsigned char* p = bytes;
  AmbientRecord r;
  r.lvl = static_cast<std::int16_t>(*p++);
  r.weight = static_cast<float>(get_real(p));
  for (float& x : r.pos)
    x = static_cast<float>(get_real(p));
  r.ndir = get_int4(p);
  r.udir = get_int4(p);
  r.val = image::to_color({p[0], p[1], p[2], p[3]});
  p += 4;
  for (float& x : r.rad)
    x = static_cast<float>(get_real(p));
  for (float& x : r.gpos)
    x = static_cast<float>(get_real(p));
  for (float& x : r.gdir)
    x = static_cast<float>(get_real(p));
  r.corral = static_cast<std::uint32_t>(get_int4(p));
  return r;
}

bool record_ok(const AmbientRecord& r) {
  if (bad(r.pos[0]) || bad(r.pos[1]) || bad(r.pos[2])) return false;
  if (!r.ndir || !r.udir) return false;
  if (r.weight <= 0.0f || r.weight > 1.0f) return false;
  for (float x : r.rad)
    if (x <= 0.0f || x >= kHuge) return false;
  if (r.rad[0] > r.rad[1] + kTiny) return false;
  for (float c : r.val)
    if (bad_colour(c)) return false;
  if (bad(r.gpos[0]) || bad(r.gpos[1]) || bad(r.gdir[0]) || bad(r.gdir[1])) return false;
  return true;
}

bool record_writable(const AmbientRecord& r) {
  auto finite = [](const auto& a) {
    for (float x : a)
      if (!std::isfinite(x)) return false;
    return true;
  };
  if (!finite(r.pos) || !finite(r.rad) || !finite(r.val) || !finite(r.gpos) || !finite(r.gdir) ||
      !std::isfinite(r.weight))
    return false;
  return record_ok(decode_record(encode_record(r).data()));
}

std::optional<AmbientRecord> read_record(const unsigned char* bytes, std::size_t n) {
  if (n < kRecordSize) return std::nullopt;
  AmbientRecord r = decode_record(bytes);
  if (!record_ok(r)) return std::nullopt;
  return r;
}

} // namespace radcl::ambient
