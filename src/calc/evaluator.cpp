#include "radcl/calc/evaluator.h"
#include <cstdint>

#include <cmath>

#include "radcl/calc/library.h"
#include "radcl/calc/program.h"
#include "radcl/util/error.h"

#define RC_NOISE_REAL double
#include "radcl/calc/noise.h"

namespace radcl::calc {

// An active call: where its arguments come from (unevaluated nodes in the caller's context and
// frame, evaluated on first use and then cached — call-by-need), or given values.
struct Evaluator::Frame {
  const std::string* name = nullptr;
  const std::vector<Node>* nodes = nullptr;
  const std::string* nodes_ctx = nullptr;
  Frame* nodes_frame = nullptr;
  const double* values = nullptr;
  int nargs = 0;
  static constexpr int kCached = 16;
  double cached[kCached];
  std::uint32_t have = 0;
};

Evaluator::Evaluator(Program& program) : program_(program) {}

void Evaluator::set_ray(std::span<const double> slots) {
  for (int i = 0; i < RC_CALC_NSLOTS; ++i)
    slots_[i] = i < static_cast<int>(slots.size()) ? slots[i] : 0.0;
  has_ray_ = true;
  ++tick_;
}

void Evaluator::set_ray(const rc_calc_ray& ray) {
  double v[RC_CALC_NSLOTS];
  for (int i = 0; i < RC_CALC_NSLOTS; ++i)
    v[i] = ray.v[i];
  set_ray(v);
}

void Evaluator::clear_ray() {
  has_ray_ = false;
  ++tick_;
}

void Evaluator::set_args(std::vector<double> args) {
  args_ = std::move(args);
  has_args_ = true;
  ++tick_;
}

void Evaluator::clear_args() {
  args_.clear();
  has_args_ = false;
  ++tick_;
}

double Evaluator::eval(const Expression& e) {
  return eval_node(e.root, e.context, nullptr);
}

double Evaluator::eval(const Node& n, const std::string& context) {
  return eval_node(n, context, nullptr);
}

double Evaluator::variable(std::string_view name, const std::string& context) {
  return eval_variable(name, context);
}

double Evaluator::call(std::string_view name, std::span<const double> args,
                       const std::string& context) {
  static const std::vector<Node> none;
  std::vector<Node> nodes(args.size());
  return call_named(name, context, nullptr, nodes, context, nullptr, args.data());
}

void Evaluator::raise(int bit, const std::string& msg) {
  errors_ |= bit;
  if (warn_) warning(msg);
}

double Evaluator::argument(Frame& f, int i) {
  if (i < Frame::kCached && (f.have >> i & 1u)) return f.cached[i];
  if (i >= f.nargs) throw FatalError(*f.name + ": too few arguments");
  double v = f.values ? f.values[i] : eval_node((*f.nodes)[i], *f.nodes_ctx, f.nodes_frame);
  if (i < Frame::kCached) {
    f.cached[i] = v;
    f.have |= 1u << i;
  }
  return v;
}

double Evaluator::eval_variable(std::string_view name, const std::string& ctx) {
  if (const Definition* d = program_.lookup(name, ctx)) {
    if (d->function) throw FatalError(std::string(name) + ": undefined variable");
    if (d->body.is_num()) return d->body.num;
    if (cache_.size() <= static_cast<std::size_t>(d->id)) cache_.resize(d->id + 1, {0, 0.0});
    auto& slot = cache_[d->id];
    if (slot.first == tick_) return slot.second;
    bool outer_used = used_context_;
    used_context_ = false;
    // A variable defined through itself recurses like a function without a base case.
    if (depth_ >= max_depth_)
      throw FatalError(d->name + ": recursion deeper than " + std::to_string(max_depth_) +
                       " calls (missing base case?)");
    ++depth_;
    double v;
    try {
      v = eval_node(d->body, d->context, nullptr);
    } catch (...) {
      --depth_;
      throw;
    }
    --depth_;
    // A `:` constant that needed no ray or arguments keeps its value for good.
    if (d->constant && !used_context_) const_cast<Definition*>(d)->body = Node::number(v);
    used_context_ = used_context_ || outer_used;
    cache_[d->id] = {tick_, v};
    return v;
  }
  int slot = ray_slot(name);
  if (slot >= 0) {
    if (!has_ray_) throw FatalError("ray parameter used in constant expression");
    used_context_ = true;
    return slots_[slot];
  }
  throw FatalError(std::string(name) + ": undefined variable");
}

double Evaluator::eval_node(const Node& n, const std::string& ctx, Frame* frame) {
  // Long operator chains make deep trees, and recursion through variables walks them again at
  // every level: the total nesting is bounded too, so that it ends in an error, not in a stack
  // overflow.
  const char marker = 0;
  const auto here = reinterpret_cast<std::uintptr_t>(&marker);
  if (node_depth_ == 0) stack_top_ = here;
  if (node_depth_ >= kMaxNodeDepth || (stack_top_ > here && stack_top_ - here > kStackBudget))
    throw FatalError("expression too deeply nested to evaluate");
  struct Nest {
    int& d;
    explicit Nest(int& x) : d(x) { ++d; }
    ~Nest() { --d; }
  } nest{node_depth_};
  switch (n.op) {
  case Op::Num:
    return n.num;
  case Op::Var:
    return eval_variable(n.name, ctx);
  case Op::Param:
    return argument(*frame, n.index);
  case Op::Chan:
    if (n.index < 1 || n.index > RC_CALC_NCHANNELS) throw FatalError("illegal channel number");
    if (!has_ray_) throw FatalError("ray parameter used in constant expression");
    used_context_ = true;
    return slots_[n.index - 1];
  case Op::Add:
    return eval_node(n.kids[0], ctx, frame) + eval_node(n.kids[1], ctx, frame);
  case Op::Sub:
    return eval_node(n.kids[0], ctx, frame) - eval_node(n.kids[1], ctx, frame);
  case Op::Mul:
    return eval_node(n.kids[0], ctx, frame) * eval_node(n.kids[1], ctx, frame);
  case Op::Div: {
    double d = eval_node(n.kids[1], ctx, frame);
    if (d == 0.0) {
      raise(RC_CALC_ERR_DIVIDE, "Division by zero");
      return 0.0;
    }
    return eval_node(n.kids[0], ctx, frame) / d;
  }
  case Op::Pow: {
    double a = eval_node(n.kids[0], ctx, frame);
    double r = std::pow(a, eval_node(n.kids[1], ctx, frame));
    if (!std::isfinite(r)) {
      raise(RC_CALC_ERR_POWER, "Illegal power");
      return 0.0;
    }
    return r;
  }
  case Op::Neg:
    return -eval_node(n.kids[0], ctx, frame);
  case Op::Call:
    return call_named(n.name, ctx, frame, n.kids, ctx, frame, nullptr);
  case Op::PCall: {
    // The argument in that position must name a function; follow parameters passed on.
    Frame* f = frame;
    int index = n.index;
    for (;;) {
      if (!f || f->values || index >= f->nargs)
        throw FatalError(*frame->name + (f && index >= f->nargs && !f->values
                                             ? ": too few arguments"
                                             : ": argument not a function"));
      const Node& a = (*f->nodes)[index];
      if (a.op == Op::Var)
        return call_named(a.name, *f->nodes_ctx, f->nodes_frame, n.kids, ctx, frame, nullptr);
      if (a.op != Op::Param) throw FatalError(*frame->name + ": argument not a function");
      index = a.index;
      f = f->nodes_frame;
    }
  }
  }
  return 0.0;
}

double Evaluator::call_named(std::string_view name, const std::string& ctx, Frame*,
                             const std::vector<Node>& args, const std::string& args_ctx,
                             Frame* args_frame, const double* values) {
  Frame f;
  f.nodes = &args;
  f.nodes_ctx = &args_ctx;
  f.nodes_frame = args_frame;
  f.values = values;
  f.nargs = static_cast<int>(args.size());
  const Definition* d = program_.lookup(name, ctx);
  if (d && d->function) {
    f.name = &d->name;
    if (depth_ >= max_depth_)
      throw FatalError(d->name + ": recursion deeper than " + std::to_string(max_depth_) +
                       " calls (missing base case?)");
    ++depth_;
    struct Leave {
      int& depth;
      ~Leave() { --depth; }
    } leave{depth_};
    return eval_node(d->body, d->context, &f);
  }
  const LibraryFunction* lib = find_library(name);
  if (!lib) throw FatalError(std::string(name) + ": undefined function");
  std::string lib_name(lib->name);
  f.name = &lib_name;
  return library(static_cast<int>(lib->id), lib_name, f);
}

double Evaluator::library(int id, const std::string& name, Frame& f) {
  auto a = [&](int i) { return argument(f, i); };
  double r = 0.0;
  switch (static_cast<Lib>(id)) {
  case Lib::If:
    r = a(0) > 0.0 ? a(1) : a(2);
    break;
  case Lib::Select: {
    double s = a(0);
    long k = round_index(s);
    if (s < -0.5 || k >= f.nargs) {
      raise(RC_CALC_ERR_DOMAIN, name + ": domain error");
      return 0.0;
    }
    r = k == 0 ? f.nargs - 1 : a(static_cast<int>(k));
    break;
  }
  case Lib::Min:
  case Lib::Max: {
    // Radiance's order: the first argument, then the others from last to second.
    r = a(0);
    bool is_max = static_cast<Lib>(id) == Lib::Max;
    for (int i = f.nargs - 1; i >= 1; --i) {
      double v = a(i);
      if (is_max ? r < v : r > v) r = v;
    }
    break;
  }
  case Lib::Rand: {
    double x = a(0);
    x *= 1.0 / (1.0 + x * x) + 2.71828182845904;
    x += 0.785398163397447 - std::floor(x);
    x = 1e5 / x;
    r = x - std::floor(x);
    break;
  }
  case Lib::Floor:
    r = std::floor(a(0));
    break;
  case Lib::Ceil:
    r = std::ceil(a(0));
    break;
  case Lib::Sqrt:
    r = std::sqrt(a(0));
    break;
  case Lib::Sin:
    r = std::sin(a(0));
    break;
  case Lib::Cos:
    r = std::cos(a(0));
    break;
  case Lib::Tan:
    r = std::tan(a(0));
    break;
  case Lib::Asin:
    r = std::asin(a(0));
    break;
  case Lib::Acos:
    r = std::acos(a(0));
    break;
  case Lib::Atan:
    r = std::atan(a(0));
    break;
  case Lib::Atan2:
    r = std::atan2(a(0), a(1));
    break;
  case Lib::Exp:
    r = std::exp(a(0));
    break;
  case Lib::Log:
    r = std::log(a(0));
    break;
  case Lib::Log10:
    r = std::log10(a(0));
    break;
  case Lib::Erf:
    r = std::erf(a(0));
    break;
  case Lib::Erfc:
    r = std::erfc(a(0));
    break;
  case Lib::Noise3:
    r = rc_noise3(a(0), a(1), a(2), 3);
    break;
  case Lib::Noise3x:
    r = rc_noise3(a(0), a(1), a(2), 0);
    break;
  case Lib::Noise3y:
    r = rc_noise3(a(0), a(1), a(2), 1);
    break;
  case Lib::Noise3z:
    r = rc_noise3(a(0), a(1), a(2), 2);
    break;
  case Lib::Fnoise3:
    r = rc_fnoise3(a(0), a(1), a(2));
    break;
  case Lib::Arg: {
    if (!has_args_) throw FatalError("bad call to arg(n) - illegal constant in .cal file?");
    used_context_ = true;
    long k = round_index(a(0));
    if (k < 1) return static_cast<double>(args_.size());
    if (k > static_cast<long>(args_.size()))
      throw FatalError("missing real argument " + std::to_string(k));
    return args_[k - 1];
  }
  }
  if (!std::isfinite(r)) {
    raise(RC_CALC_ERR_DOMAIN, name + (std::isnan(r) ? ": domain error" : ": range error"));
    return 0.0;
  }
  return r;
}

double fold_constant(Program& program, const Node& n, const std::string& context, bool& ok) {
  Evaluator ev(program);
  ev.set_warnings(false);
  double v = ev.eval(n, context);
  ok = ev.errors() == 0;
  return v;
}

} // namespace radcl::calc
