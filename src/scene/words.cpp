#include "words.h"

#include <cctype>
#include <climits>
#include <cstdlib>

namespace radcl::scene::detail {
namespace {

bool is_space(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Position after a [+-]digits run starting at i, or npos.
std::size_t skip_int(std::string_view s, std::size_t i) {
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  if (i >= s.size() || !is_digit(s[i])) return std::string_view::npos;
  while (i < s.size() && is_digit(s[i]))
    ++i;
  return i;
}

std::size_t skip_real(std::string_view s, std::size_t i) {
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t start = i;
  bool digits = false;
  while (i < s.size() && is_digit(s[i]))
    ++i, digits = true;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i]))
      ++i, digits = true;
  }
  if (!digits || i == start) return std::string_view::npos;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) return skip_int(s, i + 1);
  return i;
}

bool ends_ok(std::string_view s, std::size_t i, bool trailing_space) {
  if (i == std::string_view::npos) return false;
  if (trailing_space)
    while (i < s.size() && is_space(s[i]))
      ++i;
  return i == s.size();
}

std::size_t skip_space(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && is_space(s[i]))
    ++i;
  return i;
}

} // namespace

bool is_int_word(std::string_view s, bool trailing_space) {
  return ends_ok(s, skip_int(s, skip_space(s)), trailing_space);
}

bool is_real_word(std::string_view s, bool trailing_space) {
  return ends_ok(s, skip_real(s, skip_space(s)), trailing_space);
}

long long int_value(std::string_view s) {
  std::size_t i = skip_space(s);
  bool neg = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
  long long v = 0;
  for (; i < s.size() && is_digit(s[i]); ++i) {
    if (v > (LLONG_MAX - 9) / 10) return neg ? LLONG_MIN : LLONG_MAX;
    v = v * 10 + (s[i] - '0');
  }
  return neg ? -v : v;
}

// strtod is what atof is; radcl never changes LC_NUMERIC from "C".
double real_value(const std::string& s) {
  return std::strtod(s.c_str(), nullptr);
}

} // namespace radcl::scene::detail
