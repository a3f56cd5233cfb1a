// Radiance's command-line conventions shared by rtrace and rpict: in-place "@file" / "$VAR"
// expansion, number syntax checks (words.c) and value checks after an option (badarg.c).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace radcl::options {

// Integer: [ws][+-]digits; real: [ws][+-]digits[.digits][(e|E)[+-]digits] with at least one
// digit (a leading '.' is fine). The word must end right after the number, or (with
// `allow_trailing_space`) at whitespace, as Radiance's option checks allow.
bool is_int(std::string_view s, bool allow_trailing_space = false);
bool is_real(std::string_view s, bool allow_trailing_space = false);
// is_real, and its value does not overflow (Radiance's atof turns "1e999" into Inf; no option
// means anything with it).
bool is_finite_real(std::string_view s, bool allow_trailing_space = false);

// Splits on whitespace (space, tab, newline, CR, FF, VT); no quoting, no comments.
std::vector<std::string> split_words(std::string_view text);

// Where auxiliary files (-aE, -aI, -tE, -tI) are looked up. The front end passes the scene
// module's RAYPATH search; the default tries names starting with '/', '.' as given and
// otherwise each RAYPATH entry (default ":/usr/local/lib/ray"). Returns "" if not found.
using FileFinder = std::function<std::string(const std::string&)>;
std::string default_find_file(const std::string& name);

// argv with Radiance's lazy expansion: an argument "@file" is replaced by the words of file,
// "$VAR" by the words of the environment variable; expansion repeats at the same position.
// Only positions the parser visits as options (or the first positional) are expanded.
class ArgList {
public:
  explicit ArgList(std::vector<std::string> args) : args_(std::move(args)) {}
  ArgList(int argc, const char* const* argv);

  std::size_t size() const { return args_.size(); }
  const std::string& operator[](std::size_t i) const { return args_[i]; }
  const std::vector<std::string>& words() const { return args_; }

  // Expands position i until it is a plain word. Throws SystemError("cannot expand '<arg>'",
  // with the system's reason for a file) for an unreadable file or an unset variable, as
  // Radiance does, and FatalError for expansions nested past a limit (a file naming itself) or
  // more of them than any real command line has (files that name each other further along).
  void expand(std::size_t i);

  // Radiance's badarg(): the words after position i match `types` ('i' integer, 'f' real,
  // 's' printable string), and there are enough of them.
  bool values_ok(std::size_t i, std::string_view types) const;

private:
  std::vector<std::string> args_;
  int expansions_ = 0; // so far, over the whole command line
};

// Radiance's boolean suffix: '\0' toggles, "+yYtT1" sets, "-nNfF0" clears. Returns false for
// any other character (a command line error). Characters after the suffix are ignored.
bool apply_bool_suffix(const std::string& word, std::size_t pos, bool& value);

// The message for a malformed option: "command line error at '<word>'".
[[noreturn]] void command_line_error(const std::string& word);

} // namespace radcl::options
