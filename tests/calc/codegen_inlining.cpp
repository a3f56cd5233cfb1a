// The generated source keeps its longer functions out of line (RC_NOINLINE): a compiler that
// inlines everything, as NVIDIA's does, would copy them into every call (docs/internals.md).
// Short ones stay inline, and copies of recursive functions keep their own marker only.
#include <gtest/gtest.h>
#include <string>

#include "radcl/calc/codegen.h"
#include "radcl/calc/program.h"

using namespace radcl::calc;

namespace {
bool has_line_starting(const std::string& src, const std::string& start) {
  return src.find("\n" + start) != std::string::npos;
}
} // namespace

TEST(CodeGenInlining, LongerFunctionsStayOutOfLine) {
  Program prog;
  prog.load_string("short(x) = x + 1;\n"
                   "long(x) = sin(x) * cos(x) + exp(x / 3) * acos(x / 10) + sqrt(x * x + 1) * "
                   "log(x * x + 2) + atan2(x, 2) * floor(x * 7) + tan(x / 4) * asin(x / 9);\n"
                   "fact(n) = if(n - 1, n * fact(n - 1), 1);\n",
                   "inlining.cal");
  CodeGenerator gen(prog);
  gen.request_function("short", 1, "");
  gen.request_function("long", 1, "");
  gen.request_function("fact", 1, "");
  const std::string src = gen.source();
  EXPECT_TRUE(has_line_starting(src, "RC_NOINLINE rc_calc_real rc_cal_long_")) << src;
  EXPECT_TRUE(has_line_starting(src, "rc_calc_real rc_cal_short_")) << src;
  EXPECT_FALSE(has_line_starting(src, "RC_NOINLINE rc_calc_real rc_cal_short_")) << src;
  EXPECT_TRUE(has_line_starting(src, "RC_CALC_NOINLINE rc_calc_real rc_cal_fact_")) << src;
  EXPECT_EQ(src.find("RC_NOINLINE RC_CALC_NOINLINE"), std::string::npos) << src;
}
