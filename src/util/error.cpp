#include "radcl/util/error.h"

#include <cctype>
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

std::string command_name(const std::string& argv0) {
  std::string name = argv0.substr(argv0.find_last_of('/') + 1);
  if (std::size_t dot = name.find('.'); dot != std::string::npos) name.resize(dot);
  for (char& c : name)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

int run_main(const char* progname, int (*body)(int, char**), int argc, char** argv) {
  std::string name = argc > 0 && argv[0] ? command_name(argv[0]) : "";
  set_program_name(name.empty() ? progname : name);
  const char* me = program_name().c_str();
  try {
    return body(argc, argv);
  } catch (const SystemError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: system - %s\n", me, e.what());
    return 2;
  } catch (const FatalError& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: fatal - %s\n", me, e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: internal error - %s\n", me, e.what());
    return 2;
  }
}

} // namespace radcl
