// One rtrace record in bytes: %e text, host-order float/double, or RGBE.
#include "radcl/options/ray_io.h"

#include "cformat.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace radcl::options {

RayOutput RayOutput::empty(const Vec3& origin, const Vec3& direction) {
  RayOutput r;
  r.origin = origin;
  r.direction = direction;
  r.point = origin;
  return r;
}

void RayOutput::derive_unmirrored() {
  for (int k = 0; k < 3; ++k)
    unmirrored[k] = static_cast<float>(value[k]) - static_cast<float>(mirrored[k]);
}

std::array<unsigned char, 4> to_rgbe(double r, double g, double b) {
  double d = r > g ? r : g;
  if (b > d) d = b;
  if (d <= 1e-32) return {0, 0, 0, 0};
  int e;
  d = std::frexp(d, &e) * 256.0 / d;
  auto mant = [d](double c) { return static_cast<unsigned char>(c > 0.0 ? c * d : 0.0); };
  return {mant(r), mant(g), mant(b), static_cast<unsigned char>(e + 128)};
}

namespace {

void put_reals(std::string& out, const double* v, int n, char format) {
  switch (format) {
  case 'a':
    for (int k = 0; k < n; ++k)
      out += cformat("%e\t", v[k]);
    break;
  case 'f':
    for (int k = 0; k < n; ++k) {
      float f = static_cast<float>(v[k]);
      out.append(reinterpret_cast<const char*>(&f), sizeof f);
    }
    break;
  case 'd':
    out.append(reinterpret_cast<const char*>(v), sizeof(double) * static_cast<std::size_t>(n));
    break;
  case 'c': {
    if (n != 3) throw std::logic_error("RGBE output of a value that is not a colour");
    auto c = to_rgbe(v[0], v[1], v[2]);
    out.append(reinterpret_cast<const char*>(c.data()), c.size());
    break;
  }
  default:
    throw std::logic_error("bad output format");
  }
}

void put_name(std::string& out, const std::string& name) {
  out += name;
  out += '\t';
}

} // namespace

void append_record(std::string& out, std::string_view letters, const RayOutput& r, char format,
                   int depth) {
  out.append(static_cast<std::size_t>(depth), '\t');
  for (char c : letters) {
    switch (c) {
    case 'o':
      put_reals(out, r.origin.data(), 3, format);
      break;
    case 'd':
      put_reals(out, r.direction.data(), 3, format);
      break;
    case 'v':
      put_reals(out, r.value.data(), 3, format);
      break;
    case 'V':
      put_reals(out, r.contribution.data(), 3, format);
      break;
    case 'w':
      put_reals(out, &r.weight, 1, format);
      break;
    case 'W':
      put_reals(out, r.coefficient.data(), 3, format);
      break;
    case 'l':
      put_reals(out, &r.effective_length, 1, format);
      break;
    case 'L':
      put_reals(out, &r.first_length, 1, format);
      break;
    case 'c': {
      const double uv[2] = {r.u, r.v};
      put_reals(out, uv, 2, format);
      break;
    }
    case 'p':
      put_reals(out, r.point.data(), 3, format);
      break;
    case 'n':
      put_reals(out, r.normal.data(), 3, format);
      break;
    case 'N':
      put_reals(out, r.unperturbed_normal.data(), 3, format);
      break;
    case 's':
      put_name(out, r.surface);
      break;
    case 'm':
      put_name(out, r.modifier);
      break;
    case 'M':
      put_name(out, r.material);
      break;
    case 'r':
      put_reals(out, r.mirrored.data(), 3, format);
      break;
    case 'x':
      put_reals(out, r.unmirrored.data(), 3, format);
      break;
    case 'R':
      put_reals(out, &r.mirrored_length, 1, format);
      break;
    case 'X':
      put_reals(out, &r.unmirrored_length, 1, format);
      break;
    case 'e':
      put_reals(out, r.std_error.data(), 3, format);
      break;
    case '~':
      out += "~\t";
      break;
    default:
      throw std::logic_error(std::string("bad output letter ") + c);
    }
  }
  if (format == 'a') out += '\n';
}

} // namespace radcl::options
