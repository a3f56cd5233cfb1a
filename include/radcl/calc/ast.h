// Expression trees of the .cal language (../shared/docs/radiance/calc-language.md §3).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radcl::calc {

enum class Op : std::uint8_t {
  Num,   // literal (or a folded constant)
  Var,   // variable reference by name, resolved in the definition's context at use
  Param, // parameter of the enclosing function (index)
  Chan,  // $N input channel (index = N)
  Call,  // call of a named function (user, library or ray-context)
  PCall, // call through a parameter that names a function (index)
  Add,
  Sub,
  Mul,
  Div,
  Pow,
  Neg
};

struct Node {
  Op op = Op::Num;
  double num = 0;         // Num
  int index = 0;          // Param/PCall: 0-based parameter; Chan: channel number
  std::string name;       // Var/Call: the name as written; Param/PCall: the parameter's name
  std::vector<Node> kids; // Call/PCall: arguments; binary ops: 2; Neg: 1

  static Node number(double v) {
    Node n;
    n.num = v;
    return n;
  }
  bool is_num() const { return op == Op::Num; }
  bool operator==(const Node& o) const = default;
};

// A file-level statement `name = e`, `name : e`, `f(a,b) = e` or `f(a,b) : e`.
struct Definition {
  std::string name;    // qualified name it is stored under (e.g. "x", "x`ctx", "un2`P.")
  std::string context; // context the body's names are resolved in ("" = global)
  bool constant = false;
  bool function = false;
  std::vector<std::string> params;
  Node body;
  std::string file; // where it was defined, for messages
  int line = 0;
  int id = 0; // unique per Program, for caches
};

// An expression compiled in a context (e.g. a scene string argument in its file's context).
struct Expression {
  Node root;
  std::string context;
};

} // namespace radcl::calc
