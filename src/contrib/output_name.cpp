// Output names from -o specs, as Radiance's ofname().
#include "radcl/contrib/output.h"

#include <cctype>
#include <cstdio>
#include <utility>

namespace radcl::contrib {
namespace {

// One printf conversion ("%03d"), formatted by the C library so that width digits (and a
// leading 0 flag) mean exactly what they do in Radiance's sprintf() of the whole spec.
template <class T> std::string convert(const std::string& conversion, T value) {
  const int n = std::snprintf(nullptr, 0, conversion.c_str(), value);
  if (n <= 0) return {};
  std::string s(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(s.data(), s.size(), conversion.c_str(), value);
  s.resize(static_cast<std::size_t>(n));
  return s;
}

} // namespace

int output_name(const std::string& spec, const std::string& modifier, int bin, std::string& name) {
  int flags = 0;
  std::string out;
  for (std::size_t k = 0; k < spec.size(); ++k) {
    if (spec[k] != '%') {
      out += spec[k];
      continue;
    }
    std::size_t end = k + 1;
    while (end < spec.size() && std::isdigit(static_cast<unsigned char>(spec[end])))
      ++end;
    if (end == spec.size()) return -1; // a '%' at the end
    const std::string conversion = spec.substr(k, end - k + 1);
    switch (spec[end]) {
    case '%':
      out += convert(conversion, 0); // "%%" (the unused argument is harmless)
      break;
    case 's':
      if (flags & kNamesModifier) return -1;
      flags |= kNamesModifier;
      out += convert(conversion, modifier.c_str());
      break;
    case 'd':
    case 'i':
    case 'o':
    case 'x':
    case 'X':
      if (flags & kNamesBin) return -1;
      flags |= kNamesBin;
      out += convert(conversion, bin);
      break;
    default:
      return -1;
    }
    k = end;
  }
  name = std::move(out);
  return flags;
}

} // namespace radcl::contrib
