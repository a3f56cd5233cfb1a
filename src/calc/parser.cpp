// Recursive-descent parser for .cal text (../shared/docs/radiance/calc-language.md §1-§3), folding
// constants at parse time by Radiance's rules (§3.3).
#include <cctype>
#include <cstdlib>
#include <string>

#include "radcl/calc/evaluator.h"
#include "radcl/calc/library.h"
#include "radcl/calc/program.h"
#include "radcl/util/error.h"

namespace radcl::calc {
namespace {

constexpr int kEof = -1;
constexpr std::size_t kMaxName = 127;
constexpr char kContextMark = '`';

bool is_id(int c) {
  return c != kEof && (std::isalnum(c) || c == '_' || c == '.' || c == kContextMark);
}

class Parser {
public:
  Parser(Program& prog, std::string_view text, std::string source, std::string context)
      : prog_(prog), text_(text), source_(std::move(source)), context_(std::move(context)) {
    skip();
  }

  void statements() {
    while (next() != kEof) {
      if (next() == ';') {
        advance();
        continue;
      }
      definition();
      if (next() != kEof) {
        if (next() != ';') syntax("';' expected");
        advance();
      }
    }
  }

  Node expression() {
    Node n = e1();
    if (next() != kEof) syntax("unexpected character");
    return n;
  }

private:
  int next() const { return pos_ < text_.size() ? static_cast<unsigned char>(text_[pos_]) : kEof; }
  // The raw character after the current one (inside numbers and names, spaces end the token).
  int raw(std::size_t at) const {
    return at < text_.size() ? static_cast<unsigned char>(text_[at]) : kEof;
  }
  void step() {
    if (text_[pos_] == '\n') {
      ++line_;
      line_start_ = pos_ + 1;
    }
    ++pos_;
  }
  // Skips whitespace and (nested) { } comments.
  void skip() {
    for (;;) {
      int c = next();
      if (c != kEof && std::isspace(c)) {
        step();
      } else if (c == '{') {
        int depth = 0;
        do {
          if (next() == kEof) syntax("'}' expected");
          if (next() == '{') ++depth;
          if (next() == '}') --depth;
          step();
        } while (depth > 0);
      } else {
        return;
      }
    }
  }
  void advance() {
    step();
    skip();
  }

  [[noreturn]] void syntax(const std::string& msg) const {
    std::size_t end = text_.find('\n', line_start_);
    std::string line(
        text_.substr(line_start_, end == std::string_view::npos ? end : end - line_start_));
    std::string where;
    if (!source_.empty()) where = source_ + ", line " + std::to_string(line_) + ":\n";
    std::string caret;
    for (std::size_t i = line_start_; i < pos_ && i < text_.size(); ++i)
      caret += text_[i] == '\t' ? '\t' : ' ';
    throw FatalError(where + line + "\n" + caret + "^ " + msg);
  }

  std::string name() {
    std::string s;
    while (is_id(next())) {
      if (s.size() < kMaxName) s += static_cast<char>(next());
      step();
    }
    skip();
    return s;
  }

  double number() {
    std::string s;
    auto take = [&] {
      s += static_cast<char>(next());
      step();
    };
    while (next() != kEof && std::isdigit(next()))
      take();
    if (next() == '.') {
      take();
      if (s.size() == 1 && !(next() != kEof && std::isdigit(next()))) syntax("badly formed number");
      while (next() != kEof && std::isdigit(next()))
        take();
    }
    if (next() == 'e' || next() == 'E') {
      take();
      if (next() == '+' || next() == '-') take();
      if (!(next() != kEof && std::isdigit(next()))) syntax("missing exponent");
      while (next() != kEof && std::isdigit(next()))
        take();
    }
    skip();
    return std::strtod(s.c_str(), nullptr);
  }

  void definition() {
    if (!(next() != kEof && (std::isalpha(next()) || next() == kContextMark)))
      syntax("illegal variable name");
    Definition def;
    def.line = line_;
    def.file = source_;
    std::string written = name();
    if (next() == '(') {
      def.function = true;
      do {
        advance();
        if (!(next() != kEof && std::isalpha(next()))) syntax("illegal parameter name");
        std::string p = name();
        if (p.find(kContextMark) != std::string::npos) syntax("illegal parameter name");
        def.params.push_back(p);
      } while (next() == ',');
      if (next() != ')') syntax("')' expected");
      advance();
    }
    if (next() != '=' && next() != ':') syntax("'=' or ':' expected");
    def.constant = next() == ':';
    advance();
    params_ = def.function ? &def.params : nullptr;
    def.body = e1();
    params_ = nullptr;
    def.name = qualify(written, context_);
    def.context = context_;
    prog_.define(std::move(def));
  }

  static Node binary(Op op, Node a, Node b) {
    Node n;
    n.op = op;
    n.kids.push_back(std::move(a));
    n.kids.push_back(std::move(b));
    return n;
  }

  // Evaluates a constant subtree now ("bad constant expression" if that raises an error).
  Node reduce(const Node& n) {
    bool ok = true;
    // Errors of the evaluation itself (undefined names, arg() in a constant) pass through.
    double v = fold_constant(prog_, n, context_, ok);
    if (!ok) syntax("bad constant expression");
    return Node::number(v);
  }

  // Each nested parenthesis, function argument or '^' operand goes one level deeper into the
  // recursive descent; far beyond what any function file needs, an error instead of running
  // out of stack.
  static constexpr int kMaxNesting = 256;
  int nesting_ = 0;
  struct Deeper {
    Parser& p;
    explicit Deeper(Parser& q) : p(q) {
      if (++p.nesting_ > kMaxNesting) {
        --p.nesting_;
        p.syntax("expression nested too deeply");
      }
    }
    ~Deeper() { --p.nesting_; }
  };

