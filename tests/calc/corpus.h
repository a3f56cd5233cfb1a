// Seeded generator of random .cal expressions for the host/device agreement test: every
// operator, library function, ray variable, channel and real argument, and calls of the user
// functions in kCorpusDefinitions (nested, recursive with a base case, function arguments).
#pragma once

#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include "radcl/calc/device_context.h"
#include "radcl/calc/library.h"

namespace corpus {

// Loaded (after rayinit.cal) before the expressions are parsed.
inline const char* kCorpusDefinitions = R"(
  u1(x) = x*x - 0.5*x;
  u2(x, y) = sin(x)*y + u1(y);
  u3(a, b, c) = if(a, u2(b, c), u1(c) - b);
  fact(n) = if(n - 1, n*fact(n - 1), 1);
  halves(n, x) = if(n, x + halves(n - 1, x*0.5), 0);
  even(n) = if(n, odd(n - 1), 1);
  odd(n) = if(n, even(n - 1), 0);
  apply(f, x) = f(x) + 1;
  k1 : 2.5;
  k2 : k1*PI;
  v1 = Dx*Px + Ny;
  v2 = v1*2 + A1;
  v3 = hermite(A2, A3, Rdot, T, frac(Px));
  dead(x) = x + undefined_variable_never_used;
)";

class Generator {
public:
  explicit Generator(std::uint32_t seed) : rng_(seed) {}

  std::string expression(int depth = 4) {
    if (depth <= 0 || pick(5) == 0) return leaf();
    switch (pick(9)) {
    case 0:
    case 1: {
      static const char* ops[] = {"+", "-", "*", "/", "^"};
      int o = pick(5);
      std::string a = expression(depth - 1), b = expression(depth - 1);
      if (o == 4) b = "(" + small(depth - 1) + ")"; // keep powers moderate
      return "(" + a + ops[o] + b + ")";
    }
    case 2:
      return "-" + paren(expression(depth - 1));
    case 3:
    case 4:
      return library(depth - 1);
    case 5:
    case 6:
      return user(depth - 1);
    default:
      return expression(depth - 1) + (pick(2) ? "+" : "*") + expression(depth - 1);
    }
  }

private:
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  static std::string paren(const std::string& s) { return "(" + s + ")"; }
  static std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, pick_format(v), v);
    return buf;
  }
  static const char* pick_format(double v) { return v < 0.01 ? "%.4e" : "%.6g"; }

  // A bounded exponent: a small literal or a smooth function of the inputs.
  std::string small(int depth) {
    if (pick(2)) return num(uniform(0.0, 3.0));
    return "sin(" + expression(depth > 1 ? 1 : 0) + ")";
  }

  std::string leaf() {
    switch (pick(6)) {
    case 0:
    case 1:
      return num(pick(4) == 0 ? uniform(0.0, 0.01) : uniform(0.0, 10.0));
    case 2:
      return radcl::calc::ray_slot_name(pick(RC_CALC_NSLOTS));
    case 3:
      return pick(2) ? "$" + std::to_string(1 + pick(RC_CALC_NCHANNELS))
                     : "A" + std::to_string(1 + pick(6));
    case 4: {
      static const char* vars[] = {"k1", "k2", "v1", "v2", "v3", "PI", "AC", "U", "V", "Idz"};
      return vars[pick(10)];
    }
    default:
      return "arg(" + std::to_string(pick(7)) + ")";
    }
  }

  std::string library(int depth) {
    auto e = [&] { return expression(depth); };
    static const char* unary[] = {"floor", "ceil", "sqrt", "sin",   "cos", "tan",  "asin", "acos",
                                  "atan",  "exp",  "log",  "log10", "erf", "erfc", "rand"};
    switch (pick(9)) {
    case 0:
    case 1:
    case 2:
      return std::string(unary[pick(15)]) + paren(e());
    case 3:
      return "atan2(" + e() + ", " + e() + ")";
    case 4:
      return "if(" + e() + ", " + e() + ", " + e() + ")";
    case 5: {
      int n = 1 + pick(4);
      std::string s = "select(" + std::to_string(pick(n + 2)) + (pick(2) ? "" : "+0*" + e());
      for (int i = 0; i < n; ++i)
        s += ", " + e();
      return s + ")";
    }
    case 6: {
      std::string s = pick(2) ? "min(" : "max(";
      int n = 1 + pick(4);
      for (int i = 0; i < n; ++i)
        s += (i ? ", " : "") + e();
      return s + ")";
    }
    case 7: {
      static const char* noise[] = {"noise3", "noise3x", "noise3y", "noise3z", "fnoise3"};
      return std::string(noise[pick(5)]) + "(" + e() + ", " + e() + ", " + e() + ")";
    }
    default:
      return "select(" + e() + ", " + e() + ", " + e() + ")";
    }
  }

  std::string user(int depth) {
    auto e = [&] { return expression(depth); };
    switch (pick(11)) {
    case 0:
      return "u1(" + e() + ")";
    case 1:
      return "u2(" + e() + ", " + e() + ")";
    case 2:
      return "u3(" + e() + ", " + e() + ", " + e() + ")";
    case 3:
      return "fact(1 + mod(floor(abs(" + e() + ")), 8))";
    case 4:
      return "halves(mod(floor(abs(" + e() + ")), 12), " + e() + ")";
    case 5:
      return "even(mod(floor(abs(" + e() + ")), 14))";
    case 6: {
      static const char* fs[] = {"u1", "sin", "sq", "abs", "sgn", "frac"};
      return "apply(" + std::string(fs[pick(6)]) + ", " + e() + ")";
    }
    case 7: {
      static const char* fs[] = {"bound(-1, %, 1)",     "clip(%)", "tri(%, 2)",
                                 "linterp(0.25, 1, %)", "Exp(%)",  "Acos(%)"};
      std::string f = fs[pick(6)];
      return f.replace(f.find('%'), 1, e());
    }
    case 8:
      return "turbulence(" + e() + ", " + e() + ", " + e() + ", 0.125)";
    case 9:
      return "D(" + std::to_string(1 + pick(3)) + ")*N(2) + P(" + std::to_string(1 + pick(3)) + ")";
    default:
      return "bezier(" + e() + ", 1, 2, " + e() + ", frac(" + e() + "))";
    }
  }

  std::mt19937 rng_;
};

} // namespace corpus
