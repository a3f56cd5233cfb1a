// rtrace's command line (Radiance's rtmain.c): options, -defaults listing, the octree operand.
#pragma once

#include "radcl/options/args.h"
#include "radcl/options/render_options.h"

#include <string>
#include <vector>

namespace radcl::options {

struct RtraceOptions {
  RenderOptions render = RenderOptions::rtrace_defaults();
  int nproc = 1;                     // -n
  int xres = 0;                      // -x (flush interval, or x resolution with -y)
  int yres = 0;                      // -y
  bool limit_distance = false;       // -ld
  bool immediate_irradiance = false; // -I
  bool header = true;                // -h
  char in_format = 'a';              // -f<i>
  char out_format = 'a';             // -f<i><o>
  std::string output_spec = "v";     // -o<spec>, the last one wins
  bool warnings = true;              // -w
  std::string error_file;            // -e
  ModifierList trace_list;           // -te -ti -tE -tI
  enum class Persist { None, Single, Parallel };
  Persist persist = Persist::None; // -P / -PP
  std::string persist_file;
};

// What the command line asks for. Stops at -defaults/-help or -version as Radiance does.
struct ParsedCommand {
  enum class Action { Run, PrintDefaults, PrintVersion };
  Action action = Action::Run;
  std::vector<std::string> args; // argv after the expansions done while parsing
  std::size_t operand = 0;       // index in args of the first word that is not an option
};

struct RtraceCommand : ParsedCommand {
  RtraceOptions opt;
};

// Parses argv (argv[0] included). Throws FatalError with Radiance's messages ("command line
// error at '-ab'", "bad number of processes", "cannot expand '@f'", "multiprocessing
// incompatible with persist file", ...).
RtraceCommand parse_rtrace_command_line(std::vector<std::string> argv,
                                        const FileFinder& find_file = default_find_file);

// The octree operand: exactly one word must follow the options. Throws "missing octree
// argument" or "command line error at '<word>'" (Radiance checks this after opening -e).
std::string rtrace_octree(const RtraceCommand& cmd);

// rtrace -defaults output for the options given before it.
std::string format_rtrace_defaults(const RtraceOptions& opt);

} // namespace radcl::options
