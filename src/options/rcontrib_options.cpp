#include "radcl/options/rcontrib_options.h"

#include "cformat.h"
#include "radcl/options/ray_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_set>

namespace radcl::options {
namespace {

// Words as Radiance's fgetword() reads a modifier file: white space separates them, and a word
// that starts with a double or single quote runs to the matching quote (spaces included).
std::vector<std::string> quoted_words(const std::string& text) {
  std::vector<std::string> words;
  auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  std::size_t p = 0;
  while (true) {
    while (p < text.size() && space(text[p]))
      ++p;
    if (p >= text.size()) break;
    if (text[p] == '"' || text[p] == '\'') {
      const std::size_t close = text.find(text[p], p + 1);
      words.push_back(text.substr(p + 1, close == std::string::npos ? close : close - p - 1));
      if (close == std::string::npos) break;
      p = close + 1; // the closing quote ends the word even without white space after it
      continue;
    }
    std::size_t q = p;
    while (q < text.size() && !space(text[q]))
      ++q;
    words.push_back(text.substr(p, q - p));
    p = q;
  }
  return words;
}

// The value of a bin expression made only of numbers, + - * / ^ and parentheses, which
// Radiance's parser reduces to a constant (E_RCONST) and addmodifier() then checks; nullopt for
// anything else (names, $N, syntax the engine reports when it compiles the expression). The
// grammar is calc's: unary minus binds to the operand, so -2^2 is 4, and ^ is right-assoc.
class ConstantExpr {
public:
  static std::optional<double> value(const std::string& expr) {
    ConstantExpr c(expr);
    std::optional<double> v = c.sum();
    c.skip();
    if (!v || c.p_ != c.s_.size()) return std::nullopt;
    return v;
  }

private:
  explicit ConstantExpr(const std::string& s) : s_(s) {}
  void skip() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_])))
      ++p_;
  }
  bool take(char c) {
    skip();
    if (p_ < s_.size() && s_[p_] == c) {
      ++p_;
      return true;
    }
    return false;
  }
  std::optional<double> sum() {
    std::optional<double> v = product();
    while (v) {
      if (take('+')) {
        auto r = product();
        v = r ? std::optional(*v + *r) : std::nullopt;
      } else if (take('-')) {
        auto r = product();
        v = r ? std::optional(*v - *r) : std::nullopt;
      } else {
        break;
      }
    }
    return v;
  }
  std::optional<double> product() {
    std::optional<double> v = power();
    while (v) {
      if (take('*')) {
        auto r = power();
        v = r ? std::optional(*v * *r) : std::nullopt;
      } else if (take('/')) {
        auto r = power();
        v = r ? std::optional(*v / *r) : std::nullopt;
      } else {
        break;
      }
    }
    return v;
  }
  std::optional<double> power() {
    std::optional<double> v = unary();
    if (v && take('^')) {
      auto r = power();
      v = r ? std::optional(std::pow(*v, *r)) : std::nullopt;
    }
    return v;
  }
  std::optional<double> unary() {
    if (take('-')) {
      auto v = primary();
      return v ? std::optional(-*v) : std::nullopt;
    }
    take('+');
    return primary();
  }
  std::optional<double> primary() {
    if (take('(')) {
      auto v = sum();
      return v && take(')') ? v : std::nullopt;
    }
    skip();
    auto digit = [&](std::size_t k) {
      return k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]));
    };
    const std::size_t start = p_;
    while (digit(p_))
      ++p_;
    if (p_ < s_.size() && s_[p_] == '.')
      for (++p_; digit(p_);)
        ++p_;
    if (p_ == start) return std::nullopt;
    if (p_ < s_.size() && (s_[p_] == 'e' || s_[p_] == 'E')) {
      ++p_;
      if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) ++p_;
      if (!digit(p_)) return std::nullopt;
      while (digit(p_))
        ++p_;
    }
    return std::atof(s_.substr(start, p_ - start).c_str());
  }

  const std::string& s_;
  std::size_t p_ = 0;
};

// Radiance's override_options(): contributions need every source sample and no ambient
// interpolation or super-sampling, whatever the command line says.
void override_options(RcontribOptions& o) {
  o.render.direct_threshold = 0;
  o.render.ambient_supersamples = 0;
  o.render.ambient_accuracy = 0;
  if (o.accumulate <= 0) o.xres = o.yres = 0; // a single record: nothing to flush
}

class Parser {
public:
  Parser(const std::vector<std::string>& args, const CalHooks& hooks, const FileFinder& find)
      : a_(args), hooks_(hooks), find_(find) {}

