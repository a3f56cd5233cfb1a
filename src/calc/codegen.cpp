#include "radcl/calc/codegen.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include "radcl/calc/evaluator.h"
#include "radcl/calc/library.h"
#include "radcl/calc/program.h"
#include "radcl/util/error.h"

namespace radcl::calc {
namespace {

// Generated bodies longer than this many characters are kept out of line (source()).
constexpr std::size_t kInlineBody = 160;

// What a function-valued parameter is bound to in one specialised copy.
struct Callee {
  const Definition* def = nullptr;
  const LibraryFunction* lib = nullptr;
  bool set() const { return def || lib; }
  std::string key() const { return def ? def->name : lib ? std::string("lib:") + lib->name : ""; }
};

std::string literal(double v) {
  if (std::isinf(v)) return v > 0 ? "((rc_calc_real)INFINITY)" : "((rc_calc_real)-INFINITY)";
  if (std::isnan(v)) return "((rc_calc_real)NAN)";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s(buf);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return v < 0 ? "(" + s + ")" : s;
}

// A C identifier fragment for a qualified .cal name (letters, digits, '_' kept).
std::string mangle(std::string_view name) {
  std::string out;
  for (char c : name) {
    unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u))
      out += c;
    else
      out += '_';
  }
  return out;
}

void scan(const Node& n, const std::function<void(const Node&)>& f) {
  f(n);
  for (const Node& k : n.kids)
    scan(k, f);
}

} // namespace

struct CodeGenerator::Impl {
  Program& prog;
  Options opt;

  struct Function {
    std::string name, proto, body;
    bool recursive = false; // its proto carries RC_CALC_NOINLINE
  };
  std::vector<Function> functions;
  std::map<std::string, std::string> by_key; // instance or wrapper key -> function name

  struct Pending {
    std::size_t index;
    const Definition* def;
    int depth;
    std::vector<Callee> bound;
  };
  std::vector<Pending> pending;

  std::map<int, int> scc;                      // definition id -> component
  std::map<int, std::optional<double>> folded; // variable definition id -> host value
  bool scc_done = false;
  std::set<int> cyclic, self; // components with more than one definition; self-referencing ids

  struct Scope {
    const Definition* def = nullptr; // the definition being generated; null in wrappers
    int depth = 0;
    const std::vector<Callee>* bound = nullptr;
    std::string ctx;
    std::vector<std::string> params; // C names of value parameters ("" where bound)
    std::string fname;
    int temps = 0;
  };

  Impl(Program& p, Options o) : prog(p), opt(o) {}

  [[noreturn]] static void fail(const std::string& msg) { throw FatalError(msg); }

  // Strongly connected components of the definitions' reference graph (Tarjan).
  void compute_scc() {
    if (scc_done) return;
    scc_done = true;
    std::vector<const Definition*> defs = prog.definitions();
    std::map<int, int> index, low;
    std::vector<const Definition*> stack;
    std::map<int, bool> on;
    int counter = 0, comp = 0;
    std::function<void(const Definition*)> visit = [&](const Definition* d) {
      index[d->id] = low[d->id] = counter++;
      stack.push_back(d);
      on[d->id] = true;
      scan(d->body, [&](const Node& n) {
        if (n.op != Op::Var && n.op != Op::Call) return;
        const Definition* t = prog.lookup(n.name, d->context);
        if (!t) return;
        if (t == d) self.insert(d->id);
        if (!index.count(t->id)) {
          visit(t);
          low[d->id] = std::min(low[d->id], low[t->id]);
        } else if (on[t->id]) {
          low[d->id] = std::min(low[d->id], index[t->id]);
        }
      });
      if (low[d->id] == index[d->id]) {
        const Definition* t;
        int size = 0;
        do {
          t = stack.back();
          stack.pop_back();
          on[t->id] = false;
          scc[t->id] = comp;
          ++size;
        } while (t != d);
        if (size > 1) cyclic.insert(comp);
        ++comp;
      }
    };
    for (const Definition* d : defs)
      if (!index.count(d->id)) visit(d);
  }

  bool recursive(const Definition* d) {
    compute_scc();
    return self.count(d->id) || cyclic.count(scc[d->id]);
  }

  bool same_cycle(const Definition* a, const Definition* b) {
    if (!a) return false;
    compute_scc();
    auto ia = scc.find(a->id), ib = scc.find(b->id);
    return ia != scc.end() && ib != scc.end() && ia->second == ib->second;
  }

  static std::vector<bool> function_params(const Definition* d) {
    std::vector<bool> fp(d->params.size(), false);
    scan(d->body, [&](const Node& n) {
      if (n.op == Op::PCall && n.index < static_cast<int>(fp.size())) fp[n.index] = true;
    });
    return fp;
  }

