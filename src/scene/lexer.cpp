#include "lexer.h"

namespace radcl::scene::detail {
namespace {

constexpr int kMaxWord = 512;  // Radiance's MAXSTR: words keep at most 511 characters
constexpr int kMaxLine = 2048; // buffer of readobj(): lines keep at most 2047 characters

bool is_space(int c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

} // namespace

int Lexer::get() {
  saved_ = {line_, after_cr_};
  int c;
  if (have_back_) {
    have_back_ = false;
    c = back_;
  } else {
    auto r = sb_->sbumpc();
    c = r == std::streambuf::traits_type::eof() ? kEof : static_cast<unsigned char>(r);
  }
  if (c == '\n') {
    if (!after_cr_) ++line_;
    after_cr_ = false;
  } else if (c == '\r') {
    ++line_;
    after_cr_ = true;
  } else if (c != kEof) {
    after_cr_ = false;
  }
  return c;
}

void Lexer::unget(int c) {
  back_ = c;
  have_back_ = true;
  line_ = saved_.line;
  after_cr_ = saved_.after_cr;
}

std::optional<std::string> Lexer::word() {
  int c;
  do
    c = get();
  while (is_space(c));
  int quote = 0;
  if (c == '"' || c == '\'') {
    quote = c;
    c = get();
  }
  std::string s;
  int room = kMaxWord;
  while (c != kEof && !(quote ? c == quote : is_space(c))) {
    if (--room <= 0) break; // as fgetword: unquoted, c starts the next word; quoted, it is lost
    s.push_back(static_cast<char>(c));
    c = get();
  }
  if (c == kEof) {
    if (s.empty()) return std::nullopt;
  } else if (!quote) {
    unget(c);
  }
  return s;
}

void Lexer::skip_comment() {
  for (int room = kMaxLine - 1; room > 0; --room) {
    int c = get();
    if (c == kEof || c == '\n') break;
  }
}

std::string Lexer::command_line() {
  std::string s;
  int room = kMaxLine;
  int c;
  while (--room > 0 && (c = get()) != kEof) {
    if (c == '\r') {
      c = get();
      if (c != '\n') {
        unget(c);
        c = '\n';
      }
    }
    if (c == '\n' && (s.empty() || s.back() != '\\')) break;
    s.push_back(static_cast<char>(c));
  }
  return s;
}

} // namespace radcl::scene::detail
