#include "radcl/options/args.h"

#include "radcl/util/error.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace radcl::options {
namespace {

bool is_space(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Returns the position after an integer starting at p (leading whitespace allowed), or npos.
std::size_t skip_int(std::string_view s, std::size_t p) {
  while (p < s.size() && is_space(s[p]))
    ++p;
  if (p < s.size() && (s[p] == '-' || s[p] == '+')) ++p;
  if (p >= s.size() || !is_digit(s[p])) return std::string_view::npos;
  while (p < s.size() && is_digit(s[p]))
    ++p;
  return p;
}

std::size_t skip_real(std::string_view s, std::size_t p) {
  while (p < s.size() && is_space(s[p]))
    ++p;
  if (p < s.size() && (s[p] == '-' || s[p] == '+')) ++p;
  std::size_t start = p, q = p;
  while (q < s.size() && is_digit(s[q]))
    ++q;
  if (q < s.size() && s[q] == '.') {
    ++q;
    ++start; // the point itself is not a digit
    while (q < s.size() && is_digit(s[q]))
      ++q;
  }
  if (q == start) return std::string_view::npos;
  if (q < s.size() && (s[q] == 'e' || s[q] == 'E')) {
    ++q;
    if (q < s.size() && is_space(s[q])) return std::string_view::npos;
    return skip_int(s, q);
  }
  return q;
}

bool ends_ok(std::string_view s, std::size_t p, bool allow_space) {
  if (p == std::string_view::npos) return false;
  if (p == s.size()) return true;
  return allow_space && (s[p] == ' ' || s[p] == '\t' || s[p] == '\r' || s[p] == '\n');
}

bool is_print(char c) {
  return std::isprint(static_cast<unsigned char>(c)) != 0;
}

bool is_string_value(const std::string& s) {
  std::size_t p = 0;
  while (p < s.size() && is_space(s[p]))
    ++p;
  if (p >= s.size() || !is_print(s[p])) return false;
  for (; p < s.size(); ++p)
    if (!is_print(s[p]) && !is_space(s[p])) return false;
  return true;
}

} // namespace

bool is_int(std::string_view s, bool allow_trailing_space) {
  return ends_ok(s, skip_int(s, 0), allow_trailing_space);
}

bool is_real(std::string_view s, bool allow_trailing_space) {
  return ends_ok(s, skip_real(s, 0), allow_trailing_space);
}

bool is_finite_real(std::string_view s, bool allow_trailing_space) {
  return is_real(s, allow_trailing_space) && std::isfinite(std::atof(std::string(s).c_str()));
}

std::vector<std::string> split_words(std::string_view text) {
  std::vector<std::string> words;
  std::size_t p = 0;
  while (true) {
    while (p < text.size() && is_space(text[p]))
      ++p;
    if (p >= text.size()) break;
    std::size_t q = p;
    while (q < text.size() && !is_space(text[q]))
      ++q;
    words.emplace_back(text.substr(p, q - p));
    p = q;
  }
  return words;
}

std::string default_find_file(const std::string& name) {
  if (name.empty()) return "";
  if (name[0] == '/' || name[0] == '.') return access(name.c_str(), R_OK) == 0 ? name : "";
  const char* env = std::getenv("RAYPATH");
  std::string path = env ? env : ":/usr/local/lib/ray";
  std::size_t start = 0;
  while (true) {
    std::size_t end = path.find(':', start);
    std::string dir = path.substr(start, end == std::string::npos ? end : end - start);
    std::string full = dir.empty() || dir.back() == '/' ? dir + name : dir + "/" + name;
    if (access(full.c_str(), R_OK) == 0) return full;
    if (end == std::string::npos) return "";
    start = end + 1;
  }
}

ArgList::ArgList(int argc, const char* const* argv) {
  for (int i = 0; i < argc; ++i)
    args_.emplace_back(argv[i]);
}

void ArgList::expand(std::size_t i) {
  // Radiance expands until the word is plain, so a file that names itself never ends there;
  // past this many nested expansions at one position it must be such a loop.
  constexpr int kMaxNesting = 64;
  for (int depth = 0;
       i < args_.size() && !args_[i].empty() && (args_[i][0] == '@' || args_[i][0] == '$');
       ++depth) {
    const std::string arg = args_[i];
    if (depth == kMaxNesting)
      throw FatalError("cannot expand '" + arg + "': more than " + std::to_string(kMaxNesting) +
                       " nested expansions (an option file that names itself?)");
    // Files that name each other after other words grow the line without end (Radiance hangs).
    constexpr int kMaxExpansions = 10000;
    if (++expansions_ > kMaxExpansions)
      throw FatalError("cannot expand '" + arg + "': more than " + std::to_string(kMaxExpansions) +
                       " expansions in one command line (option files that name each other?)");
    std::vector<std::string> words;
    if (arg[0] == '@') {
      // As Radiance's wordfile(): words split at white space, quotes kept as they are.
      std::error_code ec;
      if (std::filesystem::is_directory(arg.substr(1), ec))
        throw SystemError("cannot expand '" + arg + "': " + std::strerror(EISDIR));
      errno = 0;
      std::ifstream in(arg.substr(1), std::ios::binary);
      if (arg.size() < 2 || !in) {
        int err = errno;
        throw SystemError("cannot expand '" + arg + "'" +
                          (err > 0 ? std::string(": ") + std::strerror(err) : ""));
      }
      std::ostringstream ss;
      ss << in.rdbuf();
      words = split_words(ss.str());
    } else if (const char* v = std::getenv(arg.c_str() + 1)) {
      words = split_words(v);
    } else {
      throw SystemError("cannot expand '" + arg + "'");
    }
    args_.erase(args_.begin() + static_cast<std::ptrdiff_t>(i));
    args_.insert(args_.begin() + static_cast<std::ptrdiff_t>(i), words.begin(), words.end());
  }
}

bool ArgList::values_ok(std::size_t i, std::string_view types) const {
  for (std::size_t k = 0; k < types.size(); ++k) {
    std::size_t j = i + 1 + k;
    if (j >= args_.size()) return false;
    const std::string& w = args_[j];
    switch (types[k]) {
    case 's':
      if (!is_string_value(w)) return false;
      break;
    case 'i':
      if (!is_int(w, true)) return false;
      break;
    case 'f':
      if (!is_finite_real(w, true)) return false;
      break;
    default:
      return false;
    }
  }
  return true;
}

bool apply_bool_suffix(const std::string& word, std::size_t pos, bool& value) {
  char c = pos < word.size() ? word[pos] : '\0';
  switch (c) {
  case '\0':
    value = !value;
    return true;
  case '+':
  case 'y':
  case 'Y':
  case 't':
  case 'T':
  case '1':
    value = true;
    return true;
  case '-':
  case 'n':
  case 'N':
  case 'f':
  case 'F':
  case '0':
    value = false;
    return true;
  default:
    return false;
  }
}

void command_line_error(const std::string& word) {
  throw FatalError("command line error at '" + word + "'");
}

} // namespace radcl::options