  static bool param_used(const Definition* d, int i) {
    bool used = false;
    scan(d->body, [&](const Node& n) { used = used || (n.op == Op::Param && n.index == i); });
    return used;
  }

  std::string add_function(const std::string& key, const std::string& name,
                           const std::string& proto) {
    if (static_cast<int>(functions.size()) >= opt.max_functions)
      fail("too many generated .cal functions (runaway specialisation?)");
    by_key[key] = name;
    functions.push_back({name, proto, ""});
    return name;
  }

  // The generated copy of `d` at recursion level `depth` with its function parameters bound.
  std::string instance(const Definition* d, int depth, const std::vector<Callee>& bound) {
    std::string key = "def:" + d->name + "#" + std::to_string(depth);
    for (const Callee& c : bound)
      key += "#" + c.key();
    if (auto it = by_key.find(key); it != by_key.end()) return it->second;
    std::string name = "rc_cal_" + mangle(d->name) + "_" + std::to_string(functions.size());
    // Copies of recursive functions stay calls: inlining the whole unrolled chain makes
    // programs that take minutes to compile.
    const bool rec = recursive(d);
    std::string proto =
        std::string(rec ? "RC_CALC_NOINLINE " : "") + "rc_calc_real " + name + "(rc_calc_env* e";
    for (std::size_t i = 0; i < d->params.size(); ++i)
      if (!bound[i].set()) proto += ", rc_calc_real p" + std::to_string(i);
    proto += ")";
    add_function(key, name, proto);
    functions.back().recursive = rec;
    pending.push_back({functions.size() - 1, d, depth, bound});
    return name;
  }

  void drain() {
    while (!pending.empty()) {
      Pending p = std::move(pending.back());
      pending.pop_back();
      Scope sc;
      sc.def = p.def;
      sc.depth = p.depth;
      sc.bound = &p.bound;
      sc.ctx = p.def->context;
      sc.fname = p.def->name;
      for (std::size_t i = 0; i < p.def->params.size(); ++i)
        sc.params.push_back(p.bound[i].set() ? "" : "p" + std::to_string(i));
      std::string out;
      std::string value = gen(p.def->body, sc, out);
      functions[p.index].body = out + "  return " + value + ";\n";
    }
  }

  std::string temp(Scope& sc, std::string& out, const std::string& init = "") {
    std::string t = "t" + std::to_string(sc.temps++);
    out += "  rc_calc_real " + t + (init.empty() ? "" : " = " + init) + ";\n";
    return t;
  }

  std::optional<double> fold_variable(const Definition* d, const Node& n, const std::string& ctx) {
    auto it = folded.find(d->id);
    if (it != folded.end()) return it->second;
    std::optional<double> v;
    try {
      Evaluator ev(prog);
      ev.set_warnings(false);
      double x = ev.eval(n, ctx);
      if (ev.errors() == 0) v = x;
    } catch (const FatalError&) {
    }
    folded[d->id] = v;
    return v;
  }

  Callee resolve_callee(const Node& n, Scope& sc) {
    if (n.op == Op::Var) {
      Callee c;
      const Definition* d = prog.lookup(n.name, sc.ctx);
      if (d && d->function)
        c.def = d;
      else
        c.lib = find_library(n.name);
      if (!c.set()) fail(n.name + ": undefined function");
      return c;
    }
    if (n.op == Op::Param && sc.bound && (*sc.bound)[n.index].set()) return (*sc.bound)[n.index];
    fail(sc.fname + ": argument not a function");
  }

  std::string user_call(const Definition* d, const std::vector<Node>& kids, Scope& sc,
                        std::string& out) {
    int depth = same_cycle(sc.def, d) ? sc.depth + 1 : 0;
    if (depth > opt.recursion_depth) return "rc_calc_too_deep(e)";
    std::vector<bool> fp = function_params(d);
    std::vector<Callee> bound(d->params.size());
    std::string args;
    for (std::size_t i = 0; i < d->params.size(); ++i) {
      if (fp[i]) {
        if (i >= kids.size()) fail(d->name + ": too few arguments");
        bound[i] = resolve_callee(kids[i], sc);
      } else if (i < kids.size()) {
        args += ", " + gen(kids[i], sc, out);
      } else if (param_used(d, static_cast<int>(i))) {
        fail(d->name + ": too few arguments");
      } else {
        args += ", 0.0";
      }
    }
    return instance(d, depth, bound) + "(e" + args + ")";
  }

