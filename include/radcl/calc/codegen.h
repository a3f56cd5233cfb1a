// OpenCL C generation for .cal definitions: the scene compiler asks for the variables,
// functions and expressions its primitives use and gets back the names of generated functions;
// source() is the code (to be placed in a program's generated.cl). Only what was requested and
// what that reaches is emitted; variables that need no ray or arguments are folded on the host.
//
// Generated functions have the signature
//   rc_calc_real NAME(rc_calc_env* e [, rc_calc_real a1, ...])
// (radcl/calc/device_context.h): e carries the ray variables, the primitive's real arguments and
// the error bits that replace Radiance's warnings. Arguments are passed by value (evaluated
// before the call, where Radiance evaluates them on first use; the results are the same since
// the language has no side effects). if() and select() evaluate only the chosen branch.
//
// Recursion (forbidden in OpenCL C) is unrolled: a function that is part of a call cycle gets
// one copy per nesting level up to Options::recursion_depth; a call beyond that returns 0 and
// sets RC_CALC_ERR_DEPTH. Functions passed as arguments (dot(v1,v2) of rayinit.cal) get one
// copy per combination of functions passed.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radcl/calc/ast.h"

namespace radcl::calc {

class Program;

class CodeGenerator {
public:
  struct Options {
    int recursion_depth = 16;  // nesting levels generated for recursive functions
    int max_functions = 20000; // generated functions before giving up (runaway specialisation)
  };

  explicit CodeGenerator(Program& program);
  CodeGenerator(Program& program, Options options);
  ~CodeGenerator();

  // rc_calc_real NAME(rc_calc_env* e): the value of variable `name` seen from `context`
  // (a definition or a ray variable). Errors (undefined variable, ...) throw FatalError.
  std::string request_variable(std::string_view name, const std::string& context = "");
  // rc_calc_real NAME(rc_calc_env* e, rc_calc_real a1 .. a<nargs>): function `name` (user or
  // library) called with nargs arguments, e.g. a colordata function of 1 or 3 values or a
  // plasfunc reflection function of (dx, dy, dz, omega).
  std::string request_function(std::string_view name, int nargs, const std::string& context = "");
  // rc_calc_real NAME(rc_calc_env* e): an expression (a scene string argument).
  std::string request_expression(const Expression& expr);

  // The generated OpenCL C: an include of the runtime, prototypes, then every function.
  std::string source();

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
};

} // namespace radcl::calc
