// rpict's command line (Radiance's rpmain.c): rendering, view and picture options.
#pragma once

#include "radcl/options/render_options.h"
#include "radcl/options/rtrace_options.h"
#include "radcl/options/view.h"

#include <iosfwd>
#include <string>

namespace radcl::options {

struct RpictOptions {
  RenderOptions render = RenderOptions::rpict_defaults();
  View view;                     // -vt... -vf; checked and set up by the parser
  int xres = 512;                // -x
  int yres = 512;                // -y
  double pixel_aspect = 1.0;     // -pa
  double pixel_jitter = 0.67;    // -pj
  double pixel_motion = 0.0;     // -pm
  double pixel_aperture = 0.0;   // -pd
  int pixel_sample = 4;          // -ps
  double pixel_threshold = 0.05; // -pt
  int report_interval = 0;       // -t
  int sequence_start = 0;        // -S (0 = off)
  std::string output_file;       // -o (also set by -ro)
  std::string z_file;            // -z
  std::string recover_file;      // -r / -ro
  bool warnings = true;          // -w
  std::string error_file;        // -e
  RtraceOptions::Persist persist = RtraceOptions::Persist::None; // -P / -PP
  std::string persist_file;
};

struct RpictCommand : ParsedCommand {
  RpictOptions opt;
};

// Parses argv (argv[0] included; its basename also names the program's own view lines in -vf
// files). -vf - reads `stdin_in`. After the options, the view is checked (FatalError with
// setview's message). Throws "cannot open view file \"f\"", "bad view file \"f\"", ...
RpictCommand parse_rpict_command_line(std::vector<std::string> argv,
                                      const FileFinder& find_file = default_find_file,
                                      std::istream* stdin_in = nullptr);

// The octree operand: none (read stdin: "") or one. Throws "command line error at '<word>'"
// for more, "missing octree argument" when -S is given without one.
std::string rpict_octree(const RpictCommand& cmd);

// rpict -defaults output for the options given before it.
std::string format_rpict_defaults(const RpictOptions& opt);

} // namespace radcl::options
