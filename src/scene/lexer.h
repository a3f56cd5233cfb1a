// Character-level reading of a scene file as Radiance's readobj() does it: words (fgetword),
// comment lines (fgets) and command lines (fgetline), with line numbers for messages.
#pragma once

#include <optional>
#include <streambuf>
#include <string>

namespace radcl::scene::detail {

class Lexer {
public:
  static constexpr int kEof = -1;

  explicit Lexer(std::streambuf* sb) : sb_(sb) {}

  int get();
  void unget(int c); // one character, the last one read
  int line() const { return line_; }

  // Next word: skips white space; a leading " or ' quotes up to the matching quote. At most
  // 511 characters (the rest starts a new word). nullopt at end of input with nothing read.
  std::optional<std::string> word();
  // Discards a comment: up to 2047 characters, through the newline.
  void skip_comment();
  // A command line, starting at its '!': backslash-newline continues it (both kept), CR-LF
  // and lone CR end it like a newline; at most 2047 characters.
  std::string command_line();

private:
  struct State {
    int line;
    bool after_cr;
  };
  std::streambuf* sb_;
  int line_ = 1;
  bool after_cr_ = false; // a '\n' right after '\r' does not start another line
  State saved_{1, false};
  int back_ = kEof;
  bool have_back_ = false;
};

} // namespace radcl::scene::detail
