#include "radcl/ambient/text.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "radcl/ambient/dircode.h"

namespace radcl::ambient {
namespace {

void append(std::string& out, const char* fmt, auto... args) {
  char buf[256];
  const int n = std::snprintf(buf, sizeof buf, fmt, args...);
  out.append(buf, static_cast<std::size_t>(n));
}

// Whitespace-separated words, as scanf's conversions see them.
class Words {
public:
  explicit Words(std::string_view s) : s_(s) {}

  std::optional<std::string> next() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_])))
      ++pos_;
    if (pos_ == s_.size()) return std::nullopt;
    const std::size_t start = pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_])))
      ++pos_;
    return std::string(s_.substr(start, pos_ - start));
  }

  void skip() { next(); } // "%*s"

  // Each conversion must take its whole word; otherwise reading stops.
  bool get(float& v) {
    return convert([&](const char* b, char** e) { v = std::strtof(b, e); });
  }
  bool get(double& v) {
    return convert([&](const char* b, char** e) { v = std::strtod(b, e); });
  }
  bool get(std::int16_t& v) {
    return convert(
        [&](const char* b, char** e) { v = static_cast<std::int16_t>(std::strtol(b, e, 10)); });
  }
  bool get(std::uint32_t& v, int base) {
    return convert(
        [&](const char* b, char** e) { v = static_cast<std::uint32_t>(std::strtoul(b, e, base)); });
  }

private:
  template <class F> bool convert(F f) {
    auto w = next();
    if (!w) return false;
    char* end = nullptr;
    f(w->c_str(), &end);
    return end != w->c_str() && *end == '\0';
  }

  std::string_view s_;
  std::size_t pos_ = 0;
};

} // namespace

std::string format_record(const AmbientRecord& r, bool data_only) {
  const Dir n = decode_dir(r.ndir);
  const Dir u = decode_dir(r.udir);
  const double px = r.pos[0], py = r.pos[1], pz = r.pos[2];
  const double wt = r.weight, r0 = r.rad[0], r1 = r.rad[1];
  const double vr = r.val[0], vg = r.val[1], vb = r.val[2];
  const double gp0 = r.gpos[0], gp1 = r.gpos[1], gd0 = r.gdir[0], gd1 = r.gdir[1];
  const int lvl = r.lvl;
  std::string out;
  if (data_only) {
    append(out, "%f\t%f\t%f\t", px, py, pz);
    append(out, "%f\t%f\t%f\t", n[0], n[1], n[2]);
    append(out, "%f\t%f\t%f\t", u[0], u[1], u[2]);
    append(out, "%d\t%f\t%f\t%f\t", lvl, wt, r0, r1);
    append(out, "%e\t%e\t%e\t", vr, vg, vb);
    append(out, "%f\t%f\t", gp0, gp1);
    append(out, "%f\t%f\t", gd0, gd1);
    append(out, "%u\n", static_cast<unsigned>(r.corral));
  } else {
    append(out, "Position:\t%f\t%f\t%f\n", px, py, pz);
    append(out, "Normal:\t\t%f\t%f\t%f\n", n[0], n[1], n[2]);
    append(out, "Uvector:\t%f\t%f\t%f\n", u[0], u[1], u[2]);
    append(out, "Lvl,Wt,UVrad:\t%d\t\t%f\t%f\t%f\n", lvl, wt, r0, r1);
    append(out, "Value:\t\t%e\t%e\t%e\n", vr, vg, vb);
    append(out, "Pos.Grad:\t%f\t%f\n", gp0, gp1);
    append(out, "Dir.Grad:\t%f\t%f\n", gd0, gd1);
    append(out, "Corral:\t\t%8X\n\n", static_cast<unsigned>(r.corral));
  }
  return out;
}

std::vector<AmbientRecord> parse_records(std::string_view text, bool data_only) {
  std::vector<AmbientRecord> out;
  Words in(text);
  auto label = [&] {
    if (!data_only) in.skip();
  };
  for (;;) {
    AmbientRecord r;
    Dir d{};
    label();
    if (!(in.get(r.pos[0]) && in.get(r.pos[1]) && in.get(r.pos[2]))) break;
    label();
    if (!(in.get(d[0]) && in.get(d[1]) && in.get(d[2]))) break;
    r.ndir = encode_dir(d);
    label();
    if (!(in.get(d[0]) && in.get(d[1]) && in.get(d[2]))) break;
    r.udir = encode_dir(d);
    label();
    if (!(in.get(r.lvl) && in.get(r.weight) && in.get(r.rad[0]) && in.get(r.rad[1]))) break;
    label();
    if (!(in.get(r.val[0]) && in.get(r.val[1]) && in.get(r.val[2]))) break;
    label();
    if (!(in.get(r.gpos[0]) && in.get(r.gpos[1]))) break;
    label();
    if (!(in.get(r.gdir[0]) && in.get(r.gdir[1]))) break;
    label();
    if (!in.get(r.corral, data_only ? 10 : 16)) break;
    out.push_back(r);
  }
  return out;
}

} // namespace radcl::ambient
