// rcontrib's command line (Radiance 5.4's rcmain.c): rendering options, the modifiers to track
// with the output, parameters and bins in force for each, and the .cal sources.
#pragma once

#include "radcl/options/args.h"
#include "radcl/options/render_options.h"
#include "radcl/util/error.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace radcl::options {

// One tracked modifier with the -o/-p/-b/-bn in force when its -m (or -M file word) came.
struct RcontribModifier {
  std::string name;
  std::optional<std::string> outspec; // -o in force; nullopt = standard output
  std::string params;                 // -p in force ("" = none)
  std::string bin_expr;               // -b in force, "0" when none was given
  int nbins = 1; // bins: 1 for a constant bin expression, else the -bn in force
};

// -f files and -e statements in command-line order (they are all loaded before tracing).
struct CalSource {
  bool is_file;
  std::string text; // file name as given, or statements
};

// What the parser needs of the .cal state while parsing, because Radiance evaluates -bn's
// expression (e.g. `-bn Nrbins` after `-p MF=2 -f reinhartb.cal`) at that point of the command
// line. An empty hook is skipped; without `eval`, -bn takes only a plain number.
struct CalHooks {
  std::function<void(const std::string& file)> load_file;       // -f
  std::function<void(const std::string& statements)> load_expr; // -e
  std::function<void(const std::string& params)> set_params;    // -p
  std::function<double(const std::string& expr)> eval;          // -bn
};

struct RcontribOptions {
  RenderOptions render = RenderOptions::rcontrib_defaults();
  int nproc = 1;                          // -n
  bool contributions = false;             // -V
  int accumulate = 1;                     // -c
  int xres = 0, yres = 0;                 // -x -y
  bool warnings = true;                   // -w
  bool limit_distance = false;            // -ld
  bool immediate_irradiance = false;      // -I
  bool force_open = false;                // -fo
  bool recover = false;                   // -r
  bool header = true;                     // -h
  char in_format = 'a', out_format = 'a'; // -f[afd][afdc]
  int report_interval = 0;                // -t
  std::vector<CalSource> cal;
  std::vector<RcontribModifier> modifiers;
};

struct RcontribCommand {
  enum class Action { Run, PrintDefaults, PrintVersion } action = Action::Run;
  RcontribOptions opt;
  std::vector<std::string> args; // the command line after expansion (for the output header)
  std::size_t operand = 0;       // index in args of the octree (== args.size() when missing)
};

// A malformed command line ("command line error at '<word>'"). Radiance's rcontrib prints its
// usage line on standard error before the message, so the front end catches this to do so too.
class RcontribUsageError : public FatalError {
public:
  using FatalError::FatalError;
};

// The usage line (with its newline) that goes before a RcontribUsageError's message.
std::string rcontrib_usage(const std::string& program);

// Parses argv (argv[0] included), calling the hooks as Radiance does its .cal work, in
// command-line order. Stops at -version or -defaults/-help. Throws RcontribUsageError for a
// malformed option or more than one operand, and FatalError with Radiance's other messages
// ("bad number of processes", "duplicate modifier 'x'", "missing required modifier argument",
// ...; SystemError for -M files and @file expansion). A missing octree is left to the caller
// ("missing octree argument"), as Radiance checks it after the options.
RcontribCommand parse_rcontrib_command_line(const std::vector<std::string>& args,
                                            const CalHooks& cal,
                                            const FileFinder& find_file = default_find_file);

// rcontrib -defaults output for the options given before it.
std::string format_rcontrib_defaults(const RcontribOptions& opt);

} // namespace radcl::options
