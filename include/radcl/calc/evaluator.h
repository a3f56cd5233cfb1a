// Host evaluation of .cal expressions in double precision, with Radiance's semantics
// (../shared/docs/radiance/calc-language.md §3.2-§3.4): call-by-need arguments, `=` variables
// cached per ray, division by zero / illegal powers / library domain errors give 0 with a warning,
// undefined names and missing arguments are fatal. Used for constant folding, the `radcl calc`
// command and tests; rendering evaluates the generated device code instead (codegen.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "radcl/calc/ast.h"
#include "radcl/calc/device_context.h"

namespace radcl::calc {

class Program;

class Evaluator {
public:
  explicit Evaluator(Program& program);

  // The ray being shaded: values by rc_calc_slot. Without one, using a ray variable is fatal
  // ("ray parameter used in constant expression"), as in a `:` constant.
  void set_ray(std::span<const double> slots);
  void set_ray(const rc_calc_ray& ray); // float slots widened to double
  void clear_ray();
  // The primitive's real arguments (arg(n), A1..). Without them arg() is fatal.
  void set_args(std::vector<double> args);
  void clear_args();

  double eval(const Expression& e);
  double eval(const Node& n, const std::string& context = "");
  double variable(std::string_view name, const std::string& context = "");
  double call(std::string_view name, std::span<const double> args, const std::string& context = "");

  // Deepest nesting of user-function calls before evaluation stops with a FatalError (Radiance
  // has no limit and overflows the stack).
  void set_max_depth(int depth) { max_depth_ = depth; }
  // RC_CALC_ERR_* bits raised since the last reset (the warnings Radiance prints).
  int errors() const { return errors_; }
  void reset_errors() { errors_ = 0; }
  // Print Radiance's warnings (via radcl::warning); on by default.
  void set_warnings(bool on) { warn_ = on; }
  // Whether the last evaluations read the ray or the real arguments.
  bool used_context() const { return used_context_; }
  void reset_used_context() { used_context_ = false; }

  struct Frame; // one active user-function call

private:
  double eval_node(const Node& n, const std::string& ctx, Frame* frame);
  double eval_call(const Node& n, const std::string& ctx, Frame* frame);
  double call_named(std::string_view name, const std::string& ctx, Frame* frame,
                    const std::vector<Node>& args, const std::string& args_ctx, Frame* args_frame,
                    const double* values);
  double library(int lib, const std::string& name, Frame& f);
  double argument(Frame& f, int i);
  double eval_variable(std::string_view name, const std::string& ctx);
  void raise(int bit, const std::string& msg);

  Program& program_;
  double slots_[RC_CALC_NSLOTS] = {};
  bool has_ray_ = false;
  std::vector<double> args_;
  bool has_args_ = false;
  std::uint64_t tick_ = 1;
  std::vector<std::pair<std::uint64_t, double>> cache_; // by Definition::id
  int max_depth_ = 400;
  int depth_ = 0;
  static constexpr int kMaxNodeDepth = 8000;
  // Stack the evaluation may use below its outermost call: frames differ in size between
  // builds (sanitizers make them several times larger), so the depth alone cannot bound it.
  // 2 MiB fits the main thread's 8 MiB and a worker thread's 4 MiB.
  static constexpr std::uintptr_t kStackBudget = 2u << 20;
  int node_depth_ = 0;
  std::uintptr_t stack_top_ = 0;
  int errors_ = 0;
  bool warn_ = true;
  bool used_context_ = false;
};

// Folds `n` to a number at parse time (no ray, no arguments): sets `ok` false when it raised an
// arithmetic error. Throws what evaluation throws.
double fold_constant(Program& program, const Node& n, const std::string& context, bool& ok);

} // namespace radcl::calc