  std::string lib_call(const LibraryFunction* lib, const std::vector<Node>& kids, Scope& sc,
                       std::string& out) {
    int n = static_cast<int>(kids.size());
    if (n < lib->args) fail(std::string(lib->name) + ": too few arguments");
    auto arg = [&](int i) { return gen(kids[i], sc, out); };
    auto check = [](const std::string& x) { return "rc_calc_check(e, " + x + ")"; };
    switch (lib->id) {
    case Lib::If: {
      std::string c = arg(0);
      std::string t = temp(sc, out);
      std::string a, b;
      std::string va = gen(kids[1], sc, a), vb = gen(kids[2], sc, b);
      out += "  if ((" + c + ") > 0) {\n" + a + "  " + t + " = " + va + ";\n  } else {\n" + b +
             "  " + t + " = " + vb + ";\n  }\n";
      return check(t);
    }
    case Lib::Select: {
      std::string s = temp(sc, out, arg(0));
      std::string t = temp(sc, out);
      std::string k = "k" + std::to_string(sc.temps++);
      out += "  int " + k + " = rc_calc_index(" + s + ");\n";
      out += "  if (" + s + " < -0.5 || " + k + " >= " + std::to_string(n) + ") {\n    " + t +
             " = rc_calc_check(e, (rc_calc_real)NAN);\n  } else if (" + k + " == 0) {\n    " + t +
             " = " + std::to_string(n - 1) + ".0;\n  }";
      for (int i = 1; i < n; ++i) {
        std::string body;
        std::string v = gen(kids[i], sc, body);
        out += " else if (" + k + " == " + std::to_string(i) + ") {\n" + body + "  " + t + " = " +
               v + ";\n  }";
      }
      out += "\n";
      return check(t);
    }
    case Lib::Min:
    case Lib::Max: {
      std::string t = temp(sc, out, arg(0));
      const char* cmp = lib->id == Lib::Max ? " < " : " > ";
      for (int i = n - 1; i >= 1; --i) {
        std::string v = temp(sc, out, arg(i));
        out += "  if (" + t + cmp + v + ") " + t + " = " + v + ";\n";
      }
      return check(t);
    }
    case Lib::Rand:
      return check("rc_calc_rand(" + arg(0) + ")");
    case Lib::Arg:
      return "rc_calc_arg(e, " + arg(0) + ")";
    case Lib::Atan2: // in rc_calc_real, as pow (kernels/calc/runtime.cl)
      return check("rc_calc_atan2(" + arg(0) + ", " + arg(1) + ")");
    case Lib::Noise3:
    case Lib::Noise3x:
    case Lib::Noise3y:
    case Lib::Noise3z:
    case Lib::Fnoise3: {
      std::string x = arg(0), y = arg(1), z = arg(2);
      if (lib->id == Lib::Fnoise3) return check("rc_fnoise3(" + x + ", " + y + ", " + z + ")");
      int axis =
          lib->id == Lib::Noise3 ? 3 : static_cast<int>(lib->id) - static_cast<int>(Lib::Noise3x);
      return check("rc_noise3(" + x + ", " + y + ", " + z + ", " + std::to_string(axis) + ")");
    }
    default:
      return check(std::string(lib->name) + "(" + arg(0) + ")");
    }
  }