  RcontribCommand run() {
    RcontribCommand cmd;
    RcontribOptions& o = cmd.opt;
    std::size_t i = 1;
    for (; i < a_.size(); ++i) {
      a_.expand(i);
      if (i >= a_.size() || a_[i].empty() || a_[i][0] != '-') break;
      if (a_[i] == "-version") {
        cmd.action = RcontribCommand::Action::PrintVersion;
        break;
      }
      if (a_[i] == "-defaults" || a_[i] == "-help") {
        cmd.action = RcontribCommand::Action::PrintDefaults;
        break;
      }
      int n = parse_render_option(o.render, a_, i, find_);
      if (n < 0) n = own_option(o, i);
      i += static_cast<std::size_t>(n);
    }
    cmd.args = a_.words();
    cmd.operand = std::min(i, a_.size());
    if (cmd.action == RcontribCommand::Action::PrintDefaults) override_options(o);
    if (cmd.action != RcontribCommand::Action::Run) return cmd;
    if (o.modifiers.empty()) throw FatalError("missing required modifier argument");
    override_options(o);
    if (i + 1 < a_.size()) bad(i); // one octree at most
    return cmd;
  }

private:
  [[noreturn]] void bad(std::size_t i) const {
    throw RcontribUsageError("command line error at '" + a_[i] + "'");
  }

  // rcontrib's own option at i; returns the number of values it took.
  int own_option(RcontribOptions& o, std::size_t i) {
    const std::string& w = a_[i];
    auto value = [&](std::size_t len, const char* types) -> const std::string& {
      if (w.size() != len || !a_.values_ok(i, types)) bad(i);
      return a_[i + 1];
    };
    auto boolean = [&](std::size_t pos, bool& v) {
      if (!apply_bool_suffix(w, pos, v)) bad(i);
      return 0;
    };
    auto integer = [&](int& v) {
      v = std::atoi(value(2, "i").c_str());
      return 1;
    };
    const char c2 = w.size() > 2 ? w[2] : '\0';
    switch (w[1]) {
    case 'n':
      integer(o.nproc);
      if (o.nproc <= 0) throw FatalError("bad number of processes");
      return 1;
    case 'V':
      return boolean(2, o.contributions);
    case 'x':
      return integer(o.xres);
    case 'y':
      return integer(o.yres);
    case 'w':
      return boolean(2, o.warnings);
    case 'e': {
      const std::string& s = value(2, "s");
      if (hooks_.load_expr) hooks_.load_expr(s);
      o.cal.push_back({false, s});
      return 1;
    }
    case 'l':
      if (c2 != 'd') bad(i);
      return boolean(3, o.limit_distance);
    case 'I':
      return boolean(2, o.immediate_irradiance);
    case 'f': // a .cal file, -fo (force open) or the i/o format
      if (c2 == '\0') {
        const std::string& f = value(2, "s");
        if (hooks_.load_file) hooks_.load_file(f);
        o.cal.push_back({true, f});
        return 1;
      }
      if (c2 == 'o') return boolean(3, o.force_open);
      set_format(o, w);
      return 0;
    case 'o':
      outspec_ = value(2, "s");
      return 1;
    case 'c':
      return integer(o.accumulate);
    case 'r':
      return boolean(2, o.recover);
    case 'h':
      return boolean(2, o.header);
    case 'p':
      params_ = value(2, "s");
      if (hooks_.set_params) hooks_.set_params(params_);
      return 1;
    case 'b':
      if (c2 == 'n') {
        bincnt_ = bin_count(value(3, "s"));
        return 1;
      }
      bin_expr_ = value(2, "s");
      return 1;
    case 'm':
      add_modifier(o, value(2, "s"));
      return 1;
    case 'M':
      add_modifier_file(o, value(2, "s"));
      return 1;
    case 't':
      return integer(o.report_interval);
    default:
      bad(i);
    }
  }

  // -f<in>[<out>]: a format error is Radiance's own message, without the usage line.
  static void set_format(RcontribOptions& o, const std::string& w) {
    const std::string fmt = w.substr(2);
    auto fail = [&] { throw FatalError("Illegal i/o format: -f" + fmt); };
    if (fmt[0] != 'a' && fmt[0] != 'f' && fmt[0] != 'd') fail();
    o.in_format = fmt[0];
    if (fmt.size() == 1) {
      o.out_format = o.in_format;
      return;
    }
    if (std::string_view("afdc").find(fmt[1]) == std::string_view::npos || fmt.size() > 2) fail();
    o.out_format = fmt[1];
  }

