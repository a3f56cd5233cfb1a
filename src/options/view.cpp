#include "radcl/options/view.h"
#include "radcl/options/ray_io.h"

#include "cformat.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace radcl::options {
namespace {

constexpr double kFtiny = 1e-6;
constexpr double kPi = 3.14159265358979323846;

bool space(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// The view option at av[0], whose words may run on to the end of a header line (so a word ends
// at whitespace, not only at its terminating NUL), as getviewopt() sees them.
int view_option(View& v, int ac, const char* const* av) {
  if (ac <= 0 || av[0][0] != '-' || av[0][1] != 'v') return -1;
  // Nothing glued after the option letters; enough values of the right kind.
  auto ok = [&](int pos, int nreal) {
    if (av[0][pos] && !space(av[0][pos])) return false;
    if (ac - 1 < nreal) return false;
    for (int k = 1; k <= nreal; ++k)
      if (!is_finite_real(av[k], true)) return false;
    return true;
  };
  auto vec = [&](Vec3& out) {
    if (!ok(3, 3)) return -1;
    out = {std::atof(av[1]), std::atof(av[2]), std::atof(av[3])};
    return 3;
  };
  auto real = [&](double& out) {
    if (!ok(3, 1)) return -1;
    out = std::atof(av[1]);
    return 1;
  };
  switch (av[0][2]) {
  case 't':
    if (!av[0][3] || space(av[0][3]) || !ok(4, 0)) return -1;
    v.type = av[0][3];
    return 0;
  case 'p':
    return vec(v.point);
  case 'd': {
    int n = vec(v.direction);
    if (n >= 0) v.focal = 1.0;
    return n;
  }
  case 'u':
    return vec(v.up);
  case 'h':
    return real(v.horiz);
  case 'v':
    return real(v.vert);
  case 'o':
    return real(v.fore);
  case 'a':
    return real(v.aft);
  case 's':
    return real(v.shift);
  case 'l':
    return real(v.lift);
  default:
    return -1;
  }
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

} // namespace

int parse_view_option(View& v, const ArgList& args, std::size_t i) {
  std::vector<const char*> av;
  for (std::size_t k = i; k < args.size() && k < i + 4; ++k)
    av.push_back(args[k].c_str());
  return view_option(v, static_cast<int>(av.size()), av.data());
}

int scan_view_line(View& v, std::string_view line) {
  std::string buf(line); // NUL-terminated copy: options read to the end of the line
  const char* s = buf.c_str();
  while (space(*s))
    ++s;
  int nvopts = 0;
  while (*s) {
    const char* av[4];
    int ac = 0;
    do {
      if (ac || *s == '-') av[ac++] = s;
      while (*s && !space(*s))
        ++s;
      while (space(*s))
        ++s;
    } while (*s && ac < 4);
    int na = view_option(v, ac, av);
    if (na >= 0) {
      if (na + 1 < ac) s = av[na + 1];
      ++nvopts;
    } else if (ac > 1) {
      s = av[1];
    }
  }
  return nvopts;
}

bool is_view_line(std::string_view line, std::string_view progname) {
  auto base = [](std::string_view p) {
    std::size_t slash = p.find_last_of('/');
    return slash == std::string_view::npos ? p : p.substr(slash + 1);
  };
  std::size_t end = 0;
  while (end < line.size() && !space(line[end]))
    ++end;
  std::string_view word = line.substr(0, end);
  std::size_t slash = word.find_last_of('/');
  std::string_view rest = slash == std::string_view::npos ? line : line.substr(slash + 1);
  const std::string_view names[] = {base(progname), "VIEW=",  "rpict",  "rview",
                                    "rvu",          "rpiece", "pinterp"};
  for (std::string_view n : names)
    if (rest.substr(0, n.size()) == n) return true;
  return false;
}

std::string format_view(const View& v) {
  return cformat(" -vt%c -vp %.6g %.6g %.6g -vd %.6g %.6g %.6g -vu %.6g %.6g %.6g -vh %.6g -vv "
                 "%.6g -vo %.6g -va %.6g -vs %.6g -vl %.6g",
                 v.type, v.point[0], v.point[1], v.point[2], v.direction[0] * v.focal,
                 v.direction[1] * v.focal, v.direction[2] * v.focal, v.up[0], v.up[1], v.up[2],
                 v.horiz, v.vert, v.fore, v.aft, v.shift, v.lift);
}

std::string setup_view(View& v) {
  const char* ill_horiz = "illegal horizontal view size";
  const char* ill_vert = "illegal vertical view size";
  if (v.fore < -kFtiny || v.aft < -kFtiny || (v.aft > kFtiny && v.aft <= v.fore))
    return "illegal fore/aft clipping plane";
  if (v.focal <= kFtiny) return "illegal view distance";
  v.focal *= normalize_direction(v.direction);
  if (v.focal == 0.0) return "zero view direction";
  if (normalize_direction(v.up) == 0.0) return "zero view up vector";
  v.hvec = cross(v.direction, v.up);
  if (normalize_direction(v.hvec) == 0.0) return "view up parallel to view direction";
  v.vvec = cross(v.hvec, v.direction);
  if (v.horiz <= kFtiny) return ill_horiz;
  if (v.vert <= kFtiny) return ill_vert;
  const double half = kPi / 180.0 / 2.0;
  switch (v.type) {
  case 'l':
    v.hn2 = v.horiz;
    v.vn2 = v.vert;
    break;
  case 'v':
    if (v.horiz >= 180.0 - kFtiny) return ill_horiz;
    if (v.vert >= 180.0 - kFtiny) return ill_vert;
    v.hn2 = 2.0 * std::tan(v.horiz * half);
    v.vn2 = 2.0 * std::tan(v.vert * half);
    break;
  case 'c':
    if (v.horiz > 360.0 + kFtiny) return ill_horiz;
    if (v.vert >= 180.0 - kFtiny) return ill_vert;
    v.hn2 = v.horiz * (kPi / 180.0);
    v.vn2 = 2.0 * std::tan(v.vert * half);
    break;
  case 'a':
    if (v.horiz > 360.0 + kFtiny) return ill_horiz;
    if (v.vert > 360.0 + kFtiny) return ill_vert;
    v.hn2 = v.horiz * (kPi / 180.0);
    v.vn2 = v.vert * (kPi / 180.0);
    break;
  case 'h':
    if (v.horiz > 180.0 + kFtiny) return ill_horiz;
    if (v.vert > 180.0 + kFtiny) return ill_vert;
    v.hn2 = 2.0 * std::sin(v.horiz * half);
    v.vn2 = 2.0 * std::sin(v.vert * half);
    break;
  case 's':
    if (v.horiz >= 360.0 - kFtiny) return ill_horiz;
    if (v.vert >= 360.0 - kFtiny) return ill_vert;
    v.hn2 = 2. * std::sin(v.horiz * half) / (1.0 + std::cos(v.horiz * half));
    v.vn2 = 2. * std::sin(v.vert * half) / (1.0 + std::cos(v.vert * half));
    break;
  default:
    return "unknown view type";
  }
  if (v.type != 'a' && v.type != 's') {
    if (v.type != 'c')
      for (double& c : v.hvec)
        c *= v.hn2;
    for (double& c : v.vvec)
      c *= v.vn2;
  }
  v.hn2 *= v.hn2;
  v.vn2 *= v.vn2;
  return "";
}

} // namespace radcl::options