  Node e1() {
    Deeper guard(*this);
    Node a = e2();
    while (next() == '+' || next() == '-') {
      Op op = next() == '+' ? Op::Add : Op::Sub;
      advance();
      Node n = binary(op, std::move(a), e2());
      a = n.kids[0].is_num() && n.kids[1].is_num() ? reduce(n) : std::move(n);
    }
    return a;
  }

  Node e2() {
    Node a = e3();
    while (next() == '*' || next() == '/') {
      Op op = next() == '*' ? Op::Mul : Op::Div;
      advance();
      Node b = e3();
      if (a.is_num() && b.is_num()) {
        a = reduce(binary(op, std::move(a), std::move(b)));
      } else if (b.is_num()) {
        if (op == Op::Div) {
          if (b.num == 0) syntax("divide by zero constant");
          a = binary(Op::Mul, std::move(a), Node::number(1.0 / b.num)); // as Radiance, for speed
        } else if (b.num == 0) {
          a = Node::number(0); // E * 0
        } else {
          a = binary(op, std::move(a), std::move(b));
        }
      } else if (a.is_num() && a.num == 0) {
        a = Node::number(0); // 0 * E, 0 / E
      } else {
        a = binary(op, std::move(a), std::move(b));
      }
    }
    return a;
  }

  Node e3() {
    Node a = e4();
    if (next() != '^') return a;
    advance();
    Deeper guard(*this);
    Node b = e3();
    if (a.is_num() && b.is_num()) return reduce(binary(Op::Pow, std::move(a), std::move(b)));
    if (a.is_num() && a.num == 0) return Node::number(0);
    if ((b.is_num() && b.num == 0) || (a.is_num() && a.num == 1)) return Node::number(1);
    if (b.is_num() && b.num == 1) return a;
    return binary(Op::Pow, std::move(a), std::move(b));
  }

  // Unary minus applies to an E5 only, so it binds tighter than '^' (-2^2 = 4).
  Node e4() {
    if (next() == '-') {
      advance();
      Node a = e5();
      if (a.is_num()) {
        a.num = -a.num;
        return a;
      }
      if (a.op == Op::Neg) return std::move(a.kids[0]);
      Node n;
      n.op = Op::Neg;
      n.kids.push_back(std::move(a));
      return n;
    }
    if (next() == '+') advance();
    return e5();
  }

  int param_index(const std::string& s) const {
    if (!params_) return -1;
    for (std::size_t i = 0; i < params_->size(); ++i)
      if ((*params_)[i] == s) return static_cast<int>(i);
    return -1;
  }

  // Whether `n` names a constant function: a user `:` function, or a constant library function
  // not masked by a definition.
  bool const_function(const Node& n) const {
    if (n.op != Op::Var) return false;
    if (const Definition* d = prog_.lookup(n.name, context_)) return d->function && d->constant;
    const LibraryFunction* lib = find_library(n.name);
    return lib && lib->constant;
  }

  bool const_value(const Node& n) const {
    if (n.op == Op::Call) {
      Node callee;
      callee.op = Op::Var;
      callee.name = n.name;
      if (!const_function(callee)) return false;
      for (const Node& k : n.kids)
        if (!k.is_num() && !const_function(k)) return false;
      return true;
    }
    if (n.op != Op::Var) return false;
    const Definition* d = prog_.lookup(n.name, context_);
    return d && d->constant && !d->function;
  }

  Node e5() {
    if (next() == '(') {
      advance();
      Node n = e1();
      if (next() != ')') syntax("')' expected");
      advance();
      return n;
    }
    if (next() == '$') {
      step();
      if (!(next() != kEof && std::isdigit(next()))) syntax("unexpected character");
      Node n;
      n.op = Op::Chan;
      // An integer of digits only, as Radiance's getinum reads it.
      long chan = 0;
      while (next() != kEof && std::isdigit(next())) {
        chan = chan * 10 + (next() - '0');
        if (chan > 1000000) syntax("channel number too large");
        step();
      }
      skip();
      n.index = static_cast<int>(chan);
      return n;
    }
    if (next() != kEof && (std::isalpha(next()) || next() == kContextMark)) {
      Node n;
      n.name = name();
      int p = param_index(n.name);
      if (next() == '(') {
        n.op = p >= 0 ? Op::PCall : Op::Call;
        n.index = p;
        do {
          advance();
          n.kids.push_back(e1());
        } while (next() == ',');
        if (next() != ')') syntax("')' expected");
        advance();
      } else {
        n.op = p >= 0 ? Op::Param : Op::Var;
        n.index = p;
      }
      if ((n.op == Op::Var || n.op == Op::Call) && const_value(n)) return reduce(n);
      return n;
    }
    if (next() != kEof && (std::isdigit(next()) || next() == '.')) return Node::number(number());
    syntax("unexpected character");
  }

  Program& prog_;
  std::string_view text_;
  std::string source_, context_;
  std::size_t pos_ = 0, line_start_ = 0;
  int line_ = 1;
  const std::vector<std::string>* params_ = nullptr;
};

} // namespace

void Program::load_string(std::string_view text, const std::string& source,
                          const std::string& context) {
  Parser(*this, text, source, context).statements();
}

Expression Program::parse_expression(std::string_view text, const std::string& context,
                                     const std::string& source) {
  return Expression{Parser(*this, text, source, context).expression(), context};
}

} // namespace radcl::calc
