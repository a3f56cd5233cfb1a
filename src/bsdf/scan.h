// Number scanning shared by the readers of Klems matrices and tensor trees (private to bsdf).
#pragma once

#include <charconv>
#include <cmath>
#include <string_view>

namespace radcl::bsdf::detail {

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

inline size_t skip_space(std::string_view s, size_t i) {
  while (i < s.size() && is_space(s[i]))
    ++i;
  return i;
}

inline bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Reads a finite real at s[i] in Radiance's syntax, [+-]digits[.digits][(e|E)[+-]digits] with a
// digit on one side of the point; returns the index after it, or npos (no number there, or one
// that overflows).
inline size_t scan_real(std::string_view s, size_t i, double* value) {
  const size_t start = i;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t digits = 0;
  while (i < s.size() && is_digit(s[i]))
    ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i]))
      ++i, ++digits;
  }
  if (digits == 0) return std::string_view::npos;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    if (j >= s.size() || !is_digit(s[j])) return std::string_view::npos;
    while (j < s.size() && is_digit(s[j]))
      ++j;
    i = j;
  }
  // from_chars takes no leading '+'.
  const size_t from = s[start] == '+' ? start + 1 : start;
  const auto [end, ec] = std::from_chars(s.data() + from, s.data() + i, *value);
  if (ec != std::errc() || end != s.data() + i || !std::isfinite(*value))
    return std::string_view::npos;
  return i;
}

// The word at s[i] (up to white space, a comma or a brace), for messages.
inline std::string_view word_at(std::string_view s, size_t i) {
  size_t j = i;
  while (j < s.size() && !is_space(s[j]) && s[j] != ',' && s[j] != '{' && s[j] != '}' && j - i < 40)
    ++j;
  return s.substr(i, j == i ? 1 : j - i);
}

} // namespace radcl::bsdf::detail
