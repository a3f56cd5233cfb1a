#include "radcl/util/error.h"

#include <cstdio>
#include <exception>

namespace radcl {
namespace {
std::string g_program = "radcl";
void print_warning(const std::string& msg) {
  std::fprintf(stderr, "%s: warning - %s\n", g_program.c_str(), msg.c_str());
}
WarningSink g_sink = print_warning;
} // namespace

void set_warning_sink(WarningSink sink) {
  g_sink = sink ? sink : print_warning;
}
void warning(const std::string& msg) {
  g_sink(msg);
}
void set_program_name(const std::string& name) {
  g_program = name;
}
const std::string& program_name() {
  return g_program;
}

int run_main(const char* progname, int (*body)(int, char**), int argc, char** argv) {
  set_program_name(progname);
  try {
    return body(argc, argv);
  } catch (const FatalError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: fatal - %s\n", progname, e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: internal error - %s\n", progname, e.what());
    return 2;
  }
}

} // namespace radcl