  // -bn: Radiance rounds the value to an int there and then; one that does not fit an int
  // counts as no bins (Radiance's conversion is undefined).
  int bin_count(const std::string& expr) const {
    const double v = hooks_.eval           ? hooks_.eval(expr)
                     : is_real(expr, true) ? std::atof(expr.c_str())
                                           : 0.0;
    const double r = v + .5;
    return r > INT_MIN && r < INT_MAX ? static_cast<int>(r) : 0;
  }

  void add_modifier(RcontribOptions& o, const std::string& name) {
    if (!names_.insert(name).second) throw FatalError("duplicate modifier '" + name + "'");
    if (name == "void") throw FatalError("cannot track 'void' modifier");
    RcontribModifier m;
    m.name = name;
    m.outspec = outspec_;
    m.params = params_;
    m.bin_expr = bin_expr_;
    if (std::optional<double> c = ConstantExpr::value(bin_expr_)) {
      // Radiance takes (int)(value + 1.5) bins and wants one: any constant in [-.5, .5).
      if (!(*c + 1.5 >= 1 && *c + 1.5 < 2))
        throw FatalError("illegal non-zero constant for bin (" + bin_expr_ + ")");
      m.nbins = 1;
    } else if (bincnt_ <= 0) {
      throw FatalError("unspecified or illegal bin count for modifier '" + name + "'");
    } else {
      m.nbins = bincnt_;
    }
    o.modifiers.push_back(std::move(m));
  }

  void add_modifier_file(RcontribOptions& o, const std::string& file) {
    const std::string path = find_(file);
    // Radiance's message carries the errno of its failed search: the file is not there.
    if (path.empty())
      throw SystemError("cannot find modifier file '" + file + "': " + std::strerror(ENOENT));
    // A directory reads as nothing in Radiance (no modifiers, no message); refuse it instead.
    std::error_code ec;
    int err = std::filesystem::is_directory(path, ec) ? EISDIR : 0;
    errno = 0;
    std::ifstream in;
    if (!err) {
      in.open(path, std::ios::binary);
      if (!in) err = errno;
    }
    if (err || !in)
      throw SystemError("cannot load modifier file '" + path + "'" +
                        (err > 0 ? std::string(": ") + std::strerror(err) : ""));
    std::ostringstream ss;
    ss << in.rdbuf();
    for (const std::string& name : quoted_words(ss.str()))
      add_modifier(o, name);
  }

  ArgList a_;
  const CalHooks& hooks_;
  const FileFinder& find_;
  // What later -m options take.
  std::optional<std::string> outspec_;
  std::string params_;
  std::string bin_expr_ = "0"; // a single bin unless -b says otherwise
  int bincnt_ = 0;
  std::unordered_set<std::string> names_;
};

} // namespace

std::string rcontrib_usage(const std::string& program) {
  return "Usage: " + program +
         " [-n nprocs][-V][-c count][-r][-e expr][-f source][-o ospec][-p p1=V1,p2=V2]"
         "[-b binv][-bn N] {-m mod | -M file} [rtrace options] octree\n";
}

RcontribCommand parse_rcontrib_command_line(const std::vector<std::string>& args,
                                            const CalHooks& cal, const FileFinder& find_file) {
  return Parser(args, cal, find_file).run();
}

std::string format_rcontrib_defaults(const RcontribOptions& o) {
  std::string s;
  s += cformat("-c %-5d\t\t\t# accumulated rays per record\n", o.accumulate);
  s += cformat("-V%c\t\t\t\t# output %s\n", o.contributions ? '+' : '-',
               o.contributions ? "contributions" : "coefficients");
  if (o.immediate_irradiance) s += "-I+\t\t\t\t# immediate irradiance on\n";
  s += cformat("-n %-2d\t\t\t\t# number of rendering processes\n", o.nproc);
  s += cformat("-x %-9d\t\t\t# %s\n", o.xres, o.yres && o.xres ? "x resolution" : "flush interval");
  s += cformat("-y %-9d\t\t\t# y resolution\n", o.yres);
  s +=
      o.limit_distance ? "-ld+\t\t\t\t# limit distance on\n" : "-ld-\t\t\t\t# limit distance off\n";
  s += cformat("-h%c\t\t\t\t# %s header\n", o.header ? '+' : '-', o.header ? "output" : "no");
  s += cformat("-f%c%c\t\t\t\t# format input/output = %s/%s\n", o.in_format, o.out_format,
               format_name(o.in_format), format_name(o.out_format));
  s += o.warnings ? "-w+\t\t\t\t# warning messages on\n" : "-w-\t\t\t\t# warning messages off\n";
  s += format_render_defaults(o.render);
  return s;
}

} // namespace radcl::options