  std::string gen(const Node& n, Scope& sc, std::string& out) {
    switch (n.op) {
    case Op::Num:
      return literal(n.num);
    case Op::Param:
      if (n.index >= static_cast<int>(sc.params.size())) fail(sc.fname + ": too few arguments");
      if (sc.params[n.index].empty()) fail(n.name + ": undefined variable");
      return sc.params[n.index];
    case Op::Chan:
      if (n.index < 1 || n.index > RC_CALC_NCHANNELS) fail("illegal channel number");
      return "((rc_calc_real)e->ray.v[" + std::to_string(n.index - 1) + "])";
    case Op::Var: {
      if (const Definition* d = prog.lookup(n.name, sc.ctx)) {
        if (d->function) fail(n.name + ": undefined variable");
        if (auto v = fold_variable(d, n, sc.ctx)) return literal(*v);
        int depth = same_cycle(sc.def, d) ? sc.depth + 1 : 0;
        if (depth > opt.recursion_depth) return "rc_calc_too_deep(e)";
        return instance(d, depth, {}) + "(e)";
      }
      int slot = ray_slot(n.name);
      if (slot >= 0) return "((rc_calc_real)e->ray.v[" + std::to_string(slot) + "])";
      fail(n.name + ": undefined variable");
    }
    case Op::Add:
    case Op::Sub:
    case Op::Mul: {
      std::string a = gen(n.kids[0], sc, out);
      std::string b = gen(n.kids[1], sc, out);
      const char* op = n.op == Op::Add ? " + " : n.op == Op::Sub ? " - " : " * ";
      return "(" + a + op + b + ")";
    }
    case Op::Div: {
      std::string a = gen(n.kids[0], sc, out);
      return "rc_calc_div(e, " + a + ", " + gen(n.kids[1], sc, out) + ")";
    }
    case Op::Pow: {
      std::string a = gen(n.kids[0], sc, out);
      return "rc_calc_pow(e, " + a + ", " + gen(n.kids[1], sc, out) + ")";
    }
    case Op::Neg:
      return "(-" + gen(n.kids[0], sc, out) + ")";
    case Op::Call: {
      const Definition* d = prog.lookup(n.name, sc.ctx);
      if (d && d->function) return user_call(d, n.kids, sc, out);
      if (const LibraryFunction* lib = find_library(n.name)) return lib_call(lib, n.kids, sc, out);
      fail(n.name + ": undefined function");
    }
    case Op::PCall: {
      if (!sc.bound || n.index >= static_cast<int>(sc.bound->size()) || !(*sc.bound)[n.index].set())
        fail(sc.fname + ": argument not a function");
      const Callee& c = (*sc.bound)[n.index];
      return c.def ? user_call(c.def, n.kids, sc, out) : lib_call(c.lib, n.kids, sc, out);
    }
    }
    fail("bad expression");
  }

  // A wrapper function with `nparams` value parameters whose body is `body` seen from `ctx`.
  std::string wrapper(const std::string& key, const std::string& stem, const Node& body,
                      const std::string& ctx, int nparams) {
    if (auto it = by_key.find(key); it != by_key.end()) return it->second;
    std::string name = "rc_cal_" + stem + "_" + std::to_string(functions.size());
    Scope sc;
    sc.ctx = ctx;
    sc.fname = name;
    std::string proto = "rc_calc_real " + name + "(rc_calc_env* e";
    for (int i = 0; i < nparams; ++i) {
      sc.params.push_back("a" + std::to_string(i + 1));
      proto += ", rc_calc_real a" + std::to_string(i + 1);
    }
    proto += ")";
    std::string out;
    std::string value = gen(body, sc, out);
    add_function(key, name, proto);
    functions.back().body = out + "  return " + value + ";\n";
    drain();
    return name;
  }
};

CodeGenerator::CodeGenerator(Program& program) : CodeGenerator(program, Options{}) {}
CodeGenerator::CodeGenerator(Program& program, Options options)
    : impl_(std::make_unique<Impl>(program, options)) {}
CodeGenerator::~CodeGenerator() = default;

std::string CodeGenerator::request_variable(std::string_view name, const std::string& context) {
  Node n;
  n.op = Op::Var;
  n.name = std::string(name);
  return impl_->wrapper("var:" + n.name + "@" + context, "var_" + mangle(name), n, context, 0);
}

std::string CodeGenerator::request_function(std::string_view name, int nargs,
                                            const std::string& context) {
  Node n;
  n.op = Op::Call;
  n.name = std::string(name);
  for (int i = 0; i < nargs; ++i) {
    Node p;
    p.op = Op::Param;
    p.index = i;
    p.name = "a" + std::to_string(i + 1);
    n.kids.push_back(p);
  }
  return impl_->wrapper("fn:" + n.name + "/" + std::to_string(nargs) + "@" + context,
                        "fn_" + mangle(name), n, context, nargs);
}

std::string CodeGenerator::request_expression(const Expression& expr) {
  std::string key = "expr:" + std::to_string(impl_->functions.size());
  return impl_->wrapper(key, "expr", expr.root, expr.context, 0);
}

std::string CodeGenerator::source() {
  impl_->drain();
  std::string s = "/* Generated from .cal definitions by radcl (src/calc/codegen.cpp). */\n"
                  "#include \"calc/runtime.cl\"\n\n";
  // Larger bodies stay calls (RC_NOINLINE, kernels/calc/runtime.cl): a compiler that inlines
  // everything copies them into every caller (a sky's acos into each of its uses).
  auto proto = [](const Impl::Function& f) {
    const bool big = f.body.size() > kInlineBody && !f.recursive;
    return (big ? "RC_NOINLINE " : "") + f.proto;
  };
  for (const auto& f : impl_->functions)
    s += proto(f) + ";\n";
  s += "\n";
  for (const auto& f : impl_->functions)
    s += proto(f) + " {\n" + f.body + "}\n\n";
  return s;
}

} // namespace radcl::calc
