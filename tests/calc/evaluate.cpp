// Parser and host evaluator: Radiance's precedence (and its unary-minus quirk), constants,
// functions, call-by-need arguments, arg(n), select, if, recursion and the error rules.
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "radcl/calc/evaluator.h"
#include "radcl/calc/program.h"
#include "radcl/util/error.h"
#include "warnings.h"

using namespace radcl::calc;
using radcl::FatalError;

namespace {

struct Calc : ::testing::Test {
  Program prog;
  Evaluator ev{prog};
  radcl::test::CapturedWarnings warnings;
  double eval(const std::string& text) { return ev.eval(prog.parse_expression(text)); }
  std::string error_of(const std::string& text) {
    try {
      eval(text);
    } catch (const FatalError& e) {
      return e.what();
    }
    return "";
  }
  std::string load_error(const std::string& text, const std::string& source = "t.cal") {
    try {
      prog.load_string(text, source);
    } catch (const FatalError& e) {
      return e.what();
    }
    return "";
  }
};

} // namespace

TEST_F(Calc, PrecedenceAndAssociativity) {
  EXPECT_EQ(eval("1+2*3"), 7);
  EXPECT_EQ(eval("(1+2)*3"), 9);
  EXPECT_EQ(eval("10-4-3"), 3);  // left associative
  EXPECT_EQ(eval("64/4/2"), 8);  // left associative
  EXPECT_EQ(eval("2^3^2"), 512); // right associative
  EXPECT_EQ(eval("2*3^2"), 18);
  EXPECT_EQ(eval("2^-1"), 0.5);
  EXPECT_EQ(eval("+3 - -2"), 5);
}

TEST_F(Calc, UnaryMinusBindsTighterThanPower) {
  EXPECT_EQ(eval("-2^2"), 4);
  prog.load_string("x = 3;", "t.cal");
  EXPECT_EQ(eval("-x^2"), 9);
  EXPECT_EQ(eval("0-x^2"), -9);
  EXPECT_EQ(eval("-(x^2)"), -9);
}

TEST_F(Calc, NumbersAndComments) {
  EXPECT_EQ(eval("1.5e2"), 150);
  EXPECT_EQ(eval(".5"), 0.5);
  EXPECT_EQ(eval("2E-1"), 0.2);
  EXPECT_EQ(eval("1 {comment {nested}} + 2"), 3);
  prog.load_string("{ header }\na = 1; ; b = a + 1 {trailing}\n", "t.cal");
  EXPECT_EQ(eval("b"), 2);
  // '.' belongs to names: a.b is one name.
  prog.load_string("a.b = 7;", "t.cal");
  EXPECT_EQ(eval("a.b"), 7);
}

TEST_F(Calc, StatementsAcrossFiles) {
  prog.load_string("x = 2; f(a) = a*y;", "one.cal");
  prog.load_string("y = x + 1", "two.cal"); // last statement without ';'
  EXPECT_EQ(eval("f(4)"), 12);
  // Later redefinitions win, even for expressions parsed earlier.
  Expression e = prog.parse_expression("f(1)");
  prog.load_string("y = 10;", "three.cal");
  EXPECT_EQ(ev.eval(e), 10);
  ASSERT_EQ(warnings.list().size(), 1u);
  EXPECT_EQ(warnings.list()[0], "y: redefined");
}

TEST_F(Calc, ConstantsFoldAtParseTime) {
  prog.load_string("k : 2*3; PI : 3.14159265358979323846; c : cos(PI*sqrt(2));", "t.cal");
  Expression e = prog.parse_expression("k + 1");
  ASSERT_EQ(e.root.op, Op::Num);
  EXPECT_EQ(e.root.num, 7);
  EXPECT_NEAR(eval("c"), -0.266255342, 1e-9);
  Expression f = prog.parse_expression("x*0 + 0/x + x^0");
  ASSERT_EQ(f.root.op, Op::Num); // x*0 -> 0, 0/x -> 0, x^0 -> 1, then 0 + 0 + 1
  EXPECT_EQ(f.root.num, 1);
  Expression g = prog.parse_expression("y/4");
  ASSERT_EQ(g.root.op, Op::Mul); // x/c becomes x*(1/c)
  EXPECT_EQ(g.root.kids[1].num, 0.25);
  EXPECT_EQ(eval("sin(PI/2)"), 1);
}

