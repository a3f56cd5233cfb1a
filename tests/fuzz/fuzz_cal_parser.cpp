// The .cal parser (calc module): the input as a file of statements, and as one expression (a
// scene string argument). Built only when the calc module is in the tree.
#include "fuzz_target.h"
#include "radcl/calc/program.h"

RADCL_FUZZ_TARGET(cal_parser) {
  radcl::calc::Program program;
  try {
    program.load_string(data, "fuzz.cal");
  } catch (const radcl::FatalError&) {
  }
  (void)program.parse_expression(data, "", "fuzz");
}
