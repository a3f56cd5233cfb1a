// radcl calc: evaluates .cal expressions on the host, like Radiance's calc/ev: definitions from
// files (-f) and statements (-e), then each expression argument printed on its own line.
// -r loads rayinit.cal first; -a sets the real arguments (arg(n), A1..); -c generates the
// OpenCL C for the expressions instead of evaluating them.
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "radcl/calc/codegen.h"
#include "radcl/calc/evaluator.h"
#include "radcl/calc/program.h"
#include "radcl/util/error.h"
#include "radcl_commands.h"

namespace radcl::cli {

int cmd_calc(int argc, char** argv) {
  calc::Program prog;
  std::vector<std::string> exprs;
  std::vector<double> args;
  bool have_args = false, codegen = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw FatalError("calc: " + a + " needs a value");
      return argv[++i];
    };
    if (a == "-f") {
      prog.load_file(value());
    } else if (a == "-e") {
      prog.load_string(value(), "");
    } else if (a == "-r") {
      prog.load_rayinit();
    } else if (a == "-a") {
      std::istringstream in(value());
      double v;
      while (in >> v)
        args.push_back(v);
      have_args = true;
    } else if (a == "-c") {
      codegen = true;
    } else if (a.size() > 1 && a[0] == '-' && !(a[1] == '.' || std::isdigit(a[1]) || a[1] == '(')) {
      throw FatalError("calc: unknown option \"" + a + "\"");
    } else {
      exprs.push_back(a);
    }
  }
  if (exprs.empty())
    throw FatalError("calc: usage: radcl calc [-r] [-f file.cal]... [-e 'statements']... "
                     "[-a 'A1 A2 ..'] [-c] expression ...");
  if (codegen) {
    calc::CodeGenerator gen(prog);
    for (const std::string& e : exprs)
      std::printf("/* %s: */ %s\n", e.c_str(),
                  gen.request_expression(prog.parse_expression(e)).c_str());
    std::printf("%s", gen.source().c_str());
    return 0;
  }
  calc::Evaluator ev(prog);
  if (have_args) ev.set_args(args);
  for (const std::string& e : exprs)
    std::printf("%.9g\n", ev.eval(prog.parse_expression(e)));
  return 0;
}

} // namespace radcl::cli