TEST_F(Calc, UserFunctions) {
  prog.load_string("sq(x) : x*x; hyp(a,b) = sqrt(sq(a)+sq(b)); apply(f, x) = f(x);"
                   "twice(f, x) = f(f(x));",
                   "t.cal");
  EXPECT_EQ(eval("hyp(3,4)"), 5);
  EXPECT_EQ(eval("apply(sq, 3)"), 9);
  EXPECT_NEAR(eval("apply(sin, 1)"), std::sin(1.0), 1e-15);
  EXPECT_EQ(eval("twice(sq, 3)"), 81);
  EXPECT_EQ(eval("hyp(3,4,99)"), 5); // extra arguments are ignored
}

TEST_F(Calc, CallByNeedArguments) {
  // A missing argument is an error only when it is used.
  prog.load_string("first(a,b) = a; second(a,b) = b; z = 0;", "t.cal");
  EXPECT_EQ(eval("first(1)"), 1);
  EXPECT_EQ(error_of("second(1)"), "second: too few arguments");
  // An unused argument is never evaluated (no division warning).
  EXPECT_EQ(eval("first(2, 1/z)"), 2);
  EXPECT_TRUE(warnings.list().empty());
}

TEST_F(Calc, IfAndSelect) {
  prog.load_string("z = 0;", "t.cal");
  EXPECT_EQ(eval("if(1, 2, 3)"), 2);
  EXPECT_EQ(eval("if(0, 2, 3)"), 3);
  EXPECT_EQ(eval("if(-1, 2, 3)"), 3);
  EXPECT_EQ(eval("if(1, 2, 1/z)"), 2); // only the chosen branch is evaluated
  EXPECT_TRUE(warnings.list().empty());
  EXPECT_EQ(eval("select(2, 10, 20, 30)"), 20);
  EXPECT_EQ(eval("select(2.4, 10, 20, 30)"), 20);
  EXPECT_EQ(eval("select(2.6, 10, 20, 30)"), 30);
  EXPECT_EQ(eval("select(0, 10, 20, 30)"), 3);   // 0: number of choices
  EXPECT_EQ(eval("select(z+4, 10, 20, 30)"), 0); // out of range: domain error, 0
  EXPECT_EQ(eval("select(z-1, 10, 20, 30)"), 0);
  ASSERT_EQ(warnings.list().size(), 2u);
  EXPECT_EQ(warnings.list()[0], "select: domain error");
  EXPECT_EQ(eval("min(3, 1, 2)"), 1);
  EXPECT_EQ(eval("max(3, 1, 5, 2)"), 5);
}

TEST_F(Calc, ArgAndRayVariables) {
  prog.load_rayinit();
  EXPECT_EQ(error_of("arg(1)"), "bad call to arg(n) - illegal constant in .cal file?");
  EXPECT_EQ(error_of("Dx"), "ray parameter used in constant expression");
  ev.set_args({5, 6, 7});
  EXPECT_EQ(eval("arg(0)"), 3);
  EXPECT_EQ(eval("AC"), 3);
  EXPECT_EQ(eval("arg(2)"), 6);
  EXPECT_EQ(eval("A3"), 7);
  EXPECT_EQ(error_of("A4"), "missing real argument 4");
  std::vector<double> ray(RC_CALC_NSLOTS, 0.0);
  ray[RC_CALC_DX] = 0.25;
  ray[RC_CALC_PZ] = -3;
  ray[RC_CALC_LV] = 0.5;
  ev.set_ray(ray);
  EXPECT_EQ(eval("Dx + Pz"), -2.75);
  EXPECT_EQ(eval("$1 + $9 + $27"), -2.25); // channels $1..$27
  EXPECT_EQ(eval("D(1)*4 + P(3)"), -2);
  EXPECT_EQ(error_of("$28"), "illegal channel number");
}

TEST_F(Calc, RayinitDefinitions) {
  prog.load_rayinit();
  EXPECT_NEAR(eval("PI"), M_PI, 1e-15);
  EXPECT_NEAR(eval("DEGREE*180"), M_PI, 1e-15);
  EXPECT_EQ(eval("bound(0, 2, 1)"), 1);
  EXPECT_EQ(eval("clip(-3)"), 0);
  EXPECT_EQ(eval("frac(2.25)"), 0.25);
  EXPECT_EQ(eval("mod(-1, 3)"), 2);
  EXPECT_EQ(eval("abs(-2) + sgn(-5) + sgn(0)"), 1);
  EXPECT_EQ(eval("and(1, -1) + or(-1, 1) + not(1)"), -1 + 1 - 1);
  EXPECT_EQ(eval("inside(0, 0.5, 1)"), 0.5);
  EXPECT_EQ(eval("hermite(1, 2, 0, 0, 0.5)"), 1.5);
  EXPECT_EQ(eval("Acos(2)"), 0);
  EXPECT_EQ(eval("Sqrt(-1)"), 0);
  EXPECT_EQ(eval("Exp(-200)"), 0);
  EXPECT_EQ(eval("Atan2(0, 0)"), 0);
  EXPECT_NEAR(eval("unif2norm(0.975)"), 1.96, 1e-3);
  prog.load_string("v1(i) = select(i, 1, 0, 0); v2(i) = select(i, 0, 1, 0);", "vec.cal");
  EXPECT_EQ(eval("dot(v1, v2)"), 0);
  EXPECT_EQ(eval("cross(3, v1, v2)"), 1); // x cross y = z
  EXPECT_TRUE(warnings.list().empty());
}

TEST_F(Calc, LibraryFunctions) {
  EXPECT_EQ(eval("floor(-1.5) + ceil(1.2)"), 0);
  EXPECT_NEAR(eval("atan2(1, -1)"), 3 * M_PI / 4, 1e-15);
  EXPECT_NEAR(eval("log10(1000) + log(exp(2))"), 5, 1e-14);
  EXPECT_NEAR(eval("erf(0.5) + erfc(0.5)"), 1, 1e-15);
  // rand(): Radiance's formula, deterministic and in [0,1).
  double x = 0.3, y = x * (1 / (1 + x * x) + 2.71828182845904);
  y += 0.785398163397447 - std::floor(y);
  y = 1e5 / y;
  EXPECT_EQ(eval("rand(0.3)"), y - std::floor(y));
  // Perlin noise is 0 on lattice points; its partials are finite differences.
  EXPECT_EQ(eval("noise3(1, 2, 3)"), 0);
  double n0 = eval("noise3(0.3, 0.4, 0.5)"), nb = eval("noise3(0.2995, 0.4, 0.5)");
  EXPECT_NEAR(eval("noise3x(0.3, 0.4, 0.5)"), (n0 - nb) / 0.0005, 1e-9);
  double f = eval("fnoise3(0.3, 0.4, 0.5)");
  EXPECT_GT(f, -1.5);
  EXPECT_LT(f, 1.5);
  EXPECT_NE(f, eval("fnoise3(0.31, 0.4, 0.5)"));
}

TEST_F(Calc, ArithmeticErrorsGiveZeroWithWarning) {
  prog.load_string("z = 0;", "t.cal");
  EXPECT_EQ(eval("1/z"), 0);
  EXPECT_EQ(eval("(z-8)^(1/3) + 2"), 2);
  EXPECT_EQ(eval("sqrt(z-1) + 1"), 1);
  EXPECT_EQ(eval("log(z)"), 0);
  EXPECT_EQ(eval("exp(1000+z)"), 0);
  ASSERT_EQ(warnings.list().size(), 5u);
  EXPECT_EQ(warnings.list()[0], "Division by zero");
  EXPECT_EQ(warnings.list()[1], "Illegal power");
  EXPECT_EQ(warnings.list()[2], "sqrt: domain error");
  EXPECT_EQ(warnings.list()[3], "log: range error");
  EXPECT_EQ(warnings.list()[4], "exp: range error");
  EXPECT_EQ(ev.errors(), RC_CALC_ERR_DIVIDE | RC_CALC_ERR_POWER | RC_CALC_ERR_DOMAIN);
}

TEST_F(Calc, Recursion) {
  prog.load_string("fact(n) = if(n-1, n*fact(n-1), 1); fib(n) = if(n-2, fib(n-1)+fib(n-2), 1);"
                   "bad(n) = n*bad(n-1); loop = loop + 1;",
                   "r.cal");
  EXPECT_EQ(eval("fact(10)"), 3628800);
  EXPECT_EQ(eval("fib(15)"), 610);
  ev.set_max_depth(100);
  EXPECT_EQ(error_of("bad(3)"), "bad: recursion deeper than 100 calls (missing base case?)");
  EXPECT_EQ(error_of("loop"), "loop: recursion deeper than 100 calls (missing base case?)");
  EXPECT_EQ(eval("fact(5)"), 120); // the evaluator is usable after the error
}

TEST_F(Calc, UndefinedNames) {
  EXPECT_EQ(error_of("nothing + 1"), "nothing: undefined variable");
  EXPECT_EQ(error_of("nofunc(1)"), "nofunc: undefined function");
  prog.load_string("f(x) = x;", "t.cal");
  EXPECT_EQ(error_of("f"), "f: undefined variable");
  EXPECT_EQ(error_of("if(1)"), "if: too few arguments");
}

TEST_F(Calc, SyntaxErrorsNameFileLineAndPosition) {
  EXPECT_EQ(load_error("a = 1;\nb = 2 +;\n"),
            "t.cal, line 2:\nb = 2 +;\n       ^ unexpected character");
  EXPECT_EQ(load_error("a = (1;"), "t.cal, line 1:\na = (1;\n      ^ ')' expected");
  EXPECT_EQ(load_error("a = 1 b = 2"), "t.cal, line 1:\na = 1 b = 2\n      ^ ';' expected");
  EXPECT_EQ(load_error("a = 1/0;"), "t.cal, line 1:\na = 1/0;\n       ^ bad constant expression");
  EXPECT_EQ(load_error("a = 1/(2-2);"),
            "t.cal, line 1:\na = 1/(2-2);\n           ^ bad constant expression");
  EXPECT_EQ(load_error("a = x/0;"), "t.cal, line 1:\na = x/0;\n       ^ divide by zero constant");
  EXPECT_EQ(load_error("a = 1e;"), "t.cal, line 1:\na = 1e;\n      ^ missing exponent");
  EXPECT_EQ(load_error("a = .;"), "t.cal, line 1:\na = .;\n     ^ badly formed number");
  EXPECT_EQ(load_error("3 = 1;"), "t.cal, line 1:\n3 = 1;\n^ illegal variable name");
  EXPECT_EQ(load_error("f(1) = 1;"), "t.cal, line 1:\nf(1) = 1;\n  ^ illegal parameter name");
  EXPECT_EQ(load_error("a + 1;"), "t.cal, line 1:\na + 1;\n  ^ '=' or ':' expected");
  EXPECT_EQ(load_error("a = 1 {open"), "t.cal, line 1:\na = 1 {open\n           ^ '}' expected");
}

TEST_F(Calc, Contexts) {
  prog.load_rayinit();
  EXPECT_EQ(Program::context_for_file("/x/my file.cal"), "my_file");
  EXPECT_EQ(Program::context_for_file("."), "");
  prog.load_string("k = 2; A1 = 100; g` = 5; `h = 6;", "mine.cal", "mine");
  EXPECT_EQ(ev.eval(prog.parse_expression("k * g + h", "mine")), 16);
  EXPECT_EQ(error_of("k"), "k: undefined variable"); // local to the context
  EXPECT_EQ(eval("g"), 5);                           // defined global with a trailing `
  EXPECT_EQ(eval("k`mine"), 2);                      // explicit context
  ev.set_args({1});
  EXPECT_EQ(eval("A1"), 1); // the global A1 of rayinit.cal is untouched
  EXPECT_EQ(ev.eval(prog.parse_expression("A1", "mine")), 100);
}
